// Runs that survive: the real binary interrupted by SIGINT, SIGTERM and kill -9 at chosen
// points of its progress (mid-stage, at a stage boundary, twice in a row), resumed with
// `synthesize --resume`, ends with every output file byte for byte equal to the run never
// interrupted (run.json's wall times aside; loss.csv without its seconds column).
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <regex>

#include "core/atomic_file.hpp"
#include "core/formats/text_table.hpp"
#include "core/paths.hpp"
#include "core/run_directory.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/run_compare.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::Child;
using ppsynth::test::check_same_run;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kGabor = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/";

// Quick settings with enough iterations per stage to interrupt inside one.
std::string quick_run(const std::string& config, const std::string& extra = "") {
  return kGabor + config + " --quick --set method.quick.max_iterations=9 --set method.quick.res=16 " + extra;
}

// A line of the progress log: stage `stage` (1-based) has begun / iteration `it` of it ran.
std::function<bool(const std::string&)> stage_begins(int stage) {
  return [stage](const std::string& l) { return l.find("stage " + std::to_string(stage) + "/") != std::string::npos; };
}
std::function<bool(const std::string&)> iteration_of(const std::string& label, int it) {
  const std::regex re(label + " it +" + std::to_string(it) + "/");
  return [re](const std::string& l) { return std::regex_search(l, re); };
}

// Interrupts a run at `when` with `sig`; returns the exit code. The run must be unfinished then.
int interrupt(const std::string& args, const std::function<bool(const std::string&)>& when, int sig) {
  Child c(args);
  REQUIRE(c.wait_for(when));
  c.signal(sig);
  const int status = c.finish();
  INFO(c.output());
  return status;
}

}  // namespace

TEST_CASE("SIGINT mid-stage: exit 130, the resume command printed, --resume finishes it identically", "[apps][resume]") {
  auto d = ppsynth::test::scratch_dir("resume_sigint");
  const std::string run = (d / "run").string();
  REQUIRE(run_ppsynth("synthesize " + quick_run("lines.json") + "-o " + (d / "ref").string()).status == 0);
  Child c("synthesize " + quick_run("lines.json") + "-o " + run);
  REQUIRE(c.wait_for(iteration_of("sigma 1/2", 3)));
  c.signal(SIGINT);
  CHECK(c.finish() == 130);
  CHECK_THAT(c.output(), Catch::Contains("ppsynth synthesize --resume " + run));
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Unfinished);
  CHECK(fs::exists(run + "/checkpoint.bin"));
  // Starting again without --resume refuses and names both ways on.
  auto again = run_ppsynth("synthesize " + quick_run("lines.json") + "-o " + run);
  CHECK(again.status == 2);
  CHECK_THAT(again.output, Catch::Contains("--resume") && Catch::Contains("--force"));
  // --resume takes the directory alone.
  CHECK(run_ppsynth("synthesize --resume " + run + " --seed 3").status == 2);
  REQUIRE(run_ppsynth("synthesize -q --resume " + run).status == 0);
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Complete);
  check_same_run(d / "ref", run);
  // Its run.json times the whole run: the interrupted process's time (from its checkpoint)
  // and this one's; the uninterrupted run had nothing before.
  const auto info = nlohmann::json::parse(ppsynth::read_file_text(fs::path(run) / "run.json"));
  const double before = info["method_stats"].value("seconds_before_resume", -1.0);
  CHECK(before > 0);
  CHECK(info["synthesis_seconds"].get<double>() >= before);
  CHECK(info["total_seconds"].get<double>() >= info["synthesis_seconds"].get<double>());
  const auto ref = nlohmann::json::parse(ppsynth::read_file_text(d / "ref" / "run.json"));
  CHECK(ref["method_stats"].value("seconds_before_resume", -1.0) == 0);
  // The CPU time too: the interrupted process's (its checkpoint kept it) and this one's.
  CHECK(ref.value("cpu_seconds", 0.0) > 0);
  CHECK(info.value("cpu_seconds", 0.0) > 0);
  // A finished run has nothing to resume.
  auto done = run_ppsynth("synthesize --resume " + run);
  CHECK(done.status == 2);
  CHECK_THAT(done.output, Catch::Contains("finished"));
}

TEST_CASE("SIGTERM at a stage's start, then SIGINT after resuming, then resume again", "[apps][resume]") {
  auto d = ppsynth::test::scratch_dir("resume_twice");
  const std::string run = (d / "run").string();
  REQUIRE(run_ppsynth("synthesize " + quick_run("lines.json") + "-o " + (d / "ref").string()).status == 0);
  CHECK(interrupt("synthesize " + quick_run("lines.json") + "-o " + run, stage_begins(2), SIGTERM) == 143);
  CHECK(interrupt("synthesize --resume " + run, iteration_of("sigma 2/2", 5), SIGINT) == 130);
  REQUIRE(run_ppsynth("synthesize -q --resume " + run).status == 0);
  check_same_run(d / "ref", run);
}

