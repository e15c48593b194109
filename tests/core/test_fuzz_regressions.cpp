// Inputs found by the libFuzzer targets (tests/fuzz, scripts/fuzz.sh), one test case each:
// the input as the fuzzer found it (or its minimal form), and the correct outcome, an
// InputError naming the file or key, or a correct parse. Each names its target and finding.
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/json_format.hpp"
#include "core/formats/point_io.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;

// fuzz_json_points, fuzz_parse_points: a number beyond double made nlohmann::json throw
// out_of_range (error 406), not parse_error, and it escaped the reader uncaught.
TEST_CASE("fuzz: a JSON point number beyond double is an InputError", "[fuzz][formats]") {
  const std::string text = "{\"points\": [[1e400, 0.2, 0]]}";
  CHECK_THROWS_AS(parse_json_points(text, "overflow.json"), InputError);
  CHECK_THROWS_WITH(parse_points(text, "overflow.json"), Catch::Contains("overflow.json") &&
                                                             Catch::Contains("1e400"));
  CHECK_THROWS_AS(parse_points("{\"points\": [[0.5, 0.5, 0]], \"domain\": [0, 0, -1e999, 1]}", "d.json"),
                  InputError);
  // Large but finite numbers still parse (and are then judged by the reader).
  CHECK(parse_json_points("{\"points\": [[0.5, 0.25, 0]], \"domain\": [0, 0, 1e300, 1]}", "big.json").size() == 1);
}

// fuzz_config: the same overflow in a config file escaped load_config.
TEST_CASE("fuzz: a config number beyond double is an InputError", "[fuzz][config]") {
  const auto dir = test::scratch_dir("fuzz_config_overflow");
  const std::string path = (dir / "c.json").string();
  std::ofstream(path) << "{\"method\": {\"type\": \"pcf2017\", \"iterations\": \"many\", \"bins\": 1e999}}";
  CHECK_THROWS_WITH(load_config(path), Catch::Contains("c.json") && Catch::Contains("1e999"));
  CHECK_THROWS_AS(load_config(path), InputError);
}

// fuzz_config: "--set name=<bytes that are not UTF-8>" was stored as a string; writing the
// resolved config (json::dump, config.json of every run) then threw type_error 316.
TEST_CASE("fuzz: a --set assignment that is not UTF-8 is an InputError", "[fuzz][config]") {
  json config = {{"seed", 1}};
  CHECK_THROWS_AS(set_override(config, "name=\xff\xfe"), InputError);
  CHECK_THROWS_AS(set_override(config, "method.\xc3=1"), InputError);  // a truncated sequence in a key
  CHECK(config == json{{"seed", 1}});
  set_override(config, "name=caf\xc3\xa9");  // valid UTF-8 is kept and writes back
  CHECK(config["name"] == "caf\xc3\xa9");
  CHECK_NOTHROW(config.dump());
}

// fuzz_plain_text (round trip): the reader took "# x y scale dep#h" and named an attribute
// "dep#h", which the plain text writer refuses; the reader now refuses it, naming the line.
TEST_CASE("fuzz: a plain text column name with '#' is an InputError", "[fuzz][formats]") {
  const std::string text =
      "# domain 0 0 2 1 periodic\n# x y scale dep#h (free remark)\n0.1 0.2 0.3 0.4\n1.9 0.9 0. 50.6\n";
  CHECK_THROWS_WITH(parse_points(text, "hash.txt"), Catch::Contains("hash.txt:2") && Catch::Contains("dep#h"));
  // The same file with a plain name reads, and writes back.
  const std::string ok =
      "# domain 0 0 2 1 periodic\n# x y scale depth (free remark)\n0.1 0.2 0.3 0.4\n1.9 0.9 0. 50.6\n";
  const PointSet ps = parse_points(ok, "ok.txt");
  REQUIRE(ps.size() == 2);
  CHECK(ps.attribute_names() == std::vector<std::string>{"scale", "depth"});
  CHECK(parse_points(format_points(ps, Format::Plain), "back.txt").size() == 2);
}

// fuzz_config: a "parent" whose name is longer than the file system allows made
// std::filesystem::weakly_canonical throw filesystem_error (ENAMETOOLONG) out of load_config.
TEST_CASE("fuzz: a config parent name too long for the file system is an InputError", "[fuzz][config]") {
  const auto dir = test::scratch_dir("fuzz_config_long_parent");
  const std::string path = (dir / "c.json").string();
  std::ofstream(path) << "{\"parent\": \"tttttttttttttqqqq~" << std::string(400, 'q') << "\"}";
  CHECK_THROWS_AS(load_config(path), InputError);
  CHECK_THROWS_WITH(load_config(path), Catch::Contains("qqqq"));
}

// fuzz_point_synthesis (round trip, found in CI): uniform scaling of a 1e-18 by 1e308 extent
// gave a domain of width 0 (1e-18 / 1e308 rounds to 0); it validated, and its write did not
// read back ("all points share one x"). A short side below 2^-52 of the long side is refused.
TEST_CASE("fuzz: a Point-Synthesis extent too thin to scale uniformly is an InputError", "[fuzz][formats]") {
  const std::string text = "0e308 -03e18 1 0\n-1e-18 1e308 2 3\n";
  ReadOptions uniform;
  uniform.format = Format::PointSynthesis;
  uniform.scaling = AxisScaling::Uniform;
  CHECK_THROWS_AS(parse_points(text, "thin.txt", uniform), InputError);
  CHECK_THROWS_WITH(parse_points(text, "thin.txt", uniform),
                    Catch::Contains("thin.txt") && Catch::Contains("aspect ratio") && Catch::Contains("per-axis"));
  // Per-axis scaling maps each side onto [0, 1] and reads it.
  ReadOptions per_axis;
  per_axis.format = Format::PointSynthesis;
  const PointSet ps = parse_points(text, "thin.txt", per_axis);
  CHECK(ps.domain().x1 == 1.0);
  CHECK(ps[1].x == 0.0);
  // A wide but representable aspect (1e6) still scales uniformly.
  CHECK(parse_points("0 0 1\n1e6 1 1\n", "wide.txt", uniform).domain().y1 == 1e-6);
}
