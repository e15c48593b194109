// Messages that lead somewhere, through the real binary: each case names the defect a review
// found that it guards against.
#include <catch2/catch.hpp>

#include <sched.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "core/generators/lattices.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::read_file_text;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
const std::string kPptbf = std::string(PPSYNTH_SOURCE_DIR) + "/configs/pptbf/fig2_base.json";
const std::string kOneIteration = " --quick -q --set method.quick.max_iterations=1";

// A 64-point exemplar and a u = 2 output (256 points on the unit square), plain text.
std::pair<std::string, std::string> exemplar_and_output(const fs::path& dir) {
  const std::string ex = (dir / "ex.txt").string(), out = (dir / "out.txt").string();
  ppsynth::write_points(ex, ppsynth::jittered_grid_points(64, 1));
  ppsynth::write_points(out, ppsynth::jittered_grid_points(256, 2));
  return {ex, out};
}

// One finished quick run, made once for the cases that need one.
const std::string& finished_run() {
  static const std::string run = [] {
    const std::string dir = (ppsynth::test::scratch_dir("messages_run") / "run").string();
    const auto r = run_ppsynth("synthesize " + kLines + kOneIteration + " -o " + dir);
    if (r.status != 0) FAIL("the quick run failed: " << r.output);
    return dir;
  }();
  return run;
}

int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

TEST_CASE("a flag and a --set of the same config key are refused, naming both", "[apps][messages]") {
  // The defect: `--set seed=5` silently beat `--seed 7`.
  const auto d = ppsynth::test::scratch_dir("messages_set_conflict");
  const std::string out = " -o " + (d / "x").string();
  struct Case {
    std::string args, flag, set;
  };
  for (const Case& c : {Case{"--seed 7 --set seed=5", "--seed 7", "seed=5"},
                        Case{"--set seed=5 --seed 7", "--seed 7", "seed=5"},
                        Case{"-e " + kLines + " --set exemplar=other.txt", "--exemplar", "exemplar=other.txt"},
                        Case{"--size 2 1 --set output.size=[1,1]", "--size", "output.size=[1,1]"},
                        Case{"--size 2 1 --set output={}", "--size", "output={}"},
                        Case{"--method gabor --set method.type=roveri2015", "--method gabor", "method.type=roveri2015"},
                        Case{"--device cpu --set runtime.device=cpu", "--device cpu", "runtime.device=cpu"}}) {
    const auto r = run_ppsynth("synthesize " + kLines + kOneIteration + " " + c.args + out);
    INFO(c.args << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(c.flag) && Catch::Contains(c.set) && Catch::Contains("give one"));
    CHECK_FALSE(fs::exists(d / "x"));
  }
  // Keys that do not overlap are fine: the flag's seed is the run's.
  const auto ok = run_ppsynth("synthesize " + kLines + kOneIteration + " --seed 7 --set method.k=16" + out);
  INFO(ok.output);
  REQUIRE(ok.status == 0);
  CHECK_THAT(read_file_text((d / "x" / "run.json").string()), Catch::Contains("\"seed\": 7"));
  // pptbf's --seed the same way.
  const auto p = run_ppsynth("pptbf " + kPptbf + " --res 8 --seed 3 --set seed=4 -o " + (d / "p.png").string());
  CHECK(p.status == 2);
  CHECK_THAT(p.output, Catch::Contains("--seed 3") && Catch::Contains("seed=4"));
  CHECK_FALSE(fs::exists(d / "p.png"));
}