TEST_CASE("kill -9 loses at most a checkpoint interval: from a stage boundary and mid-stage", "[apps][resume]") {
  auto d = ppsynth::test::scratch_dir("resume_kill");
  SECTION("2 classes, checkpoints at stage boundaries only: resumes from the boundary") {
    const std::string cfg = "poisson_n64c2_point.json";
    const std::string run = (d / "run2").string();
    const std::string boundaries_only = quick_run(cfg, "--set checkpoint_seconds=1e6 ");
    CHECK(interrupt("synthesize " + boundaries_only + "-o " + run, iteration_of("class 2/2 \\(id 1\\), sigma 1/2", 4),
                    SIGKILL) == 128 + SIGKILL);
    REQUIRE(fs::exists(run + "/checkpoint.bin"));
    // the run's own config says checkpoint_seconds=1e6: compare against a reference made with it
    REQUIRE(run_ppsynth("synthesize " + boundaries_only + "-o " + (d / "ref2b").string()).status == 0);
    REQUIRE(run_ppsynth("synthesize -q --resume " + run).status == 0);
    check_same_run(d / "ref2b", run);
  }
  SECTION("disks, a checkpoint after every iteration: resumes mid-stage") {
    const std::string cfg = "poisson_n64c2_disk.json";
    const std::string every = "--set checkpoint_seconds=1e-9 ";
    REQUIRE(run_ppsynth("synthesize " + quick_run(cfg, every) + "-o " + (d / "refd").string()).status == 0);
    const std::string run = (d / "rund").string();
    CHECK(interrupt("synthesize " + quick_run(cfg, every) + "-o " + run, iteration_of("class 1/2 \\(id 0\\), sigma 2/2", 2),
                    SIGKILL) == 128 + SIGKILL);
    REQUIRE(run_ppsynth("synthesize -q --resume " + run).status == 0);
    check_same_run(d / "refd", run);
  }
}

TEST_CASE("a run directory moved elsewhere, its exemplar file gone, resumes from its own copy", "[apps][resume]") {
  auto d = ppsynth::test::scratch_dir("resume_moved");
  const fs::path ex = d / "lines_copy.txt";
  fs::copy_file(fs::path(ppsynth::shared_root()) / "data/exemplars/gabor-paper/lines.txt", ex);
  const std::string args = quick_run("lines.json", "-e " + ex.string() + " ");
  REQUIRE(run_ppsynth("synthesize " + args + "-o " + (d / "ref").string()).status == 0);
  CHECK(interrupt("synthesize " + args + "-o " + (d / "run").string(), iteration_of("sigma 1/2", 3), SIGINT) == 130);
  // What a resume needs is in the directory from the start (a machine that resumes it need
  // not have the exemplar's file, nor the same path).
  REQUIRE(fs::exists(d / "run" / "exemplar.txt"));
  fs::rename(d / "run", d / "moved");
  fs::remove(ex);
  SECTION("resumed, it ends as the run never stopped") {
    REQUIRE(run_ppsynth("synthesize -q --resume " + (d / "moved").string()).status == 0);
    check_same_run(d / "ref", d / "moved");
  }
  SECTION("its copy edited, the resume is refused") {
    const std::string copy = (d / "moved" / "exemplar.txt").string();
    std::string text = ppsynth::read_file_text(copy);
    const size_t last = text.rfind('\n', text.size() - 2) + 1;  // a point more: its last line again
    text += text.substr(last);
    ppsynth::write_text_atomic(copy, text);
    auto r = run_ppsynth("synthesize --resume " + (d / "moved").string());
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("made for another synthesis") && Catch::Contains("the exemplar's points"));
  }
}

TEST_CASE("a method that cannot resume says so", "[apps][resume]") {
  auto d = ppsynth::test::scratch_dir("resume_baseline");
  const std::string run = (d / "run").string();
  REQUIRE(run_ppsynth("synthesize " + kGabor + "lines_roveri2015.json --quick -q -o " + run).status == 0);
  // What a killed roveri2015 run leaves: its directory unfinished, and no checkpoint.
  auto marker = ppsynth::run_dir_marker(run);
  marker["state"] = "running";
  ppsynth::write_text_atomic(run + "/.ppsynth-run", marker.dump());
  auto r = run_ppsynth("synthesize --resume " + run);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("cannot resume") && Catch::Contains("--force"));
}
