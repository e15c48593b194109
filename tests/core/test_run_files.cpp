// The JSON files of run and sweep directories read back as what they claim to be, or refused
// naming the file and the key: config.json, run.json, metrics.json (core/run_json.hpp,
// core/metrics/metric_values.hpp), the marker (core/run_directory.hpp) and the sweep's
// manifest (core/sweep_manifest.hpp). Hand edits, truncations and crafted values never reach
// the code that uses them.
#include <catch2/catch.hpp>

#include <fstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "core/sweep_manifest.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

nlohmann::json config() {
  return {{"name", "lines"},  {"description", ""},       {"exemplar", "lines.txt"}, {"format", "auto"},
          {"scaling", "per-axis"}, {"seed", 95}, {"method", {{"type", "gabor"}}}, {"output", {{"size", nullptr}}}};
}

SweepManifest manifest() {
  SweepManifest m;
  m.name = "seeds";
  m.spec_source = "spec.json";
  m.spec = nlohmann::json::object();
  SweepRow r;
  r.id = "0123456789ab";
  r.group = "ba9876543210";
  r.label = "lines seed 95";
  r.group_label = "lines";
  r.source = "lines.json";
  r.seed = 95;
  r.dir = "runs/" + r.id;
  r.config = config();
  m.rows.push_back(r);
  return m;
}

}  // namespace

TEST_CASE("config.json: a resolved run config or an error naming the file and key", "[run_files]") {
  CHECK_NOTHROW(check_run_config(config(), "config.json"));
  struct Case {
    const char* key;
    nlohmann::json value;
  };
  for (const Case& c : {Case{"seed", -5}, Case{"seed", "95"}, Case{"seed", 9223372036854775808ull}, Case{"seed", 1.5},
                        Case{"method", "gabor"}, Case{"method", {{"type", 3}}}, Case{"name", 7}, Case{"exemplar", nullptr},
                        Case{"output", 3}}) {
    nlohmann::json j = config();
    j[c.key] = c.value;
    INFO(c.key << " = " << c.value.dump());
    CHECK_THROWS_WITH(check_run_config(j, "run/config.json"),
                      Catch::Contains("run/config.json") && Catch::Contains(std::string("'") + c.key + "'"));
  }
  CHECK_THROWS_WITH(check_run_config(nlohmann::json::array(), "run/config.json"), Catch::Contains("run/config.json"));
  // Malformed JSON on disk: an InputError naming the file and the line, never a JSON exception.
  const auto d = test::scratch_dir("run_files_config");
  const std::string path = (d / "config.json").string();
  std::ofstream(path) << "{\n  \"seed\": 95,\n  \"method\": {\n";
  CHECK_THROWS_WITH(read_run_config(path), Catch::Contains(path + ":4") && !Catch::Contains("json.exception"));
  CHECK_THROWS_WITH(read_run_config((d / "none.json").string()), Catch::Contains("none.json") && Catch::Contains("missing"));
}

TEST_CASE("run.json: typed, whatever was edited into it", "[run_files]") {
  const RunRecord r = parse_run_record({{"seed", 96}, {"quick", true}, {"threads", 2}, {"processor", "x (AVX2)"},
                                       {"total_seconds", 1.5}, {"method_stats", {{"stages", 4}}},
                                       {"preset", {{"name", "fast"}, {"variant", "without bf16 units"}, {"reason", "no bf16 units"}}}},
                                      "run.json");
  CHECK(r.seed == 96);
  CHECK(r.preset_variant == "without bf16 units");
  CHECK(parse_run_record({{"preset", nullptr}}, "run.json").preset_variant.empty());  // a run without a preset
  CHECK(r.quick);
  CHECK(r.threads == 2);
  CHECK(r.total_seconds == 1.5);
  CHECK(r.method_stats["stages"] == 4);
  CHECK(parse_run_record(nlohmann::json::object(), "run.json").seed == 0);  // runs made before a key was recorded
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"seed", "95"}, {"quick", 1}, {"threads", 0}, {"threads", "4"}, {"total_seconds", -1}, {"total_seconds", "x"},
           {"processor", 5}, {"method_stats", nlohmann::json::array()}, {"preset", "fast"}, {"preset", {{"variant", 1}}}}) {
    INFO(key << " = " << value.dump());
    CHECK_THROWS_WITH(parse_run_record({{key, value}}, "r/run.json"), Catch::Contains("r/run.json") && Catch::Contains("'" + key + "'"));
  }
}

