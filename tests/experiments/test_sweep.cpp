// Sweeps, in process: seeds and grids expand into rows with stable ids; planning again keeps
// the rows that did not change; a directory that is not a sweep's is never planned into;
// gather pools seeds and compares with a reference. (Through the binary, with local tasks,
// interruption and the SLURM script: tests/apps/test_sweep_cli.cpp.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/summary_stats.hpp"
#include "core/processor.hpp"
#include "core/run_directory.hpp"
#include "optim/run/run_store.hpp"
#include "optim/run/run_synthesis.hpp"
#include "experiments/gather/gather.hpp"
#include "experiments/execute/sweep_executors.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "experiments/execute/sweep_runs.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ppsynth;
using nlohmann::json;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

json tiny_spec(json grid = json::object()) {
  return {{"name", "tiny"},
          {"runs", {kLines}},
          {"seeds", {3, "5-6"}},
          {"quick", true},
          {"set", {"method.quick.max_iterations=3", "method.quick.res=16"}},
          {"grid", grid}};
}

// The spec planned into `dir` and every row run there, in process.
SweepManifest planned_and_run(const json& spec, const std::string& dir) {
  plan_sweep(expand_sweep_spec(spec, "spec", ""), dir);
  const SweepManifest m = load_sweep(dir);
  for (const auto& row : m.rows) REQUIRE(run_sweep_task(dir, row.id, "", nullptr) == RowState::Done);
  return m;
}

std::vector<std::string> ids(const SweepManifest& m) {
  std::vector<std::string> v;
  for (const auto& r : m.rows) v.push_back(r.id);
  return v;
}

}  // namespace

TEST_CASE("a sweep spec expands into rows with stable ids", "[sweep]") {
  const auto m = expand_sweep_spec(tiny_spec({{"method.max_iterations", {5, 7}}}), "spec", "");
  REQUIRE(m.rows.size() == 6);  // 3 seeds x 2 grid points
  const auto row_ids = ids(m);
  std::set<std::string> unique(row_ids.begin(), row_ids.end());
  CHECK(unique.size() == 6);
  CHECK(m.rows[0].config["seed"] == 3);
  CHECK(m.rows[0].config["method"]["max_iterations"] == 5);
  CHECK(m.rows[3].config["method"]["max_iterations"] == 7);
  CHECK(m.rows[0].group == m.rows[2].group);  // seeds of one config pool together
  CHECK(m.rows[0].group != m.rows[3].group);
  CHECK(m.rows[0].dir == "runs/" + m.rows[0].id);
  CHECK(m.rows[0].quick);
  // The same spec gives the same ids; an edit of one axis value keeps the other rows' ids.
  CHECK(ids(expand_sweep_spec(tiny_spec({{"method.max_iterations", {5, 7}}}), "spec", "")) == ids(m));
  const auto edited = expand_sweep_spec(tiny_spec({{"method.max_iterations", {5, 8}}}), "spec", "");
  for (int i = 0; i < 3; ++i) CHECK(edited.rows[i].id == m.rows[i].id);
  for (int i = 3; i < 6; ++i) CHECK(edited.rows[i].id != m.rows[i].id);
  // Labels, descriptions and checkpoint intervals do not make another run.
  json relabelled = tiny_spec({{"method.max_iterations", {5, 7}}});
  relabelled["set"].push_back("checkpoint_seconds=5");
  relabelled["set"].push_back("description=another");
  CHECK(ids(expand_sweep_spec(relabelled, "spec", "")) == ids(m));
}

