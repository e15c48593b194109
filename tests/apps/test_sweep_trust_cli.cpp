// Sweeps and gathers that trust only what they can prove, through the real binary: gather
// --force never replaces a run or one of its inputs; a sweep's tasks name their row by id, so
// a re-plan never makes a task run another row; one process at a time works on a sweep; a
// re-plan waits for running rows; the SLURM script is built from checked values only; a grid
// axis that changes nothing is refused; the local executor keeps the user's PPSYNTH_THREADS.
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/atomic_file.hpp"
#include "core/formats/text_table.hpp"
#include "core/run_directory.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::Child;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
const std::string kTiny = " --quick -q --set method.quick.max_iterations=1 --set method.quick.res=16 ";

// A sweep spec of lines over `seeds`, each run tiny unless `iterations` says otherwise. Runs
// of more iterations than lines' 500 a stage take them all (no early stop): a row meant to be
// running when a test signals must not have finished on a loaded machine (a stage of lines
// converges in a second or two).
std::string spec(const fs::path& d, const std::string& seeds, int iterations = 1, const std::string& grid = "{}") {
  const fs::path p = d / ("spec_" + std::to_string(iterations) + ".json");
  const std::string longer = iterations > 500 ? ", \"method.max_iterations=" + std::to_string(iterations) +
                                                    "\", \"method.convergence.window=1000000000\""
                                              : "";
  std::ofstream(p) << "{\"name\": \"trust\", \"runs\": [\"" << kLines << "\"], \"seeds\": \"" << seeds
                   << "\", \"quick\": true, \"grid\": " << grid << ", \"set\": [\"method.quick.max_iterations=" << iterations
                   << "\", \"method.quick.res=16\"" << longer << "]}";
  return p.string();
}

std::string row_id(const std::string& dir, uint64_t seed) {
  for (const auto& r : ppsynth::load_sweep(dir).rows)
    if (r.seed == seed) return r.id;
  FAIL("no row of seed " << seed);
  return "";
}

}  // namespace

TEST_CASE("gather --force replaces only a gather's own directory, never a run or an input", "[apps][gather][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_gather");
  const std::string a = (d / "a").string(), b = (d / "b").string(), g = (d / "g").string();
  REQUIRE(run_ppsynth("synthesize " + kLines + kTiny + "-o " + a).status == 0);
  REQUIRE(run_ppsynth("synthesize " + kLines + kTiny + "--seed 96 -o " + b).status == 0);
  // The defect: -o A --force replaced the input run A with gather's files.
  for (const std::string out : {a, a + "/", a + "/tables", std::string(d.string())}) {
    const auto r = run_ppsynth("gather " + a + " " + b + " -o " + out + " --force");
    INFO(out << ": " << r.output);
    CHECK(r.status == 2);
    CHECK(fs::exists(a + "/output.txt"));
    CHECK(ppsynth::run_dir_state(a) == ppsynth::RunDirState::Complete);
  }
  // A run that is not an input is not a gather's either.
  const auto run = run_ppsynth("gather " + a + " -o " + b + " --force");
  CHECK(run.status == 2);
  CHECK_THAT(run.output, Catch::Contains("not a gather"));
  CHECK(fs::exists(b + "/output.txt"));
  // A gather's own directory is replaced with --force.
  REQUIRE(run_ppsynth("gather " + a + " " + b + " -o " + g).status == 0);
  CHECK(run_ppsynth("gather " + a + " " + b + " -o " + g).status == 2);
  CHECK(run_ppsynth("gather " + a + " " + b + " -o " + g + " --force").status == 0);

  // A sweep's run: the defect replaced it and `sweep status` still said done.
  const std::string sw = (d / "sw").string();
  REQUIRE(run_ppsynth("sweep plan " + spec(d, "95") + " -o " + sw).status == 0);
  REQUIRE(run_ppsynth("sweep run " + sw + " --local", "PPSYNTH_THREADS=1").status == 0);
  const std::string row = sw + "/runs/" + row_id(sw, 95);
  CHECK(run_ppsynth("gather " + sw + " -o " + row + " --force").status == 2);
  CHECK(fs::exists(row + "/output.txt"));
}

TEST_CASE("a sweep's tasks name their row by id: a re-plan never runs another row", "[apps][sweep][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_replan");
  const std::string sw = (d / "sw").string();
  REQUIRE(run_ppsynth("sweep plan " + spec(d, "95-97") + " -o " + sw).status == 0);
  const std::string id95 = row_id(sw, 95), id96 = row_id(sw, 96);
  const std::string before = ppsynth::sweep_manifest_hash(ppsynth::load_sweep(sw));
  // A re-plan while tasks are queued: seed 95 leaves the plan, the rows after it move up.
  REQUIRE(run_ppsynth("sweep plan " + spec(d, "96-97") + " -o " + sw).status == 0);
  // The task queued for seed 96 runs seed 96 (the defect ran the row that moved into its place).
  const auto t96 = run_ppsynth("sweep task " + sw + " --row " + id96 + " --manifest " + before, "PPSYNTH_THREADS=1");
  INFO(t96.output);
  REQUIRE(t96.status == 0);
  CHECK_THAT(t96.output, Catch::Contains("planned again"));
  CHECK_THAT(ppsynth::read_file_text(sw + "/runs/" + id96 + "/run.json"), Catch::Contains("\"seed\": 96"));
  // The task queued for the dropped row runs nothing.
  const auto t95 = run_ppsynth("sweep task " + sw + " --row " + id95 + " --manifest " + before, "PPSYNTH_THREADS=1");
  CHECK(t95.status == 2);
  CHECK_THAT(t95.output, Catch::Contains("no row " + id95));
  CHECK_FALSE(fs::exists(sw + "/runs/" + id95));
}

