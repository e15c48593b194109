// The readers of planned and finished runs take a run's seed, method type and runtime typed
// (optim/run/run_options_of.hpp): a bad value is an InputError naming the file and the key
// before anything runs, where it was taken as another value.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/run_json.hpp"
#include "experiments/execute/sweep_executors.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "experiments/reproduce/reproduce_numbers.hpp"
#include "optim/run/run_config.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ppsynth;
using nlohmann::json;
using Catch::Matchers::Contains;

TEST_CASE("sweep run: a row's malformed runtime.device is refused naming the manifest and the key", "[sweep][run_options_of]") {
  const auto d = test::scratch_dir("typed_run_readers_sweep");
  const std::string dir = (d / "sw").string();
  const json spec = {{"name", "tiny"}, {"runs", {std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json"}}, {"seeds", {3}}, {"quick", true}};
  plan_sweep(expand_sweep_spec(spec, "spec", ""), dir);
  const std::string manifest = dir + "/manifest.json";
  json m = read_run_json(manifest);
  for (const json device : {json(5), json("gpu")}) {
    m["rows"][0]["config"]["runtime"]["device"] = device;  // was taken as the CPU
    std::ofstream(manifest) << m.dump(1);
    LocalExecution how;
    how.binary = (d / "no-such-ppsynth").string();  // nothing may start
    CHECK_THROWS_AS(execute_local(dir, how, nullptr), InputError);
    CHECK_THROWS_WITH(execute_local(dir, how, nullptr), Contains(manifest + " rows[0].config") && Contains("runtime.device"));
    CHECK(fs::is_empty(d / "sw" / "runs"));
  }
}

TEST_CASE("reproduce: a run's malformed seed or method type is refused naming its config.json", "[reproduce][run_options_of]") {
  const json resolved = resolve_run_config(json{{"exemplar", "x.txt"}, {"method", {{"type", "roveri2015"}}}}, {});
  // The report's numbers (one seed: its columns'), the seed a string (was nlohmann's type_error).
  ReproduceResult r;
  r.dir = "rep";
  ColumnResult ours;
  ours.column = "ours";
  ours.run_dir = "panels/a/ours";
  ours.config = resolved;
  ours.config["seed"] = "95";
  PanelResult panel;
  panel.name = "a";
  panel.columns = {ours};
  r.panels = {panel};
  CHECK_THROWS_AS(collect_item_numbers(ReproduceConfig{}, r), InputError);
  CHECK_THROWS_WITH(collect_item_numbers(ReproduceConfig{}, r), Contains("rep/panels/a/ours/config.json") && Contains("seed"));
  // A run's iterations read its method type (was nlohmann's type_error).
  RunOutcome run;
  run.dir = "runs/x";
  run.config = resolved;
  run.config["method"]["type"] = 3;
  CHECK_THROWS_AS(total_iterations(run), InputError);
  CHECK_THROWS_WITH(total_iterations(run), Contains("runs/x/config.json") && Contains("method"));
}