TEST_CASE("a sweep spec's mistakes name the key", "[sweep]") {
  json bad = tiny_spec();
  bad["color"] = 1;
  CHECK_THROWS_WITH(expand_sweep_spec(bad, "spec", ""), Catch::Contains("color"));
  bad = tiny_spec();
  bad["runs"] = {"no/such.json"};
  CHECK_THROWS_WITH(expand_sweep_spec(bad, "spec", ""), Catch::Contains("runs[0]") && Catch::Contains("no/such.json"));
  bad = tiny_spec();
  bad["name"] = "../x";
  CHECK_THROWS_WITH(expand_sweep_spec(bad, "spec", ""), Catch::Contains("name"));
  bad = tiny_spec({{"method.max_iterations", json::array()}});
  CHECK_THROWS_WITH(expand_sweep_spec(bad, "spec", ""), Catch::Contains("grid.method.max_iterations"));
  bad = tiny_spec();
  bad["set"] = {"method.no_such_key=1"};
  CHECK_THROWS_WITH(expand_sweep_spec(bad, "spec", ""), Catch::Contains("no_such_key"));
}

TEST_CASE("planning again keeps unchanged rows; only a sweep's directory is planned into", "[sweep]") {
  const auto d = test::scratch_dir("sweep_plan");
  const std::string dir = (d / "sw").string();
  const auto first = plan_sweep(expand_sweep_spec(tiny_spec({{"method.max_iterations", {5, 7}}}), "spec", ""), dir);
  CHECK(first.added == 6);
  fs::create_directories(d / "sw" / "runs" / "kept_marker");  // stands for a finished run's files
  const auto again = plan_sweep(expand_sweep_spec(tiny_spec({{"method.max_iterations", {5, 8}}}), "spec", ""), dir);
  CHECK(again.kept == 3);
  CHECK(again.added == 3);
  CHECK(again.dropped == 3);
  CHECK(fs::exists(d / "sw" / "runs" / "kept_marker"));
  CHECK(load_sweep(dir).rows.size() == 6);
  for (const auto& s : sweep_status(dir, load_sweep(dir))) CHECK(s.state == RowState::Pending);
  // Not a sweep: refused, untouched.
  fs::create_directories(d / "other");
  std::ofstream(d / "other" / "mine.txt") << "mine";
  CHECK_THROWS_WITH(plan_sweep(expand_sweep_spec(tiny_spec(), "spec", ""), (d / "other").string()),
                    Catch::Contains("not a sweep directory"));
  CHECK(fs::exists(d / "other" / "mine.txt"));
  CHECK_THROWS_WITH(load_sweep((d / "other").string()), Catch::Contains("not a sweep directory"));
  CHECK_THROWS(plan_sweep(expand_sweep_spec(tiny_spec(), "spec", ""), "."));
}

