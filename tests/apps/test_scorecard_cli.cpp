// `ppsynth eval`'s scorecard (core/metrics/novelty.hpp, close_pairs.hpp): the tiled_copy
// method's output is flagged a copy, in the table and the JSON; an independent Poisson-disk
// pattern is not; --diversity flags two seeds of tiled_copy as translates of each other; bad
// options exit 2 naming the flag.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "core/formats/point_io.hpp"
#include "core/generators/poisson_disk.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using nlohmann::json;

namespace {

ppsynth::test::CommandResult ppsynth_cmd(const std::string& args) {
  return ppsynth::test::run_program(ppsynth::test::ppsynth_binary(), args, "PPSYNTH_THREADS=1");
}

const char* kQuick = " -q --no-verdict --no-second-order --no-curves";

}  // namespace

TEST_CASE("eval's scorecard flags tiled_copy's output as a copy and a new pattern as new", "[apps][novelty]") {
  const auto d = ppsynth::test::scratch_dir("scorecard_cli");
  const std::string ex = (d / "ex.txt").string(), fresh = (d / "fresh.txt").string();
  ppsynth::write_points(ex, ppsynth::poisson_disk_points(100, 5));
  ppsynth::write_points(fresh, ppsynth::poisson_disk_points(400, 6));
  for (const char* seed : {"1", "2"}) {
    const auto r = ppsynth_cmd(std::string("synthesize -q -e ") + ex + " -m tiled_copy --seed " + seed + " -o " +
                               (d / ("copy" + std::string(seed))).string());
    REQUIRE(r.status == 0);
  }
  const std::string copy = (d / "copy1" / "output.txt").string(), copy2 = (d / "copy2" / "output.txt").string();

  auto r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick + " --json");
  REQUIRE(r.status == 0);
  json j = json::parse(r.output);
  CHECK(j["scorecard"]["novelty"]["copy"] == true);
  CHECK(j["scorecard"]["novelty"]["share"].get<double>() == 1.0);
  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("novelty    1.000 of") && Catch::Contains("COPY"));

  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + fresh + kQuick + " --json --diversity " + copy);
  REQUIRE(r.status == 0);
  j = json::parse(r.output);
  CHECK(j["scorecard"]["novelty"]["copy"] == false);
  CHECK(j["scorecard"]["novelty"]["matched"] == 0);
  CHECK(j["scorecard"]["diversity"]["copy"] == false);

  // Two seeds of tiled_copy: the same pattern shifted.
  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick + " --diversity " + copy2);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("diversity") && Catch::Contains("the other output's"));
  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick + " --json --diversity " + copy2);
  CHECK(json::parse(r.output)["scorecard"]["diversity"]["copy"] == true);

  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick + " --novelty-k 0");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("--novelty-k"));
  r = ppsynth_cmd("eval --exemplar " + ex + " --output " + copy + kQuick + " --no-scorecard --diversity " + copy2);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("--diversity"));
}