TEST_CASE("seeds outside 0..2^63-1 are refused, naming the flag", "[apps][messages]") {
  // The defect: eval's --crop-seed and --verdict-seed and generate's --seed wrapped -1 and
  // 2^64 - 1 around and ran.
  const auto d = ppsynth::test::scratch_dir("messages_seeds");
  const auto [ex, out] = exemplar_and_output(d);
  const std::string eval = "eval --exemplar " + ex + " --output " + out + " --no-second-order --no-curves --json ";
  for (const std::string value : {"-1", "-5", "18446744073709551615", "9223372036854775808", "99999999999999999999", "1e3"}) {
    for (const std::string flag : {"--crop-seed", "--verdict-seed"}) {
      const auto r = run_ppsynth(eval + "--protocol crops --crops 2 --no-verdict " + flag + " " + value);
      INFO(flag << " " << value << "\n" << r.output);
      CHECK(r.status == 2);
      CHECK_THAT(r.output, Catch::Contains(flag) && Catch::Contains("9223372036854775807"));
    }
    const auto g = run_ppsynth("generate uniform -n 10 --seed " + value + " -o " + (d / "g.txt").string());
    INFO("generate --seed " << value << "\n" << g.output);
    CHECK(g.status == 2);
    CHECK_THAT(g.output, Catch::Contains("--seed"));
    CHECK_FALSE(fs::exists(d / "g.txt"));
  }
  // The largest is taken as given.
  const auto big = run_ppsynth(eval + "--protocol crops --crops 2 --no-verdict --crop-seed 9223372036854775807");
  INFO(big.output);
  REQUIRE(big.status == 0);
  CHECK_THAT(big.output, Catch::Contains("\"seed\": 9223372036854775807"));
  CHECK(run_ppsynth("generate uniform -n 10 --seed 9223372036854775807 -o " + (d / "g.txt").string()).status == 0);
}

TEST_CASE("--resume names what is wrong with its path and creates nothing", "[apps][messages]") {
  const auto d = ppsynth::test::scratch_dir("messages_resume");
  std::ofstream(d / "file.txt") << "a file\n";
  // The defect: a regular file got "name a new directory".
  auto r = run_ppsynth("synthesize --resume " + (d / "file.txt").string());
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("file.txt") && Catch::Contains("not a run directory"));
  CHECK_THAT(r.output, !Catch::Contains("name a new directory"));
  CHECK(read_file_text((d / "file.txt").string()) == "a file\n");
  // The defect: a missing path had its parent directories created.
  r = run_ppsynth("synthesize --resume " + (d / "a" / "b" / "run").string());
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("no such directory"));
  CHECK_FALSE(fs::exists(d / "a"));
}

TEST_CASE("an empty path is refused, never taken as no path", "[apps][messages]") {
  // The defect: `gather -o ''` printed the table and wrote nothing, as without -o.
  const auto d = ppsynth::test::scratch_dir("messages_empty_path");
  const auto [ex, out] = exemplar_and_output(d);
  for (const std::string args : {"gather " + finished_run() + " -o ''",
                                 "eval --exemplar " + ex + " --output " + out + " --no-verdict --no-second-order --out ''",
                                 "spectrum " + ex + " -o " + (d / "s.png").string() + " --frequencies 8 --json ''",
                                 "synthesize " + kLines + kOneIteration + " -o ''"}) {
    const auto r = run_ppsynth(args, "cd " + d.string() + " &&");
    INFO(args << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("expected a path"));
  }
  CHECK_FALSE(fs::exists(d / "runs"));  // synthesize's default directory
  CHECK_FALSE(fs::exists(d / "s.png"));
}

TEST_CASE("gather --reference errors name the reference file", "[apps][messages]") {
  const auto d = ppsynth::test::scratch_dir("messages_reference");
  std::ofstream(d / "empty.txt") << "";
  std::ofstream(d / "one.txt") << "0.5 0.5\n";
  ppsynth::write_points((d / "strip.txt").string(), ppsynth::jittered_grid_points(16, 1, ppsynth::Domain{0, 0, 1, 0.05}));
  for (const std::string name : {"empty.txt", "one.txt", "strip.txt"}) {
    const std::string file = (d / name).string();
    const auto r = run_ppsynth("gather " + finished_run() + " --reference " + file);
    INFO(r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(file));
  }
}

TEST_CASE("sweep names an unknown subcommand and lists them", "[apps][messages]") {
  // The defect: `ppsynth sweep nosuch` said "A subcommand is required".
  auto r = run_ppsynth("sweep nosuch");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("'nosuch' is not a sweep subcommand") && Catch::Contains("plan, run, status, task"));
  CHECK_THAT(r.output, !Catch::Contains("A subcommand is required"));
  r = run_ppsynth("sweep");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("plan, run, status, task"));
  CHECK(run_ppsynth("sweep --help").status == 0);
  CHECK(run_ppsynth("-v sweep status --help").status == 0);
}