TEST_CASE("tasks run rows, skip finished ones, and gather pools seeds against a reference", "[sweep]") {
  const auto d = test::scratch_dir("sweep_tasks");
  const std::string dir = (d / "sw").string();
  const auto m = planned_and_run(tiny_spec(), dir);
  for (const auto& s : sweep_status(dir, m)) CHECK(s.state == RowState::Done);
  const auto before = fs::last_write_time(fs::path(dir) / m.rows[0].dir / "output.txt");
  CHECK(run_sweep_task(dir, m.rows[0].id, "", nullptr) == RowState::Done);  // done already: not run again
  CHECK(fs::last_write_time(fs::path(dir) / m.rows[0].dir / "output.txt") == before);
  CHECK_THROWS_WITH(run_sweep_task(dir, "0123456789ab", "", nullptr), Catch::Contains("no row 0123456789ab"));

  GatherOptions o;
  o.references = {{"", (fs::path(dir) / m.rows[0].dir / "output.txt").string()}};  // seed 3's own output
  const GatherResult g = gather_runs({dir}, o);
  REQUIRE(g.runs.size() == 3);
  const auto pcf = std::find_if(g.summaries.begin(), g.summaries.end(),
                                [](const MetricSummary& s) { return s.scope == "all" && s.metric == "pcf_mse"; });
  REQUIRE(pcf != g.summaries.end());
  REQUIRE(pcf->values.size() == 3);
  CHECK(pcf->seeds == std::vector<uint64_t>{3, 5, 6});
  CHECK(pcf->median == Approx(quantile(pcf->values, 0.5)));
  REQUIRE(pcf->reference);
  CHECK(*pcf->reference == Approx(pcf->values[0]));  // the reference is seed 3's output
  CHECK(*pcf->ratio == Approx(pcf->median / pcf->values[0]));
  CHECK(*pcf->within >= 1.0 / 3);
  // Written: tables, JSON and the page; a second gather into it needs force.
  write_gather(g, (d / "g").string(), false);
  for (const char* f : {"gather.csv", "gather.md", "gather.json", "per_seed.csv", "index.html"}) CHECK(fs::exists(d / "g" / f));
  CHECK_THROWS_WITH(write_gather(g, (d / "g").string(), false), Catch::Contains("--force"));
  CHECK_NOTHROW(write_gather(g, (d / "g").string(), true));

  // --protocol: every output (and the reference) evaluated again, here by 20 random crops,
  // giving what `ppsynth eval --protocol crops` gives, in place of metrics.json's quadrants.
  GatherOptions c = o;
  c.protocol = PatchProtocol::Crops;
  const GatherResult gc = gather_runs({dir}, c);
  const auto crops = std::find_if(gc.summaries.begin(), gc.summaries.end(),
                                  [](const MetricSummary& s) { return s.scope == "all" && s.metric == "pcf_mse"; });
  REQUIRE(crops != gc.summaries.end());
  REQUIRE(crops->seeds == std::vector<uint64_t>{3, 5, 6});
  EvalOptions e;
  e.protocol = PatchProtocol::Crops;
  e.include_curves = false;
  const RunOutcome seed3 = load_run((fs::path(dir) / m.rows[0].dir).string());
  CHECK(crops->values[0] == Approx(evaluate(seed3.exemplar, seed3.output, e)["all"]["pcf_mse"].get<double>()));
  CHECK(crops->values[0] != Approx(pcf->values[0]));  // the quadrants said something else
  REQUIRE(crops->reference);
  CHECK(*crops->reference == Approx(crops->values[0]));
  CHECK(format_gather(gc).find("protocol crops") != std::string::npos);

  // Each run records its processor; a group whose seeds ran on two kinds says so (a sweep's
  // SLURM tasks may land on different nodes).
  CHECK(g.notes.empty());
  for (const auto& run : g.runs) CHECK(run.processor == processor_kind());
  const fs::path run_json = fs::path(dir) / m.rows[1].dir / "run.json";
  json info = read_run_json(run_json.string());
  CHECK(made_differently(info).empty());
  info["processor"] = "Other CPU (avx2)";
  std::ofstream(run_json) << info.dump(2);
  CHECK(made_differently(info).find("Other CPU (avx2)") != std::string::npos);
  const GatherResult mixed = gather_runs({dir}, o);
  REQUIRE(mixed.notes.size() == 1);
  CHECK_THAT(mixed.notes[0], Catch::Contains("2 kinds of processor") && Catch::Contains("Other CPU (avx2): seed 5") &&
                                 Catch::Contains(processor_kind() + ": seeds 3, 6"));
  CHECK(format_gather(mixed).find("note: lines") != std::string::npos);
  write_gather(mixed, (d / "g").string(), true);
  std::ifstream md(d / "g" / "gather.md");
  CHECK(std::string(std::istreambuf_iterator<char>(md), {}).find("Note: lines") != std::string::npos);
}

