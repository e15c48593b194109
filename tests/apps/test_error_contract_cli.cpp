// One error contract, through the real binary: usage and input errors exit 2, an internal
// error 3, a stop by signal 130 / 143; `--help` says so; every message is a line naming the
// option, file or key, without a C++ backtrace or an exception's internal name.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/formats/text_table.hpp"

#include <nlohmann/json.hpp>
#include "tests/support/run_command.hpp"
#include "tests/support/sanitizers.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

// No message may show how ppsynth is built inside.
void check_plain(const std::string& output) {
  INFO(output);
  CHECK_THAT(output, !Catch::Contains("json.exception") && !Catch::Contains("Exception raised from") &&
                         !Catch::Contains("frame #") && !Catch::Contains("c10::") && !Catch::Contains("std::") &&
                         !Catch::Contains("internal error"));
}

}  // namespace

TEST_CASE("the command line parser's errors exit 2 with the option named", "[apps][errors]") {
  struct Case {
    std::string args, says;
  };
  for (const Case& c : {Case{"synthesize --no-such-option", "--no-such-option"}, Case{"eval", "required"},
                        Case{"sweep run x --local -j 0", "-j"}, Case{"sweep run x --local -j many", "-j"},
                        Case{"synthesize --size 0 1 --quick", "--size"}, Case{"synthesize --size 1 --quick", "--size"},
                        Case{"synthesize --points 0", "--points"}, Case{"sweep run x --slurm --cpus=-5 --dry-run", "--cpus"},
                        Case{"synthesize --seed -5", "--seed"}, Case{"synthesize --seed 99999999999999999999", "--seed"},
                        Case{"synthesize --seed 9223372036854775808", "--seed"}, Case{"synthesize --seed 1e3", "--seed"},
                        Case{"", "subcommand"}}) {
    const auto r = run_ppsynth(c.args);
    INFO(c.args << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(c.says));
    // -j 0 printed CLI11's range of a double: 2.2250738585072014e-308 to 1.79...e+308.
    CHECK_THAT(r.output, !Catch::Contains("e-308") && !Catch::Contains("e+308"));
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') <= 2);
  }
}

TEST_CASE("an unknown command is named as unknown, exit 2", "[apps][errors]") {
  const auto r = run_ppsynth("nosuchcmd");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("unknown command 'nosuchcmd'") && Catch::Contains("synthesize"));
  CHECK_THAT(r.output, !Catch::Contains("A subcommand is required"));
  CHECK(run_ppsynth("-v nosuchcmd").status == 2);
}

TEST_CASE("--help documents the exit status; --help and --version exit 0", "[apps][errors]") {
  const auto help = run_ppsynth("--help");
  CHECK(help.status == 0);
  CHECK_THAT(help.output, Catch::Contains("Exit status") && Catch::Contains("2 a usage or input error") &&
                              Catch::Contains("130 / 143") && Catch::Contains("3 an internal error"));
  CHECK(run_ppsynth("synthesize --help").status == 0);
  CHECK(run_ppsynth("--version").status == 0);
}

TEST_CASE("a seed is a whole number in [0, 2^63), taken as given", "[apps][errors][synthesize]") {
  auto d = ppsynth::test::scratch_dir("errors_seed");
  // The defect: --seed -5 was ignored (seed 95 ran) and 99999999999999999999 clamped.
  for (const std::string seed : {"-5", "99999999999999999999", "18446744073709551615", "9223372036854775808", "5.5", "0x5"}) {
    const auto r = run_ppsynth("synthesize " + kLines + " --quick -q --seed " + seed + " -o " + (d / "x").string());
    INFO(seed << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_FALSE(fs::exists(d / "x"));
  }
  // The largest seed runs, and is recorded as given.
  const auto r = run_ppsynth("synthesize " + kLines + " --quick -q --set method.quick.max_iterations=1 --seed 9223372036854775807 -o " +
                             (d / "big").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(ppsynth::read_file_text((d / "big" / "run.json").string()), Catch::Contains("\"seed\": 9223372036854775807"));
  // In a config too.
  std::ofstream(d / "c.json") << "{\"parent\": \"" << kLines << "\", \"seed\": 9223372036854775808}";
  const auto c = run_ppsynth("synthesize " + (d / "c.json").string() + " --quick -q -o " + (d / "y").string());
  CHECK(c.status == 2);
  CHECK_THAT(c.output, Catch::Contains("'seed'"));
}

TEST_CASE("malformed JSON in a run directory is an input error naming the file", "[apps][errors]") {
  auto d = ppsynth::test::scratch_dir("errors_run_json");
  const std::string run = (d / "run").string();
  REQUIRE(run_ppsynth("synthesize " + kLines + " --quick -q --set method.quick.max_iterations=1 -o " + run).status == 0);
  const std::string good = ppsynth::read_file_text(run + "/run.json");
  for (const std::string file : {"run.json", "config.json", "metrics.json"}) {
    const std::string path = run + "/" + file, before = ppsynth::read_file_text(path);
    for (const std::string text : {std::string("{\"seed\": "), std::string("[1, 2]"),
                                   std::string("{\"seed\": \"95\", \"total_seconds\": \"x\", \"method\": 3, \"all\": 3}")}) {
      std::ofstream(path) << text;
      const auto r = run_ppsynth("gather " + run);
      INFO(file << " = " << text << ": " << r.output);
      CHECK(r.status == 2);
      CHECK_THAT(r.output, Catch::Contains(path));
      check_plain(r.output);
    }
    std::ofstream(path) << before;
  }
  CHECK(run_ppsynth("gather " + run).status == 0);
  // The defect: a band list longer than its values made gather read past the values' end
  // (valgrind: invalid read) and tabulate heap garbage as a metric.
  auto metrics = nlohmann::json::parse(ppsynth::read_file_text(run + "/metrics.json"));
  metrics["output"]["border_profile"]["band"] = std::vector<double>(1065, 0.01);
  std::ofstream(run + "/metrics.json") << metrics.dump();
  const auto past = run_ppsynth("gather " + run);
  INFO(past.output);
  CHECK(past.status == 2);
  CHECK_THAT(past.output, Catch::Contains(run + "/metrics.json") && Catch::Contains("output.border_profile"));
}

TEST_CASE("number lists near 2^64 are refused at once", "[apps][errors]") {
  auto d = ppsynth::test::scratch_dir("errors_number_lists");
  // The defect: these saturated and looped forever, allocating until memory was gone (the
  // limits keep an older binary from taking the machine with it). Under AddressSanitizer only
  // the time limit: a virtual memory limit keeps ASan from reserving its shadow memory at all.
  const std::string limits = ppsynth::test::kAddressSanitizer ? "timeout 60" : "ulimit -v 3000000; timeout 60";
  for (const std::string stages : {"18446744073709551615", "18446744073709551614-18446744073709551615", "99999999999999999999"}) {
    const auto r = run_ppsynth("gather " + d.string() + " --stage " + stages, limits);
    INFO(stages << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("--stage[0]"));
  }
  std::ofstream(d / "spec.json") << "{\"name\": \"big\", \"runs\": [\"" << kLines << "\"], \"seeds\": \"18446744073709551615\"}";
  const auto plan = run_ppsynth("sweep plan " + (d / "spec.json").string() + " -o " + (d / "sw").string(), limits);
  CHECK(plan.status == 2);
  CHECK_THAT(plan.output, Catch::Contains("seeds[0]"));
}