TEST_CASE("one process at a time works on a sweep; a re-plan waits for running rows", "[apps][sweep][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_lock");
  const std::string sw = (d / "sw").string();
  const std::string long_spec = spec(d, "95-96", 100000);
  REQUIRE(run_ppsynth("sweep plan " + long_spec + " -o " + sw).status == 0);
  {  // The defect: two executors on one sweep both ran its rows, and reported the other's as failed.
    Child first("sweep run " + sw + " --local -j 1", "PPSYNTH_THREADS=1");
    REQUIRE(first.wait_for([](const std::string& l) { return l.find("runs to do") != std::string::npos; }));
    const auto second = run_ppsynth("sweep run " + sw + " --local -j 1", "PPSYNTH_THREADS=1");
    INFO(second.output);
    CHECK(second.status == 2);
    CHECK_THAT(second.output, Catch::Contains("another ppsynth process"));
    const auto replan = run_ppsynth("sweep plan " + long_spec + " -o " + sw);
    CHECK(replan.status == 2);
    first.signal(SIGINT);
    CHECK(first.finish() == 130);
  }
  {  // A row running outside an executor (a SLURM task, say): the re-plan is refused too.
    Child task("sweep task " + sw + " --row " + row_id(sw, 95), "PPSYNTH_THREADS=1");
    // Running: an iteration's line (resumed from the executor's checkpoint, at whatever iteration).
    const bool progressed = task.wait_for([](const std::string& l) { return std::regex_search(l, std::regex(" it +[0-9]+/")); });
    INFO(task.output());
    REQUIRE(progressed);
    const auto replan = run_ppsynth("sweep plan " + spec(d, "96") + " -o " + sw);
    INFO(replan.output);
    CHECK(replan.status == 2);
    CHECK_THAT(replan.output, Catch::Contains("is running"));
    CHECK(ppsynth::load_sweep(sw).rows.size() == 2);  // nothing changed
    task.signal(SIGTERM);
    CHECK(task.finish() == 143);
  }
}

TEST_CASE("the SLURM script is built only from checked values", "[apps][sweep][slurm][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_sbatch");
  const std::string sw = (d / "sw").string();
  REQUIRE(run_ppsynth("sweep plan " + spec(d, "95") + " -o " + sw).status == 0);
  CHECK(run_ppsynth("sweep run " + sw + " --slurm --dry-run").status == 0);
  // (Single quotes keep a newline in the argument, as a user's script would pass it.)
  for (const std::string option : {"--partition 'a\n#SBATCH --wrap=id'", "--account 'a\nid'", "--partition 'a b'",
                                   "--sbatch-option '--qos=a\rb'", "--cpus 0", "--time-minutes 99999999999"}) {
    const auto r = run_ppsynth("sweep run " + sw + " --slurm --dry-run " + option);
    INFO(option << ": " << r.output);
    CHECK(r.status == 2);
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);  // one line: no script, no value's newline
  }
  // A manifest edited by hand: a name that would become shell lines, resources out of range.
  const std::string manifest = sw + "/manifest.json";
  const std::string good = ppsynth::read_file_text(manifest);
  for (const auto& [pointer, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"/name", "x\n#SBATCH --wrap=id"}, {"/resources/cpus", -5}, {"/resources/memory_mb", 0},
           {"/rows/0/id", "$(id)"}, {"/rows/0/dir", "../../elsewhere"}}) {
    auto j = nlohmann::json::parse(good);
    j[nlohmann::json::json_pointer(pointer)] = value;
    ppsynth::write_text_atomic(manifest, j.dump(1));
    const auto r = run_ppsynth("sweep run " + sw + " --slurm --dry-run");
    INFO(pointer << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("manifest.json") && !Catch::Contains("#SBATCH"));
  }
  ppsynth::write_text_atomic(manifest, good);
}

TEST_CASE("a grid axis that does not change the synthesis is refused", "[apps][sweep][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_grid");
  // The defect: 4 values of "description" silently became one run.
  for (const std::string grid : {R"({"description": ["a", "b", "c", "d"]})", R"({"evaluate": [true, false]})",
                                 R"({"method.k": [10, 20], "snapshots": [true, false]})"}) {
    const auto r = run_ppsynth("sweep plan " + spec(d, "95", 1, grid) + " -o " + (d / "sw").string());
    INFO(grid << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("grid") && Catch::Contains("same runs"));
    CHECK_FALSE(fs::exists(d / "sw" / "manifest.json"));
  }
  CHECK(run_ppsynth("sweep plan " + spec(d, "95", 1, R"({"method.k": [10, 20]})") + " -o " + (d / "sw").string()).status == 0);
}

TEST_CASE("the local executor keeps the user's PPSYNTH_THREADS", "[apps][sweep][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_threads");
  const std::string sw = (d / "sw").string();
  REQUIRE(run_ppsynth("sweep plan " + spec(d, "95") + " -o " + sw).status == 0);
  const auto r = run_ppsynth("sweep run " + sw + " --local -j 1", "PPSYNTH_THREADS=1");
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("1 at once, 1 thread each"));
  CHECK_THAT(ppsynth::read_file_text(sw + "/runs/" + row_id(sw, 95) + "/run.json"), Catch::Contains("\"threads\": 1"));
}