TEST_CASE("an unfinished run's progress, from its marker", "[sweep]") {
  using nlohmann::json;
  const long long now = 1'000'000;
  CHECK(ppsynth::run_progress_text(json(), now).empty());
  CHECK(ppsynth::run_progress_text(json{{"state", "running"}}, now).empty());  // before its first stage
  const json stage = {{"stage", "class 3/4 (id 2), sigma 1/4"}, {"index", 9}, {"count", 20}};
  CHECK(ppsynth::run_progress_text(json{{"progress", stage}}, now) == "stage 9/20 (class 3/4 (id 2), sigma 1/4)");
  json checkpointed = stage;
  checkpointed["checkpointed"] = now - 45;
  CHECK(ppsynth::run_progress_text(json{{"progress", checkpointed}}, now) ==
        "stage 9/20 (class 3/4 (id 2), sigma 1/4), checkpoint 45 s ago");
  CHECK(ppsynth::run_progress_text(json{{"progress", {{"checkpointed", now - 600}}}}, now) == "checkpoint 10 min ago");
  CHECK(ppsynth::run_progress_text(json{{"progress", {{"checkpointed", now - 4 * 3600 - 59}}}}, now) == "checkpoint 4 h ago");
  const json window = {{"stage", "sigma 2/4"}, {"index", 2}, {"count", 4}, {"window", 7}, {"windows", 16}};
  CHECK(ppsynth::run_progress_text(json{{"progress", window}}, now) == "stage 2/4, window 7/16 (sigma 2/4)");
}

TEST_CASE("summaries: NumPy's quantiles, non-finite values left out", "[sweep][stats]") {
  CHECK(quantile({1, 2, 3, 4}, 0.25) == Approx(1.75));
  CHECK(quantile({4, 1, 3, 2}, 0.5) == Approx(2.5));
  const Summary s = summarize({3, std::nan(""), 1, 2, INFINITY});
  CHECK(s.count == 3);
  CHECK(s.not_finite == 2);
  CHECK(s.median == 2);
  CHECK(s.min == 1);
  CHECK(s.max == 3);
  CHECK(std::isnan(summarize({}).median));
}

TEST_CASE("the SLURM job script: one array task per run that is not done", "[sweep][slurm]") {
  const auto d = test::scratch_dir("sweep_slurm");
  const std::string dir = (d / "sw").string();
  plan_sweep(expand_sweep_spec(tiny_spec(), "spec", ""), dir);
  auto m = load_sweep(dir);
  SlurmExecution how;
  how.binary = "/opt/ppsynth/bin/ppsynth";
  how.partition = "long";
  how.sbatch_options = {"--qos=low"};
  how.max_parallel = 2;
  std::string s = slurm_script(dir, m, how);
  CHECK_THAT(s, Catch::Contains("#SBATCH --array=0-2%2\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --cpus-per-task=1\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --mem=4096M\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --time=240\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --partition=long\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --qos=low\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --requeue\n"));
  // The array index picks the row's id from the list (a re-plan never shifts a task's row).
  CHECK_THAT(s, Catch::Contains("rows=(" + m.rows[0].id + " " + m.rows[1].id + " " + m.rows[2].id + ")\n"));
  CHECK_THAT(s, Catch::Contains("exec /opt/ppsynth/bin/ppsynth sweep task " + fs::absolute(dir).lexically_normal().string() +
                                " --row \"${rows[$SLURM_ARRAY_TASK_ID]}\" --manifest " + sweep_manifest_hash(m) + "\n"));
  run_sweep_task(dir, m.rows[1].id, "", nullptr);
  CHECK_THAT(slurm_script(dir, m, how), Catch::Contains("#SBATCH --array=0,2%2\n"));
  run_sweep_task(dir, m.rows[0].id, "", nullptr);
  run_sweep_task(dir, m.rows[2].id, "", nullptr);
  CHECK(slurm_script(dir, m, how).empty());
  CHECK(compress_indices({0, 1, 2, 4, 6, 7}) == "0-2,4,6-7");
}