TEST_CASE("synthesis variables stop only what synthesizes", "[apps][messages]") {
  // The defect: PPSYNTH_GABOR_MAPS=garbage (a synthesis setting) made info and eval fail.
  const auto d = ppsynth::test::scratch_dir("messages_env");
  const auto [ex, out] = exemplar_and_output(d);
  for (const std::string env : {"PPSYNTH_GABOR_MAPS=garbage", "PPSYNTH_THREADS=garbage"}) {
    for (const std::string args : {"info " + ex, "eval --exemplar " + ex + " --output " + out + " --no-verdict --no-second-order"}) {
      const auto r = run_ppsynth(args, env);
      INFO(env << " " << args << "\n" << r.output);
      CHECK(r.status == 0);
    }
    // Where it is read, it is an error naming it, before anything is written.
    const auto r = run_ppsynth("synthesize " + kLines + kOneIteration + " -o " + (d / "x").string(), env);
    INFO(r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(env.substr(0, env.find('='))));
    CHECK_FALSE(fs::exists(d / "x"));
  }
}

TEST_CASE("more threads than cores are warned about, naming the variable, value and cores", "[apps][messages]") {
  // The defect: PPSYNTH_THREADS=1024 on 2 cores was taken silently (a 1.5 s run took 62 s).
  const int cores = usable_cores();
  if (cores >= 1024) {
    WARN("1024 usable cores or more: no thread count above them is accepted");
    return;
  }
  const auto d = ppsynth::test::scratch_dir("messages_threads");
  const std::string threads = std::to_string(cores + 1);
  const auto over = run_ppsynth("synthesize " + kLines + kOneIteration + " -o " + (d / "a").string(), "PPSYNTH_THREADS=" + threads);
  INFO(over.output);
  CHECK(over.status == 0);
  CHECK_THAT(over.output, Catch::Contains("PPSYNTH_THREADS=" + threads) && Catch::Contains(std::to_string(cores) + " core"));
  const auto fits = run_ppsynth("synthesize " + kLines + kOneIteration + " -o " + (d / "b").string(), "PPSYNTH_THREADS=1");
  CHECK(fits.status == 0);
  CHECK_THAT(fits.output, !Catch::Contains("PPSYNTH_THREADS"));
}

TEST_CASE("the protocol errors suggest only what works", "[apps][messages]") {
  const auto d = ppsynth::test::scratch_dir("messages_protocol");
  const std::string ex = (d / "ex.txt").string(), strip = (d / "strip.txt").string(), thin = (d / "thin.txt").string(),
                    small = (d / "small.txt").string();
  ppsynth::write_points(ex, ppsynth::jittered_grid_points(64, 1));
  // At the exemplar's density: a 4 x 1 strip, a 4 x 0.25 strip (narrower than the exemplar),
  // and a square with fewer points than the exemplar (smaller than it at its density).
  ppsynth::write_points(strip, ppsynth::jittered_grid_points(256, 2, ppsynth::Domain{0, 0, 4, 1}));
  ppsynth::write_points(thin, ppsynth::jittered_grid_points(64, 3, ppsynth::Domain{0, 0, 4, 0.25}));
  ppsynth::write_points(small, ppsynth::jittered_grid_points(16, 4));
  const std::string eval = "eval --exemplar " + ex + " --no-verdict --no-second-order --no-curves --json --output ";
  // The defect: quadrants of a strip compared squashed patches with the exemplar, exit 0.
  auto r = run_ppsynth(eval + strip + " --protocol quadrants");
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("2 x 0.5") && Catch::Contains("--protocol crops"));
  CHECK(run_ppsynth(eval + strip + " --protocol crops").status == 0);
  // The defect: the crops error suggested --protocol quadrants, which then ran squashed.
  r = run_ppsynth(eval + thin);
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, !Catch::Contains("--protocol quadrants") && Catch::Contains("quadrants do not fit it either"));
  r = run_ppsynth(eval + thin + " --protocol quadrants");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("crops do not fit it either"));
  // Where quadrants do fit, the crops error says so, and following it works.
  r = run_ppsynth(eval + small);
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("--protocol quadrants"));
  CHECK(run_ppsynth(eval + small + " --protocol quadrants").status == 0);
}
