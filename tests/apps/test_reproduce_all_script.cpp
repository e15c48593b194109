// scripts/reproduce_all.sh, the paper's whole plan: its arguments are checked before anything
// is written; --keep-runs keeps finished runs and unfinished runs' checkpoints where a later
// machine finds them. An option in the place of OUT_DIR (`--help`, `--seeds 95-99` first) once became a
// directory named after it and started every config's runs there.
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <regex>

#include "core/formats/text_table.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

TEST_CASE("reproduce_all.sh --help prints its usage and runs nothing", "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_help");
  const auto r = test::run_program(std::string(PPSYNTH_SOURCE_DIR) + "/scripts/reproduce_all.sh", "--help", "cd " + d.string() + " &&");
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK(r.output.find("Usage: scripts/reproduce_all.sh [OUT_DIR]") != std::string::npos);
  CHECK(fs::is_empty(d));
}

TEST_CASE("reproduce_all.sh refuses an option where OUT_DIR goes, and an unknown config, before any run",
          "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_bad");
  const std::string script = std::string(PPSYNTH_SOURCE_DIR) + "/scripts/reproduce_all.sh";
  const std::string bin = test::ppsynth_binary();
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"--seeds 95-99", "'--seeds' where OUT_DIR and PPSYNTH_BINARY go"},
           {"out --quick", "'--quick' where OUT_DIR and PPSYNTH_BINARY go"},
           {"out " + bin + " --only 'fig04 fig99'", "--only names 'fig99'"}}) {
    const auto r = test::run_program(script, args, "cd " + d.string() + " &&");
    INFO(args << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK(r.output.find(message) != std::string::npos);
    CHECK(fs::is_empty(d));  // nothing written: no OUT_DIR, no directory named after an option
  }
}