TEST_CASE("gather compares groups with a baseline: ratio of medians and a bootstrap interval", "[sweep]") {
  const auto d = test::scratch_dir("sweep_baseline");
  const std::string dir = (d / "sw").string();
  const auto m = planned_and_run(tiny_spec({{"method.quick.max_iterations", {1, 3}}}), dir);
  REQUIRE(m.rows.size() == 6);
  GatherOptions o;
  o.baselines = {"lines [method.quick.max_iterations=1]"};
  const GatherResult g = gather_runs({dir}, o);
  auto find = [&](const std::string& label, const std::string& metric) {
    const auto it = std::find_if(g.comparisons.begin(), g.comparisons.end(), [&](const BaselineComparison& c) {
      return c.group_label == label && c.scope == "all" && c.metric == metric;
    });
    REQUIRE(it != g.comparisons.end());
    return *it;
  };
  auto median_of = [&](const std::string& label, const std::string& metric) {
    const auto it = std::find_if(g.summaries.begin(), g.summaries.end(), [&](const MetricSummary& s) {
      return s.group_label == label && s.scope == "all" && s.metric == metric;
    });
    REQUIRE(it != g.summaries.end());
    return it->median;
  };
  const auto self = find("lines [method.quick.max_iterations=1]", "pcf_mse");
  CHECK(self.ratio == Approx(1.0));
  CHECK(self.lo <= 1.0);
  CHECK(self.hi >= 1.0);
  CHECK(self.n == 3);
  const auto other = find("lines [method.quick.max_iterations=3]", "pcf_mse");
  CHECK(other.ratio == Approx(median_of("lines [method.quick.max_iterations=3]", "pcf_mse") /
                              median_of("lines [method.quick.max_iterations=1]", "pcf_mse")));
  CHECK(other.lo <= other.hi);
  CHECK(other.baseline_label == "lines [method.quick.max_iterations=1]");
  // Paired by seed: each seed's value over the baseline's of the same seed, and their median.
  auto values_of = [&](const std::string& label) {
    const auto it = std::find_if(g.summaries.begin(), g.summaries.end(), [&](const MetricSummary& s) {
      return s.group_label == label && s.scope == "all" && s.metric == "pcf_mse";
    });
    REQUIRE(it != g.summaries.end());
    std::map<uint64_t, double> v;
    for (size_t i = 0; i < it->seeds.size(); ++i) v[it->seeds[i]] = it->values[i];
    return v;
  };
  const auto base_values = values_of("lines [method.quick.max_iterations=1]");
  const auto other_values = values_of("lines [method.quick.max_iterations=3]");
  CHECK(other.paired_seeds == std::vector<uint64_t>{3, 5, 6});
  std::vector<double> by_hand;
  for (uint64_t seed : {3, 5, 6}) by_hand.push_back(other_values.at(seed) / base_values.at(seed));
  REQUIRE(other.paired_ratios.size() == 3);
  for (size_t i = 0; i < 3; ++i) CHECK(other.paired_ratios[i] == Approx(by_hand[i]));
  std::sort(by_hand.begin(), by_hand.end());
  CHECK(other.paired == Approx(by_hand[1]));
  CHECK(other.paired_lo >= by_hand.front());
  CHECK(other.paired_hi <= by_hand.back());
  CHECK(other.paired_lo <= other.paired);
  CHECK(other.paired >= other.paired_lo);
  CHECK(self.paired == 1.0);  // every seed against itself
  CHECK(self.paired_lo == 1.0);
  // The printed table names each group whole (the grid's keys end its label).
  const std::string printed = format_gather(g);
  CHECK_THAT(printed, Catch::Contains("\nlines [method.quick.max_iterations=3]\n  over lines [method.quick.max_iterations=1]\n"));
  CHECK_THAT(printed, Catch::Contains("\nlines [method.quick.max_iterations=1]\n  all "));
  // Written as a table of its own and a section of the Markdown.
  write_gather(g, (d / "g").string(), false);
  CHECK(fs::exists(d / "g" / "baselines.csv"));
  CHECK(fs::exists(d / "g" / "plots" / "paired_1_pcf_mse.png"));  // per-seed ratios, one plot per metric
  std::ifstream html(d / "g" / "index.html");
  CHECK(std::string(std::istreambuf_iterator<char>(html), {}).find("pcf_mse, per seed over lines [method.quick.max_iterations=1]") !=
        std::string::npos);
  std::ifstream md(d / "g" / "gather.md");
  CHECK(std::string(std::istreambuf_iterator<char>(md), {}).find("## Against baselines") != std::string::npos);
  o.baselines = {"lines"};
  CHECK_THROWS_WITH(gather_runs({dir}, o), Catch::Contains("--baseline 'lines'") && Catch::Contains("max_iterations=3"));

  // The same runs outside a sweep (copied): one name, two settings. Each group's label names
  // the keys in which it differs, so the two stay apart and either can be the baseline.
  std::vector<std::string> loose;
  for (size_t i = 0; i < m.rows.size(); ++i) {
    loose.push_back((d / "loose" / std::to_string(i)).string());
    fs::create_directories(loose.back());
    fs::copy(fs::path(dir) / m.rows[i].dir, loose.back(), fs::copy_options::recursive);
  }
  GatherOptions l;
  l.baselines = {"lines (gabor) [method.quick.max_iterations=1]"};
  const GatherResult gl = gather_runs(loose, l);
  std::set<std::string> labels;
  for (const auto& run : gl.runs) labels.insert(run.group_label);
  CHECK(labels == std::set<std::string>{"lines (gabor) [method.quick.max_iterations=1]", "lines (gabor) [method.quick.max_iterations=3]"});
  const auto loose_other = std::find_if(gl.comparisons.begin(), gl.comparisons.end(), [](const BaselineComparison& c) {
    return c.group_label == "lines (gabor) [method.quick.max_iterations=3]" && c.scope == "all" && c.metric == "pcf_mse";
  });
  REQUIRE(loose_other != gl.comparisons.end());
  CHECK(loose_other->ratio == Approx(other.ratio));
  CHECK(loose_other->paired == Approx(other.paired));
  // A seed the baseline did not run has no pair: without the baseline's seed 5 (row 1 of the
  // first group), the pairs are seeds 3 and 6, and a seed gathered twice pairs with nothing.
  REQUIRE(m.rows[1].seed == 5);
  REQUIRE(m.rows[1].group_label == "lines [method.quick.max_iterations=1]");
  REQUIRE(m.rows[4].seed == 5);
  REQUIRE(m.rows[4].group_label == "lines [method.quick.max_iterations=3]");
  std::vector<std::string> without_5 = loose;
  without_5.erase(without_5.begin() + 1);
  const GatherResult g5 = gather_runs(without_5, l);
  const auto unpaired = std::find_if(g5.comparisons.begin(), g5.comparisons.end(), [](const BaselineComparison& c) {
    return c.group_label == "lines (gabor) [method.quick.max_iterations=3]" && c.scope == "all" && c.metric == "pcf_mse";
  });
  REQUIRE(unpaired != g5.comparisons.end());
  CHECK(unpaired->paired_seeds == std::vector<uint64_t>{3, 6});
  CHECK(unpaired->paired == Approx((other_values.at(3) / base_values.at(3) + other_values.at(6) / base_values.at(6)) / 2));
  const auto twice = (d / "loose" / "twice").string();
  fs::copy(loose[4], twice, fs::copy_options::recursive);  // a second copy of the other group's seed 5
  std::vector<std::string> with_twice = loose;
  with_twice.push_back(twice);
  const GatherResult gt = gather_runs(with_twice, l);
  const auto dup = std::find_if(gt.comparisons.begin(), gt.comparisons.end(), [](const BaselineComparison& c) {
    return c.group_label == "lines (gabor) [method.quick.max_iterations=3]" && c.scope == "all" && c.metric == "pcf_mse";
  });
  REQUIRE(dup != gt.comparisons.end());
  CHECK(dup->n == 4);
  CHECK(dup->paired_seeds == std::vector<uint64_t>{3, 6});
  // a single loose run keeps its plain label
  CHECK(gather_runs({loose[0]}, GatherOptions{}).runs.at(0).group_label == "lines (gabor)");
}

