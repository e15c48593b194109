// A run directory proves itself before a run continues from it, through the real binary:
// --resume refuses a config.json edited since the run began, a checkpoint copied from another
// run, and a damaged one (exit 2, one line saying what differs, never a crash or a backtrace);
// --resume --force starts the run afresh. And what cannot run is refused before the run
// directory exists: sizes that make no output, an evaluation that cannot run, an output past
// the memory budget; a stop during the initialization or between a large output's windows is
// seen within a second.
#include <catch2/catch.hpp>

#include <csignal>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/formats/text_table.hpp"
#include "core/run_directory.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::Child;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kRuns = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/";
const std::string kQuick = " --quick --set method.quick.max_iterations=40 --set method.quick.res=16 --set checkpoint_seconds=1e-9 ";

// An unfinished run of lines in `dir` with a checkpoint (stopped by SIGTERM once stage 2 began).
void interrupted_run(const std::string& dir, const std::string& extra = "") {
  Child c("synthesize " + kRuns + "lines.json" + kQuick + extra + " -o " + dir);
  REQUIRE(c.wait_for([](const std::string& l) { return l.find("stage 2/") != std::string::npos; }));
  c.signal(SIGTERM);
  INFO(c.output());
  REQUIRE(c.finish() == 143);
  REQUIRE(fs::exists(dir + "/checkpoint.bin"));
}

void set_config_key(const std::string& dir, const nlohmann::json::json_pointer& key, const nlohmann::json& value) {
  auto c = nlohmann::json::parse(ppsynth::read_file_text(dir + "/config.json"));
  c[key] = value;
  ppsynth::write_text_atomic(dir + "/config.json", c.dump(2));
}

// A refusal as the contract has it: exit 2, one line naming what, nothing changed.
void check_refused(const ppsynth::test::CommandResult& r, const std::string& says) {
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains(says));
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
  CHECK_THAT(r.output, !Catch::Contains("Exception raised from") && !Catch::Contains("internal error"));
}

}  // namespace

TEST_CASE("--resume refuses a config.json edited since the run began, saying what differs", "[apps][resume][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_edited");
  const std::string run = (d / "run").string();
  interrupted_run(run);
  const std::string original = ppsynth::read_file_text(run + "/config.json");
  struct Edit {
    std::string key;
    nlohmann::json value;
    std::string says;
  };
  for (const Edit& e : {Edit{"/seed", 96, "seed 96 (the checkpoint's: 95)"},
                        Edit{"/method/c2", 1.5, "config key 'method.c2'"},
                        Edit{"/method/max_iterations", 7, "config key 'method.max_iterations'"},
                        Edit{"/method/num_sigmas", 3, "config key 'method.num_sigmas'"},
                        Edit{"/color", "red", "config key 'color'"},
                        Edit{"/checkpoint_seconds", -1, "config key 'checkpoint_seconds'"},
                        Edit{"/exemplar", "shared:data/exemplars/gabor-paper/poisson_n64c2_point.txt", "exemplar"}}) {
    set_config_key(run, nlohmann::json::json_pointer(e.key), e.value);
    INFO(e.key);
    check_refused(run_ppsynth("synthesize --resume " + run), e.says);
    ppsynth::write_text_atomic(run + "/config.json", original);
  }
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Unfinished);
  REQUIRE(run_ppsynth("synthesize -q --resume " + run).status == 0);
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Complete);
}

TEST_CASE("--resume refuses a checkpoint copied from another seed's run", "[apps][resume][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_foreign");
  const std::string a = (d / "a").string(), b = (d / "b").string();
  interrupted_run(a);
  interrupted_run(b, "--seed 96");
  fs::copy_file(b + "/checkpoint.bin", a + "/checkpoint.bin", fs::copy_options::overwrite_existing);
  check_refused(run_ppsynth("synthesize --resume " + a), "seed 95 (the checkpoint's: 96)");
  // --force starts it afresh from its own config.json, and it finishes.
  const auto fresh = run_ppsynth("synthesize -q --resume " + a + " --force");
  INFO(fresh.output);
  REQUIRE(fresh.status == 0);
  CHECK(ppsynth::run_dir_state(a) == ppsynth::RunDirState::Complete);
  CHECK_FALSE(fs::exists(a + "/checkpoint.bin"));
  CHECK_THAT(ppsynth::read_file_text(a + "/run.json"), Catch::Contains("\"seed\": 95"));
}

TEST_CASE("a damaged checkpoint is refused with one line; never a crash", "[apps][resume][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_damaged");
  const std::string run = (d / "run").string();
  interrupted_run(run);
  const std::string bytes = ppsynth::read_file_text(run + "/checkpoint.bin");
  // One flipped byte anywhere: in the index arrays (the defect: a segfault in map_weights), in
  // the optimizer's state (the defect: a finished, wrong output), at the start and the end.
  for (size_t at : {size_t{3}, bytes.size() / 4, bytes.size() / 2, 3 * bytes.size() / 4, bytes.size() - 3}) {
    std::string bad = bytes;
    bad[at] = static_cast<char>(bad[at] ^ 0x40);
    {
      std::ofstream out(run + "/checkpoint.bin", std::ios::binary);
      out << bad;
    }
    INFO("byte " << at << " of " << bytes.size());
    check_refused(run_ppsynth("synthesize --resume " + run), "checkpoint.bin");
  }
  std::ofstream(run + "/checkpoint.bin", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  check_refused(run_ppsynth("synthesize --resume " + run), "checkpoint.bin");
  CHECK_THAT(run_ppsynth("synthesize --resume " + run).output, Catch::Contains("--force"));
  std::ofstream(run + "/checkpoint.bin", std::ios::binary) << bytes;
  CHECK(run_ppsynth("synthesize -q --resume " + run).status == 0);
}