TEST_CASE("metrics.json: its values, or an error; never a read past a list's end", "[run_files]") {
  const nlohmann::json m = {{"all", {{"pcf_mse", 0.5}, {"wasserstein", nullptr}}},
                            {"output", {{"border_fraction", 0.1}, {"border_profile", {{"band", {0.005, 0.01}}, {"over_uniform", {1.5, 1.2}}}}}},
                            {"classes", {{{"class", 0}, {"chamfer", 0.25}}}},
                            {"cross", {{{"ci", 0}, {"cj", 1}, {"pcf_mse", 0.125}}}}};
  const auto v = metric_values(m, "metrics.json");
  const std::vector<std::pair<std::string, double>> want = {{"all/pcf_mse", 0.5},
                                                            {"all/border_fraction", 0.1},
                                                            {"all/border_density_0.5%", 1.5},
                                                            {"all/border_density_1%", 1.2},
                                                            {"class 0/chamfer", 0.25},
                                                            {"classes 0-1/pcf_mse", 0.125}};
  CHECK(v == want);
  // The defect: a band list longer than its values was read past the values' end (heap garbage
  // tabulated as a metric).
  nlohmann::json past = m;
  past["output"]["border_profile"]["band"] = nlohmann::json::array({0.005, 0.01, 0.02, 0.05});
  CHECK_THROWS_WITH(metric_values(past, "run/metrics.json"),
                    Catch::Contains("run/metrics.json") && Catch::Contains("output.border_profile"));
  for (const auto& [pointer, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"/all", 3}, {"/all/pcf_mse", "small"}, {"/classes", {{"class", 0}}}, {"/classes/0/class", -1},
           {"/classes/0/class", "0"}, {"/cross/0/cj", 1e300}, {"/output/border_profile/band/0", "x"}}) {
    nlohmann::json bad = m;
    bad[nlohmann::json::json_pointer(pointer)] = value;
    INFO(pointer << " = " << value.dump());
    CHECK_THROWS_AS(metric_values(bad, "metrics.json"), InputError);
  }
  CHECK_THROWS_AS(metric_values(nlohmann::json::array(), "metrics.json"), InputError);
}

TEST_CASE("a run directory's marker: checked, and a damaged one protects the directory", "[run_files][run_directory]") {
  const nlohmann::json good = parse_run_dir_marker(
      R"({"kind": "run", "state": "running", "pid": 12, "progress": {"index": 3, "count": 8, "stage": "class 1/2"}})", "m");
  CHECK(run_progress_text(good, 0) == "stage 3/8 (class 1/2)");
  CHECK(parse_run_dir_marker(R"({"kind": "run", "state": "running", "exemplar_format": "gabor"})", "m")["exemplar_format"] == "gabor");
  for (const std::string bad : {R"([])", R"({"state": "running"})", R"({"kind": "../x", "state": "running"})",
                                R"({"kind": "run", "state": "done"})", R"({"kind": "run", "state": "running", "pid": "12"})",
                                R"({"kind": "run", "state": "running", "progress": {"index": "3"}})",
                                R"({"kind": "run", "state": "running", "progress": []})", R"({"kind": "run", "state": )",
                                R"({"kind": "run", "state": "running", "exemplar_format": "auto"})",
                                R"({"kind": "run", "state": "running", "exemplar_format": "xyz"})",
                                R"({"kind": "run", "state": "running", "exemplar_format": 1})"}) {
    INFO(bad);
    CHECK_THROWS_WITH(parse_run_dir_marker(bad, "d/.ppsynth-run"), Catch::Contains("d/.ppsynth-run"));
  }
  const auto d = test::scratch_dir("run_files_marker");
  const std::string run = (d / "run").string();
  fs::create_directories(run);
  std::ofstream(run + "/output.txt") << "the user's\n";
  std::ofstream(run + "/.ppsynth-run") << R"({"kind": "run", "state": "complete", "progress": {"index": "x"}})";
  CHECK(run_dir_state(run) == RunDirState::Foreign);
  RunDirOptions force;
  force.force = true;
  CHECK_THROWS_WITH(RunDirectory::open(run, force), Catch::Contains("marker is damaged") && Catch::Contains("'progress.index'"));
  CHECK(fs::exists(run + "/output.txt"));
}