TEST_CASE("gather takes each run's points after a stage as a group of its own", "[sweep]") {
  const auto d = test::scratch_dir("sweep_stage");
  const std::string dir = (d / "sw").string();
  const auto m = planned_and_run(tiny_spec(), dir);
  auto row_dir = [&](size_t i) { return (fs::path(dir) / m.rows[i].dir).string(); };
  int last = 0;  // the plan's stage count, from the snapshots a run wrote
  while (fs::exists(row_dir(0) + "/snapshots/stage" + std::string(last + 1 < 10 ? "0" : "") + std::to_string(last + 1) + ".txt")) ++last;
  REQUIRE(last >= 2);
  const std::string last_label = "lines @ stage " + std::to_string(last);

  GatherOptions o;
  o.protocol = PatchProtocol::Crops;
  o.stages = {1, last};
  o.baselines = {last_label};
  const GatherResult g = gather_runs({dir}, o);
  auto summary = [](const GatherResult& r, const std::string& label) {
    const auto it = std::find_if(r.summaries.begin(), r.summaries.end(), [&](const MetricSummary& s) {
      return s.group_label == label && s.scope == "all" && s.metric == "pcf_mse";
    });
    REQUIRE(it != r.summaries.end());
    return *it;
  };
  CHECK(summary(g, "lines").seeds == std::vector<uint64_t>{3, 5, 6});
  CHECK(summary(g, "lines @ stage 1").seeds == std::vector<uint64_t>{3, 5, 6});
  // Each group's stages follow it in their order (tables and plots), not in the order of text:
  // a stage 10 (here a copy of stage 1) comes after stage 2.
  for (size_t i = 0; i < m.rows.size(); ++i)
    fs::copy_file(row_dir(i) + "/snapshots/stage01.txt", row_dir(i) + "/snapshots/stage10.txt");
  GatherOptions ten = o;
  ten.stages = {10, 2, 1};
  std::vector<std::string> order;
  for (const auto& s : gather_runs({dir}, ten).summaries)
    if (s.scope == "all" && s.metric == "pcf_mse") order.push_back(s.group_label);
  CHECK(order == std::vector<std::string>{"lines", "lines @ stage 1", "lines @ stage 2", "lines @ stage 10"});
  // The last stage's points are the output, bit for bit: every seed's ratio is exactly 1.
  const auto final_over_last = std::find_if(g.comparisons.begin(), g.comparisons.end(), [](const BaselineComparison& c) {
    return c.group_label == "lines" && c.scope == "all" && c.metric == "pcf_mse";
  });
  REQUIRE(final_over_last != g.comparisons.end());
  CHECK(final_over_last->paired_ratios == std::vector<double>{1.0, 1.0, 1.0});
  // Stage 1's value is the evaluation of that snapshot, and not the output's.
  EvalOptions e;
  e.protocol = PatchProtocol::Crops;
  e.include_curves = false;
  const RunOutcome seed3 = load_run(row_dir(0));
  const double stage1 = evaluate(seed3.exemplar, read_points(row_dir(0) + "/snapshots/stage01.txt"), e)["all"]["pcf_mse"].get<double>();
  CHECK(summary(g, "lines @ stage 1").values[0] == Approx(stage1));
  CHECK(summary(g, "lines @ stage 1").values[0] != Approx(summary(g, "lines").values[0]));
  // Snapshots have no wall time of their own.
  CHECK(std::none_of(g.summaries.begin(), g.summaries.end(),
                     [](const MetricSummary& s) { return s.group_label == "lines @ stage 1" && s.metric == "seconds"; }));
  write_gather(g, (d / "g").string(), false);
  std::ifstream md(d / "g" / "gather.md");
  CHECK_THAT(std::string(std::istreambuf_iterator<char>(md), {}), Catch::Contains("3 finished runs and 6 stage snapshots"));

  // An unfinished run counts for the stages it has passed, and not as a finished run.
  const fs::path marker = fs::path(row_dir(2)) / ".ppsynth-run";
  json state = read_run_json(marker.string());
  state["state"] = "running";
  std::ofstream(marker) << state.dump(2);
  fs::remove(fs::path(row_dir(2)) / "run.json");
  const GatherResult running = gather_runs({dir}, o);
  CHECK(summary(running, "lines").seeds == std::vector<uint64_t>{3, 5});
  CHECK(summary(running, "lines @ stage 1").seeds == std::vector<uint64_t>{3, 5, 6});
  CHECK(std::count(running.unfinished.begin(), running.unfinished.end(), row_dir(2)) == 1);

  // A finished run without the snapshot is left out, and says why.
  fs::remove(fs::path(row_dir(0)) / "snapshots" / "stage01.txt");
  const GatherResult without = gather_runs({dir}, o);
  CHECK(summary(without, "lines @ stage 1").seeds == std::vector<uint64_t>{5, 6});
  CHECK(std::count(without.unfinished.begin(), without.unfinished.end(),
                   row_dir(0) + " (--stage 1: no snapshots/stage01.txt)") == 1);

  // Stages no run has passed, or that do not exist, and a snapshot that is not the whole output.
  GatherOptions bad = o;
  bad.baselines.clear();
  bad.stages = {99};
  CHECK_THROWS_WITH(gather_runs({dir}, bad), Catch::Contains("--stage 99: no gathered run has passed"));
  bad.stages = {0};
  CHECK_THROWS_WITH(gather_runs({dir}, bad), Catch::Contains("--stage 0: expected a stage number >= 1"));
  const std::string window = row_dir(1) + "/snapshots/stage02.txt";
  write_points(window, read_points(window).crop({0, 0, 0.5, 1}), Format::Plain);  // as a window's snapshot is
  bad.stages = {2};
  CHECK_THROWS_WITH(gather_runs({dir}, bad), Catch::Contains(window) && Catch::Contains("whole outputs only"));
}