TEST_CASE("outputs that cannot be made are refused before the run directory exists", "[apps][synthesize][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_sizes");
  const std::string out = (d / "out").string();
  struct Case {
    std::string args, says;
  };
  for (const Case& c : {Case{"--size 0.02 0.02 --set evaluate=false", "at least one"},  // the defect: rc 0, 0 points
                        Case{"--size 0.5 0.5", "evaluate=false"},  // the defect: refused after the synthesis, naming --protocol
                        Case{"--size 4 0.5", "smaller than the exemplar"},
                        Case{"--set output.size=[1,\"x\"]", "output.size"},  // the defect: a run directory was left, blocking the next
                        Case{"--set output.size=[1e9,1]", "output.size"}}) {
    const auto r = run_ppsynth("synthesize " + kRuns + "lines.json --quick -q " + c.args + " -o " + out);
    INFO(c.args << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(c.says));
    CHECK_THAT(r.output, !Catch::Contains("--protocol"));
    CHECK_FALSE(fs::exists(out));
  }
  // The corrected command runs.
  CHECK(run_ppsynth("synthesize " + kRuns + "lines.json --quick -q --set method.quick.max_iterations=1 --size 1 1 -o " + out).status == 0);
}

TEST_CASE("an output past the memory budget is refused at once", "[apps][synthesize][trust]") {
  auto d = ppsynth::test::scratch_dir("trust_memory");
  const auto t0 = std::chrono::steady_clock::now();
  // The defect: 2e9 points ran 9.6 CPU-minutes in the initialization, and SIGTERM went unseen.
  const auto r = run_ppsynth("synthesize " + kRuns + "lines.json --size 1e4 1e4 -o " + (d / "x").string(),
                             "PPSYNTH_MEMORY_LIMIT_MB=1000");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("output.size") && Catch::Contains("points") && Catch::Contains("available"));
  CHECK(seconds < 30);
  CHECK_FALSE(fs::exists(d / "x"));
}

TEST_CASE("--quick accepts every rectangle the full settings accept", "[apps][synthesize][trust][windows]") {
  auto d = ppsynth::test::scratch_dir("trust_quick_rect");
  // The defect: "a window of 1.64 exemplar units cannot hold two margins of 1.14" at --quick
  // only: its coarser grid made the margins wider than the full settings' (0.60 for lines).
  for (const std::string args : {"--size 4 1", "--size 4 2"}) {
    const auto r = run_ppsynth("synthesize " + kRuns + "lines.json --quick -q --set method.quick.max_iterations=1 " + args +
                               " --set evaluate=false -o " + (d / "x").string());
    INFO(args << ": " << r.output);
    CHECK(r.status == 0);
    fs::remove_all(d / "x");
  }
  // A strip one exemplar high with the published border, past a budget of 24 x 24 positions
  // (one grid of it would take 96 x 24): its windows are at most one exemplar wide, too narrow
  // for two margins of the full settings as for --quick, which now judges it with the same
  // margins (the full settings refuse it with this very message).
  const auto strip = run_ppsynth("synthesize " + kRuns + "lines.json --quick -q --size 4 1 --set output.border=published "
                                 "--set method.window.pixels=24 -o " + (d / "x").string());
  CHECK(strip.status == 2);
  CHECK_THAT(strip.output, Catch::Contains("two margins of 0.602165"));
  CHECK_FALSE(fs::exists(d / "x"));
}

TEST_CASE("a stop during the initialization or between windows is seen within a second", "[apps][synthesize][trust][windows]") {
  auto d = ppsynth::test::scratch_dir("trust_stop");
  const std::string out = (d / "big").string();
  // A large output: its initialization and its windows' set-up run long between iterations.
  Child c("synthesize " + kRuns + "lines.json --size 120 120 --set method.max_iterations=1 --set evaluate=false -o " + out,
          "PPSYNTH_THREADS=1");
  REQUIRE(c.wait_for([](const std::string& l) { return l.find("points") != std::string::npos; }));
  const auto t0 = std::chrono::steady_clock::now();
  c.signal(SIGTERM);
  const int status = c.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(c.output());
  CHECK(status == 143);
  CHECK(seconds < 10);  // within a second on an idle machine; the bound leaves room for a loaded one
  // It stopped before its first checkpoint: nothing is left, nothing blocks the next run.
  CHECK_THAT(c.output(), Catch::Contains("nothing was kept"));
  CHECK_FALSE(fs::exists(out));
}
