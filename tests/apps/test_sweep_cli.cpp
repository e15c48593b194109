// Sweeps through the binary: plan, a task stopped by SIGTERM (interrupted, resumable), the
// local executor finishing every run with two tasks at once, each run byte for byte the run
// `ppsynth synthesize` makes with the same config and seed, a second execution that runs
// nothing, status, gather, and the SLURM script of --dry-run.
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <regex>

#include "core/formats/text_table.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/run_compare.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::run_ppsynth;

TEST_CASE("a sweep planned, interrupted, run by local tasks, followed and gathered", "[apps][sweep]") {
  const auto d = ppsynth::test::scratch_dir("sweep_cli");
  const std::string src = PPSYNTH_SOURCE_DIR;
  const std::string sets = "\"method.quick.max_iterations=9\", \"method.quick.res=16\"";
  std::ofstream(d / "spec.json") << "{\"name\": \"cli\", \"runs\": [\"" << src << "/configs/runs/lines.json\", \"" << src
                                 << "/configs/runs/poisson_n64c2_point.json\"], \"seeds\": \"1-2\", \"quick\": true, \"set\": ["
                                 << sets << "]}";
  const std::string dir = (d / "sw").string();
  auto plan = run_ppsynth("sweep plan " + (d / "spec.json").string() + " -o " + dir);
  INFO(plan.output);
  REQUIRE(plan.status == 0);
  CHECK_THAT(plan.output, Catch::Contains("4 runs planned"));
  const auto m = ppsynth::load_sweep(dir);
  REQUIRE(m.rows.size() == 4);

  // Row 0 stopped by SIGTERM mid-stage: exit 143, interrupted (its checkpoint kept). One thread,
  // as the local tasks below resume it with: results depend on the thread count in the last bits.
  ppsynth::test::Child task("sweep task " + dir + " --row " + m.rows[0].id, "PPSYNTH_THREADS=1");
  const std::regex third(" it +3/");
  REQUIRE(task.wait_for([&](const std::string& l) { return std::regex_search(l, third); }));
  task.signal(SIGTERM);
  CHECK(task.finish() == 143);
  auto status = run_ppsynth("sweep status " + dir);
  CHECK_THAT(status.output, Catch::Contains("0 done, 0 running, 1 interrupted, 0 failed, 3 pending"));
  // How far it got: the stage it stopped in (its run directory's marker) and its checkpoint.
  CHECK(std::regex_search(status.output, std::regex("interrupted .* seed 1  \\(stage 1/[0-9]+ \\(sigma 1/[0-9]+\\), checkpoint [0-9]+ s ago")));

  auto script = run_ppsynth("sweep run " + dir + " --slurm --dry-run --cpus 2 --time-minutes 30");
  CHECK(script.status == 0);
  CHECK_THAT(script.output, Catch::Contains("#SBATCH --array=0-3\n") && Catch::Contains("#SBATCH --cpus-per-task=2\n") &&
                                Catch::Contains("#SBATCH --time=30\n"));
  CHECK_FALSE(fs::exists(d / "sw" / "sweep.sbatch"));  // a dry run writes nothing

  auto run = run_ppsynth("sweep run " + dir + " --local -j 2 --threads 1");
  INFO(run.output);
  REQUIRE(run.status == 0);
  CHECK_THAT(run.output, Catch::Contains("4 done now, 0 failed"));
  // Each run's wall time and its CPU time (which runs sharing the cores do not inflate).
  CHECK(std::regex_search(run.output, std::regex(": done \\([0-9]+ s; CPU [0-9]+ s\\)")));
  status = run_ppsynth("sweep status " + dir);
  CHECK_THAT(status.output, Catch::Contains("4 done, 0 running, 0 interrupted, 0 failed, 0 pending"));
  CHECK(std::regex_search(status.output, std::regex("[0-9.]+ s \\(CPU [0-9.]+ s\\)")));
  CHECK_THAT(run_ppsynth("sweep run " + dir + " --local").output, Catch::Contains("0 done now, 0 failed, 0 interrupted, 4 done"));

  // Every run equals the run `synthesize` makes alone (one thread, as the tasks ran).
  for (const auto& row : m.rows) {
    const std::string ref = (d / ("ref_" + row.id)).string();
    auto r = run_ppsynth("synthesize " + row.source + " --seed " + std::to_string(row.seed) +
                             " --quick --set method.quick.max_iterations=9 --set method.quick.res=16 -o " + ref,
                         "PPSYNTH_THREADS=1");
    REQUIRE(r.status == 0);
    ppsynth::test::check_same_run(ref, fs::path(dir) / row.dir);
  }

  auto gather = run_ppsynth("gather " + dir + " -o " + (d / "g").string());
  INFO(gather.output);
  REQUIRE(gather.status == 0);
  CHECK_THAT(gather.output, Catch::Contains("lines") && Catch::Contains("poisson_n64c2_point") && Catch::Contains("class 1"));
  CHECK(fs::exists(d / "g" / "index.html"));
  CHECK(std::count(gather.output.begin(), gather.output.end(), '\n') > 10);
  CHECK(run_ppsynth("sweep status " + (d / "g").string()).status == 2);  // not a sweep
  // --stage: a range, before or after the directories; a bad list or a stage no run passed exits 2.
  auto staged = run_ppsynth("gather --stage 1-2 " + dir);
  INFO(staged.output);
  REQUIRE(staged.status == 0);
  CHECK_THAT(staged.output, Catch::Contains("\nlines @ stage 1\n") && Catch::Contains("\nlines @ stage 2\n"));
  auto bad_list = run_ppsynth("gather " + dir + " --stage 1-x");
  CHECK(bad_list.status == 2);
  CHECK_THAT(bad_list.output, Catch::Contains("--stage[0]") && Catch::Contains("expected a stage"));
  auto not_passed = run_ppsynth("gather " + dir + " --stage 999");
  CHECK(not_passed.status == 2);
  CHECK_THAT(not_passed.output, Catch::Contains("--stage 999: no gathered run has passed that stage"));

  // A reference output belongs to one exemplar: with runs of two, a plain file is refused, and
  // a named one is compared with that exemplar's runs only.
  const std::string published = "shared:data/reference/poisson_n64c2_point/output.txt";
  auto ambiguous = run_ppsynth("gather " + dir + " --reference " + published);
  CHECK(ambiguous.status == 2);
  CHECK_THAT(ambiguous.output, Catch::Contains("2 exemplars") && Catch::Contains("EXEMPLAR="));
  CHECK(run_ppsynth("gather " + dir + " --reference nosuch=" + published).status == 2);
  auto named = run_ppsynth("gather " + dir + " --reference poisson_n64c2_point=" + published);
  INFO(named.output);
  REQUIRE(named.status == 0);
  bool lines_row = false, poisson_row = false;
  std::istringstream rows(named.output);
  std::string group;  // each group's label is a line of its own above its rows
  for (std::string line; std::getline(rows, line);) {
    if (!line.empty() && line[0] != ' ') group = line;
    if (line.rfind("  all ", 0) != 0 || line.find(" pcf_mse ") == std::string::npos) continue;
    std::istringstream fields(line);
    std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
    if (group == "lines") {
      lines_row = true;
      CHECK(f.size() == 6);  // no reference, no ratio
    }
    if (group == "poisson_n64c2_point") {
      poisson_row = true;
      CHECK(f.size() == 8);
    }
  }
  CHECK(lines_row);
  CHECK(poisson_row);
}