TEST_CASE("gather tells apart two sweeps of one run config with other settings", "[sweep]") {
  const auto d = test::scratch_dir("sweep_two_sets");
  std::vector<std::string> dirs;
  for (const int iterations : {1, 2}) {
    json spec = tiny_spec();
    spec["seeds"] = {3};
    spec["set"] = {"method.quick.max_iterations=" + std::to_string(iterations), "method.quick.res=16"};
    dirs.push_back((d / ("sw" + std::to_string(iterations))).string());
    plan_sweep(expand_sweep_spec(spec, "spec", ""), dirs.back());
    REQUIRE(run_sweep_task(dirs.back(), load_sweep(dirs.back()).rows[0].id, "", nullptr) == RowState::Done);
  }
  std::set<std::string> labels;
  for (const auto& run : gather_runs(dirs, GatherOptions{}).runs) labels.insert(run.group_label);
  CHECK(labels == std::set<std::string>{"lines [method.quick.max_iterations=1]", "lines [method.quick.max_iterations=2]"});
  // alone, a sweep keeps its plain labels
  CHECK(gather_runs({dirs[0]}, GatherOptions{}).runs.at(0).group_label == "lines");
  // Two sweeps with one grid label, one without a key the other has (a term it does not
  // switch on): one bracket per label, the missing key named as unset.
  std::vector<std::string> grids;
  for (const bool term : {true, false}) {
    json spec = tiny_spec({{"method.quick.max_iterations", {1}}});
    spec["seeds"] = {3};
    if (term) spec["set"].push_back("method.terms.separation.weight=1");
    grids.push_back((d / (term ? "grid_term" : "grid")).string());
    plan_sweep(expand_sweep_spec(spec, "spec", ""), grids.back());
    REQUIRE(run_sweep_task(grids.back(), load_sweep(grids.back()).rows[0].id, "", nullptr) == RowState::Done);
  }
  labels.clear();
  for (const auto& run : gather_runs(grids, GatherOptions{}).runs) labels.insert(run.group_label);
  CHECK(labels == std::set<std::string>{"lines [method.quick.max_iterations=1, method.terms.separation.weight=1]",
                                        "lines [method.quick.max_iterations=1, method.terms.separation.weight unset]"});
}