// --keep-runs: the sweep's finished runs are copied, without their pictures, to a folder that
// outlives the machine, and a later run of the script on a new OUT_DIR reuses them instead of
// running them again (the machines of a long reproduction do not outlive a session).
TEST_CASE("reproduce_all.sh --keep-runs keeps a compact copy of each finished run, and a later plan reuses it",
          "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_keep");
  const std::string script = std::string(PPSYNTH_SOURCE_DIR) + "/scripts/reproduce_all.sh";
  const std::string bin = test::ppsynth_binary();
  const std::string kept = (d / "kept").string();

  const auto refused = test::run_program(script, "out " + bin + " --only fig15 --keep-runs " + kept, "cd " + d.string() + " &&");
  INFO(refused.output);
  CHECK(refused.status == 2);
  CHECK(refused.output.find("--keep-runs keeps the runs of sweeps over seeds; give --seeds too") != std::string::npos);
  CHECK(fs::is_empty(d));

  // fig15's one panel is fig08's second row: the same runs, which fig15 reuses and which are kept once.
  const std::string args = bin + " --only 'fig08 fig15' --quick --seeds 95 --keep-runs " + kept;
  const auto first = test::run_program(script, "out1 " + args, "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(first.output);
  REQUIRE(first.status == 0);
  std::vector<fs::path> runs;
  for (auto& e : fs::directory_iterator(fs::path(kept) / "fig08")) runs.push_back(e.path());
  REQUIRE(runs.size() == 2);  // ours on each row; the initialization is not a run
  CHECK((!fs::exists(fs::path(kept) / "fig15") || fs::is_empty(fs::path(kept) / "fig15")));
  for (const auto& run : runs) {
    for (const char* f : {".ppsynth-run", "config.json", "run.json", "output.txt", "init.txt", "exemplar.txt", "metrics.json"})
      CHECK(fs::exists(run / f));
    CHECK_FALSE(fs::exists(run / "exemplar_vs_output.png"));  // pictures are drawn again, not kept
    CHECK_FALSE(fs::exists(run / "snapshots"));
  }
  const auto kept_output = fs::last_write_time(runs[0] / "output.txt");

  const auto second = test::run_program(script, "out2 " + args, "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(second.output);
  REQUIRE(second.status == 0);
  for (const auto& run : runs) CHECK(second.output.find("reusing the finished run " + run.string()) != std::string::npos);
  CHECK(second.output.find(": done (") == std::string::npos);  // nothing synthesized again
  CHECK(fs::exists(d / "out2" / "fig15" / "report.json"));
  CHECK(fs::last_write_time(runs[0] / "output.txt") == kept_output);  // a kept run is never replaced

  // A run kept under another name (a machine of the other processor class names its runs by
  // the config it resolved there) and reused here is not kept again under this machine's name.
  const fs::path elsewhere = fs::path(kept) / "fig08" / "made_elsewhere";
  fs::rename(runs[0], elsewhere);
  const auto third = test::run_program(script, "out3 " + args, "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(third.output);
  REQUIRE(third.status == 0);
  CHECK(third.output.find("reusing the finished run " + elsewhere.string()) != std::string::npos);
  CHECK(third.output.find(": done (") == std::string::npos);
  size_t kept_now = 0;
  for (const auto& item : fs::directory_iterator(kept))
    for (auto& e : fs::directory_iterator(item.path())) kept_now += e.is_directory() ? 1 : 0;
  CHECK(kept_now == 2);

  // --kept-only: no new run. fig08 and fig15 are reported from what is kept; fig04 (nothing
  // kept) is listed with the runs it lacks, not run, and the page is made over the other two.
  const auto lone = test::run_program(script, "out4 " + bin + " --only fig04 --quick --seeds 95 --kept-only", "cd " + d.string() + " &&");
  CHECK(lone.status == 2);
  CHECK(lone.output.find("--kept-only reports what --keep-runs K holds; give --keep-runs too") != std::string::npos);
  const auto fourth = test::run_program(script, "out4 " + bin + " --only 'fig04 fig08 fig15' --quick --seeds 95 --keep-runs " + kept + " --kept-only",
                                        "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(fourth.output);
  REQUIRE(fourth.status == 0);
  CHECK(fourth.output.find("fig04: 1 of its 1 runs are not kept; not reported (--kept-only)") != std::string::npos);
  CHECK(fourth.output.find(": done (") == std::string::npos);
  CHECK_FALSE(fs::exists(d / "out4" / "fig04" / "report.json"));
  CHECK(fs::exists(d / "out4" / "fig08" / "report.json"));
  CHECK(fs::exists(d / "out4" / "fig15" / "report.json"));
  CHECK(fs::exists(d / "out4" / "index.html"));
  size_t kept_after = 0;
  for (const auto& item : fs::directory_iterator(kept))
    for (auto& e : fs::directory_iterator(item.path())) kept_after += e.is_directory() ? 1 : 0;
  CHECK(kept_after == 2);
}

// --keep-runs and a machine lost mid-run: an unfinished run's checkpoint is kept beside the
// finished runs (K/NAME/.inflight/RUN), and the script on another OUT_DIR (another machine)
// resumes it there, to the same output as a run never stopped (one thread, this machine).
TEST_CASE("reproduce_all.sh --keep-runs keeps an unfinished run's checkpoint, and a later run of the script resumes it",
          "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_inflight");
  const std::string src = PPSYNTH_SOURCE_DIR;
  const std::string script = src + "/scripts/reproduce_all.sh";
  const std::string bin = test::ppsynth_binary();
  const fs::path kept = d / "kept";
  // More iterations than --quick's, so the task is stopped mid-stage, not after its end.
  const std::string sets = " --set method.quick.max_iterations=12";

  // The run a lost machine leaves: fig04's one row planned, its task stopped after its third iteration.
  const fs::path sweep = d / "lost" / "sweeps" / "fig04";
  auto plan = test::run_ppsynth("reproduce fig04 --quick --seeds 95 --plan-only" + sets + " --sweep " + sweep.string() + " -o " +
                                (d / "lost" / "fig04").string());
  INFO(plan.output);
  REQUIRE(plan.status == 0);
  const SweepManifest m = load_sweep(sweep.string());
  REQUIRE(m.rows.size() == 1);
  const std::string id = m.rows[0].id;
  {
    test::Child task("sweep task " + sweep.string() + " --row " + id, "PPSYNTH_THREADS=1");
    const std::regex third(" it +3/");
    REQUIRE(task.wait_for([&](const std::string& l) { return std::regex_search(l, third); }));
    task.signal(SIGTERM);
    REQUIRE(task.finish() == 143);
  }
  REQUIRE(fs::exists(sweep / "runs" / id / "checkpoint.bin"));

  // What the script's keeper does each minute: the finished runs kept, the unfinished one's checkpoint beside them.
  const std::string keep = "set -euo pipefail; source " + src + "/scripts/lib/kept_runs.sh; keep_runs " + (sweep / "runs").string() + " " +
                           (kept / "fig04").string();
  auto kept_now = test::run_program("/bin/bash", "-c '" + keep + "'");
  INFO(kept_now.output);
  REQUIRE(kept_now.status == 0);
  const fs::path held = kept / "fig04" / ".inflight" / id;
  for (const char* f : {".ppsynth-run", "config.json", "checkpoint.bin", "exemplar.txt"}) CHECK(fs::exists(held / f));
  CHECK_FALSE(fs::exists(kept / "fig04" / id));  // not finished: not a kept run
  CHECK(test::run_program("/bin/bash", "-c '" + keep + "'").status == 0);  // again: the same checkpoint, nothing rewritten
  CHECK_FALSE(fs::exists(kept / "fig04" / ".inflight" / ("." + id + ".partial")));

  // Another machine: a new OUT_DIR, the same K. The row resumes from the kept checkpoint, is
  // kept finished, and its checkpoint copy goes.
  const auto later = test::run_program(script, "out " + bin + " --only fig04 --quick --seeds 95" + sets + " --keep-runs " + kept.string(),
                                       "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(later.output);
  REQUIRE(later.status == 0);
  CHECK(later.output.find("resuming " + id + " from the checkpoint kept in " + held.string()) != std::string::npos);
  CHECK(fs::exists(kept / "fig04" / id / "output.txt"));
  CHECK_FALSE(fs::exists(held));

  // The same row never stopped: the same output, byte for byte.
  const auto whole = test::run_program(script, "whole " + bin + " --only fig04 --quick --seeds 95" + sets + " --keep-runs " +
                                                   (d / "kept_whole").string(),
                                       "cd " + d.string() + " && PPSYNTH_THREADS=1");
  INFO(whole.output);
  REQUIRE(whole.status == 0);
  CHECK(whole.output.find("resuming") == std::string::npos);
  CHECK(read_file_text((d / "kept_whole" / "fig04" / id / "output.txt").string()) == read_file_text((kept / "fig04" / id / "output.txt").string()));
}
