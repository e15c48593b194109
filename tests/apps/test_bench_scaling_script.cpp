// scripts/bench_scaling.sh, the scaling curve's benchmark: its table holds one row per output
// with its plan and per-iteration figures, a finished run is read again rather than rerun
// (an interrupted benchmark resumes), and a bad argument is refused before any run. The
// figures themselves are a benchmark's and no test asserts on them.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string field; std::getline(s, field, sep);) out.push_back(field);
  return out;
}

}  // namespace

TEST_CASE("bench_scaling.sh tabulates a tiny run and reads it again instead of rerunning", "[apps][script][bench_scaling]") {
  const auto d = test::scratch_dir("bench_scaling");
  const std::string root = PPSYNTH_SOURCE_DIR;
  const std::string env = "cd " + root + " && PPSYNTH_BIN=" + test::ppsynth_binary() + " PPSYNTH_THREADS=1";
  const std::string args = d.string() +
                           " --copies 1 --shapes square --presets fast --exemplars lines --iterations 2"
                           " -- --set method.grid.res=32 --set method.num_sigmas=2";
  auto r = test::run_program(env, "scripts/bench_scaling.sh " + args);
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("== lines, fast, square, 1 copies") != std::string::npos);
  const std::string tsv = read_all(d / "scaling.tsv");
  std::stringstream lines(tsv);
  std::string header, row, extra;
  std::getline(lines, header);
  std::getline(lines, row);
  CHECK_FALSE(std::getline(lines, extra));  // one output, one row
  const auto h = split(header, '\t'), v = split(row, '\t');
  REQUIRE(h.size() == v.size());
  std::map<std::string, std::string> cell;
  for (size_t i = 0; i < h.size(); ++i) cell[h[i]] = v[i];
  CHECK(cell["exemplar"] == "lines");
  CHECK(cell["copies"] == "1");
  CHECK(cell["stages"] == "2");  // one class, two sigmas, one grid
  CHECK(cell["windows"] == "1x1");
  CHECK(std::stod(cell["points"]) > 0);
  CHECK(std::stod(cell["every_s"]) > 0);
  CHECK(std::stod(cell["every_s"]) >= std::stod(cell["finest_s"]));
  CHECK(cell["ratio"] == "1.0");

  // Again: the finished run is read, not rerun.
  r = test::run_program(env, "scripts/bench_scaling.sh " + args);
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("== lines") == std::string::npos);
  CHECK(read_all(d / "scaling.tsv") == tsv);
}

TEST_CASE("bench_scaling.sh refuses a bad argument before any run", "[apps][script][bench_scaling]") {
  const auto d = test::scratch_dir("bench_scaling_bad");
  const std::string root = PPSYNTH_SOURCE_DIR;
  const std::string env = "cd " + root + " && PPSYNTH_BIN=" + test::ppsynth_binary();
  for (const auto& [flags, message] : std::vector<std::pair<std::string, std::string>>{
           {"--shapes round", "unknown shape 'round'"},
           {"--copies 'four'", "--copies holds 'four'"},
           {"--iterations 1", "--iterations must be a whole number of at least 2"},
           {"--exemplars nothere", "no config"},
           {"--speed 3", "unknown argument '--speed'"}}) {
    const auto r = test::run_program(env, "scripts/bench_scaling.sh " + (d / "out").string() + " " + flags);
    INFO(flags << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK(r.output.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(d / "out"));  // nothing written
  }
}