TEST_CASE("--force replaces only a directory of its own kind", "[run_files][run_directory]") {
  const auto d = test::scratch_dir("run_files_kind");
  const std::string run = (d / "run").string();
  {
    RunDirectory r = RunDirectory::open(run, RunDirOptions{});
    write_text_atomic(run + "/output.txt", "points\n");
    r.mark_complete();
  }
  RunDirOptions gather;
  gather.kind = "gather";
  gather.force = true;
  CHECK_THROWS_WITH(RunDirectory::open(run, gather), Catch::Contains("a finished run of ppsynth, not a gather"));
  CHECK(fs::exists(run + "/output.txt"));
  RunDirOptions again;
  again.force = true;
  CHECK_NOTHROW(RunDirectory::open(run, again));
}

TEST_CASE("a sweep's manifest: every value checked before an executor uses it", "[run_files][sweep]") {
  const SweepManifest m = manifest();
  const nlohmann::json j = sweep_manifest_json(m);
  const SweepManifest back = parse_sweep_manifest(j, "manifest.json");
  CHECK(sweep_manifest_json(back) == j);
  CHECK(sweep_manifest_hash(back) == sweep_manifest_hash(m));
  struct Case {
    std::string pointer;
    nlohmann::json value;
    std::string key;
  };
  for (const Case& c : {Case{"/name", "x\n#SBATCH --wrap=rm", "'name'"}, Case{"/name", "a b", "'name'"},
                        Case{"/resources/cpus", -5, "resources.cpus"}, Case{"/resources/memory_mb", 0, "resources.memory_mb"},
                        Case{"/resources/time_minutes", 1e9, "resources.time_minutes"},
                        Case{"/resources/cpus", "4", "resources.cpus"}, Case{"/rows/0/id", "../../etc", "rows[0].id"},
                        Case{"/rows/0/dir", "runs/../../x", "rows[0].dir"}, Case{"/rows/0/seed", -1, "rows[0].seed"},
                        Case{"/rows/0/config/seed", 96, "rows[0].config.seed"}, Case{"/rows/0/config/method", 1, "method"},
                        Case{"/rows/0/quick", "no", "rows[0].quick"}, Case{"/rows/0/overrides", {1}, "rows[0].overrides"},
                        Case{"/version", 2, "version"}, Case{"/rows", nlohmann::json::object(), "rows"}}) {
    nlohmann::json bad = j;
    bad[nlohmann::json::json_pointer(c.pointer)] = c.value;
    INFO(c.pointer << " = " << c.value.dump());
    CHECK_THROWS_WITH(parse_sweep_manifest(bad, "s/manifest.json"), Catch::Contains("s/manifest.json") && Catch::Contains(c.key));
  }
  nlohmann::json twice = j;
  twice["rows"].push_back(twice["rows"][0]);
  CHECK_THROWS_WITH(parse_sweep_manifest(twice, "manifest.json"), Catch::Contains("twice"));
  CHECK_THROWS_WITH(parse_sweep_manifest(nlohmann::json::array(), "manifest.json"), Catch::Contains("not a sweep manifest"));
}
