// The run library without the command: the C++ example of docs/ARCHITECTURE.md (built from
// the document as `ppsynth_example`) runs, and the in-memory synthesize(), a run directory and
// the example all give the same points for the same spec.
#include <catch2/catch.hpp>

#include <ATen/Parallel.h>

#include <fstream>

#include "core/formats/point_io.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_store.hpp"
#include "optim/run/run_synthesis.hpp"
#include "optim/run/synthesize.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;

namespace {

const char* kLines = "shared:data/exemplars/gabor-paper/lines.txt";

void require_same_points(const PointSet& a, const PointSet& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a[i].x == b[i].x);
    REQUIRE(a[i].y == b[i].y);
    REQUIRE(a.cls(i) == b.cls(i));
  }
}

}  // namespace

TEST_CASE("the example of docs/ARCHITECTURE.md builds, runs, and equals synthesize() in process", "[library][example]") {
  const auto d = test::scratch_dir("library_example");
  // One thread, as this test process runs: the same thread count gives the same bits.
  const auto r = test::run_program(PPSYNTH_EXAMPLE_BINARY, "", "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("iterations, loss") != std::string::npos);
  CHECK(r.output.find("80 points in") != std::string::npos);
  const PointSet from_example = read_points((d / "lines_output.txt").string());

  REQUIRE(at::get_num_threads() == 1);
  const PointSet exemplar = read_points(kLines);
  const json spec = resolve_run_config({{"seed", 7}}, {"method.max_iterations=20"});
  SynthesisOptions options;
  options.quick = true;
  const SynthesisResult in_memory = synthesize(exemplar, spec, options);
  require_same_points(from_example, in_memory.output);
  // --quick: two sigmas of one class, then the border relax (the default: at most --quick's
  // 4 iterations, 0 when the class does not park).
  REQUIRE(in_memory.stages.size() == 3);
  for (int i : {0, 1}) CHECK((in_memory.stages[i].iterations >= 1 && in_memory.stages[i].iterations <= 20));
  CHECK(in_memory.stages[2].stage == "border relax");
  CHECK((in_memory.stages[2].iterations >= 0 && in_memory.stages[2].iterations <= 4));
  CHECK(in_memory.metrics["all"]["pcf_mse"].is_number());
  CHECK(in_memory.initialization.size() == 80);
}

TEST_CASE("a run directory holds what synthesize() returns for the same spec", "[library]") {
  const auto d = test::scratch_dir("library_vs_run_dir");
  const json spec = resolve_run_config({{"exemplar", kLines}, {"seed", 11}}, {});
  SynthesisOptions options;
  options.quick = true;
  const SynthesisResult in_memory = synthesize(load_exemplar(spec), spec, options);
  RunRequest req;
  req.dir = (d / "run").string();
  req.quick = true;
  const RunOutcome run = run_synthesis(spec, req);
  require_same_points(run.output, in_memory.output);
  require_same_points(read_points(req.dir + "/output.txt"), in_memory.output);
  require_same_points(read_points(req.dir + "/init.txt"), in_memory.initialization);
  CHECK(run.metrics == in_memory.metrics);
  REQUIRE(run.stages.size() == in_memory.stages.size());
  for (size_t s = 0; s < run.stages.size(); ++s) {
    CHECK(run.stages[s].stage == in_memory.stages[s].stage);
    CHECK(run.stages[s].iterations == in_memory.stages[s].iterations);
    CHECK(run.stages[s].final_loss == in_memory.stages[s].final_loss);
    CHECK(run.stages[s].details == in_memory.stages[s].details);
  }
  // run.json shows them as one flat object each, and load_run reads them back typed.
  const json record = json::parse(std::ifstream(req.dir + "/run.json"));
  REQUIRE(record["method_stats"]["stages"].size() == in_memory.stages.size());
  CHECK(record["method_stats"]["stages"][0]["iterations"] == in_memory.stages[0].iterations);
  CHECK(record["method_stats"]["stages"][0]["sigma"] == in_memory.stages[0].details["sigma"]);
  const RunOutcome loaded = load_run(req.dir);
  REQUIRE(loaded.stages.size() == in_memory.stages.size());
  CHECK(loaded.stages.back().final_loss == in_memory.stages.back().final_loss);
  CHECK_FALSE(loaded.stats.contains("stages"));
}

TEST_CASE("synthesize() needs no exemplar file and refuses what its method cannot do", "[library]") {
  PointSet ex;
  for (int i = 0; i < 12; ++i) ex.add(Vec2{(i % 4 + 0.5) / 4.0, (i / 4 + 0.5) / 3.0}, 0);
  const json spec = resolve_run_config(json::object(), {});
  SynthesisOptions options;
  options.quick = true;
  CHECK(synthesize(ex, spec, options).output.size() == 48);
  const std::string bytes = "not a checkpoint";
  options.resume_state = &bytes;
  CHECK_THROWS_AS(synthesize(ex, spec, options), InputError);  // the gabor method: a bad checkpoint
  const json copy = resolve_run_config({{"method", {{"type", "tiled_copy"}}}}, {});
  CHECK_THROWS_WITH(synthesize(ex, copy, options), Catch::Contains("cannot resume"));
}
