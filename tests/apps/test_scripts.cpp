// The helper scripts under scripts/ that users run on their own results: each is driven here
// with --quick syntheses so a broken flag, path or table shows up in the suite.
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

struct Result {
  int status = -1;
  std::string out;  // stdout only; stderr goes to /dev/null
};

// Runs a script from the source tree with the test build's binary.
Result script(const std::string& args) {
  const std::string cmd = "PPSYNTH_BIN=" + std::string(PPSYNTH_BINARY) + " " + PPSYNTH_SOURCE_DIR + "/scripts/" +
                          args + " 2>/dev/null";
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::array<char, 4096> buf{};
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), p)) > 0;) r.out.append(buf.data(), n);
  r.status = WEXITSTATUS(pclose(p));
  return r;
}

// The table row of `first` ("1", "median", ...), or "" when there is none.
std::string row(const std::string& table, const std::string& first) {
  std::smatch m;
  return std::regex_search(table, m, std::regex("(^|\n)(" + first + " [^\n]*)")) ? m[2].str() : "";
}

}  // namespace

TEST_CASE("seed_sweep.sh runs a config per seed and tabulates it against a reference", "[apps][scripts]") {
  const auto d = ppsynth::test::scratch_dir("scripts_sweep");
  const std::string lines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
  const std::string runs = " --runs " + d.string() + " ";

  auto r = script("seed_sweep.sh" + runs + lines + " 1-2 -- --quick -q");
  REQUIRE(r.status == 0);
  CHECK(fs::exists(d / "lines_s1" / "output.txt"));
  CHECK(fs::exists(d / "lines_s2" / "output.txt"));
  CHECK(fs::exists(d / "lines_s2.log"));
  CHECK(std::regex_match(row(r.out, "1"), std::regex("1( +[0-9.eE+-]+)+")));  // numbers only
  CHECK_FALSE(row(r.out, "2").empty());
  CHECK_FALSE(row(r.out, "median").empty());
  CHECK(r.out.find("reference") == std::string::npos);

  // Seed 1's own output as the reference: seed 1 is within 1.25 x of itself, not within 0.5 x
  // (its ratio is 1). --reuse keeps the runs: the deleted log is not written again.
  const std::string ref = " --reference " + (d / "lines_s1" / "output.txt").string() + " ";
  fs::remove(d / "lines_s2.log");
  r = script("seed_sweep.sh --reuse" + runs + ref + lines + " 1,2");
  REQUIRE(r.status == 0);
  CHECK_FALSE(fs::exists(d / "lines_s2.log"));
  CHECK_FALSE(row(r.out, "reference").empty());
  CHECK(row(r.out, "1").size() > 4);
  CHECK(row(r.out, "1").substr(row(r.out, "1").size() - 4) == " yes");
  r = script("seed_sweep.sh --reuse --bound 0.5" + runs + ref + lines + " 1");
  REQUIRE(r.status == 0);
  CHECK(row(r.out, "1").substr(row(r.out, "1").size() - 3) == " no");
  CHECK(r.out.find("0 of 1") != std::string::npos);
}

TEST_CASE("seed_sweep.sh refuses bad arguments before running anything", "[apps][scripts]") {
  const auto d = ppsynth::test::scratch_dir("scripts_sweep_bad");
  const std::string lines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
  const std::string runs = " --runs " + d.string() + " ";
  CHECK(script("seed_sweep.sh" + runs + lines + " 3-1").status == 2);
  CHECK(script("seed_sweep.sh" + runs + lines + " 1-x").status == 2);
  CHECK(script("seed_sweep.sh --bound abc" + runs + lines + " 1").status == 2);
  CHECK(script("seed_sweep.sh --frobnicate" + runs + lines + " 1").status == 2);
  CHECK(script("seed_sweep.sh" + runs + (d / "missing.json").string() + " 1").status == 1);
  CHECK(script("seed_sweep.sh --reference " + (d / "missing.txt").string() + runs + lines + " 1").status == 1);
  CHECK(fs::is_empty(d));  // nothing was run
}
