// The baselines' stats (pcf2017_stats.hpp, roveri2015_stats.hpp): run.json's method_stats as
// typed structs, written and read back the same, a wrong-typed or unknown key refused by its
// path, and what a synthesis records read into them.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "optim/baselines/pcf2017/pcf2017_stats.hpp"
#include "optim/baselines/roveri2015/roveri2015_stats.hpp"
#include "optim/method/method.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::Message;
using json = nlohmann::json;

namespace {

pcf2017::Pcf2017Stats pcf_rectangle() {
  pcf2017::Pcf2017Stats s;
  s.points = 110;
  s.seconds = 0.2;
  s.rectangle = RectangleStats{"1.5 x 1 exemplar units, clean border", {-0.2, -0.2, 1.7, 1.2}, 171};
  s.classes = {{0, {-0.2, -0.2, 1.7, 1.2}, 171, pcf2017::Pcf2017Descent{30, 1.8, 0.006, false, 0.13}},
               {1, {-0.2, -0.2, 1.7, 2.4}, 2, std::nullopt}};
  return s;
}

roveri2015::Roveri2015Stats roveri_rectangle() {
  roveri2015::Roveri2015Stats s;
  s.d_nn = 0.08;
  s.sigma = 0.08;
  s.delta0 = 0.16;
  s.quadrature_points = 391;
  s.initial_points = 177;
  s.points = 114;
  s.target_points = 107.0;
  s.rectangle = RectangleStats{"1.5 x 1 exemplar units, clean border", {-0.2, -0.2, 1.7, 1.2}, 177};
  s.scales = {{0.16, 467.0, 344.3, 177, 0, 0, 10, 4.7}, {0.15, 213.6, 213.5, 176, 0, 1, 3, 3.0}};
  s.seconds = 7.7;
  return s;
}

void refused(const json& j, const char* message, bool pcf) {
  INFO(j.dump());
  if (pcf)
    CHECK_THROWS_MATCHES(pcf2017::pcf2017_stats_from_json(j), std::invalid_argument, Message(message));
  else
    CHECK_THROWS_MATCHES(roveri2015::roveri2015_stats_from_json(j), std::invalid_argument, Message(message));
}

}  // namespace

TEST_CASE("pcf2017's stats are one object in run.json, and read back the same", "[baselines][method_stats]") {
  const json r = to_json(pcf_rectangle());
  CHECK(r["classes"][0] == json{{"class", 0}, {"torus", {-0.2, -0.2, 1.7, 1.2}}, {"torus_points", 171}, {"iterations", 30},
                                {"energy_initial", 1.8}, {"energy_final", 0.006}, {"converged", false}, {"target_r_max", 0.13}});
  CHECK(r["classes"][1] == json{{"class", 1}, {"torus", {-0.2, -0.2, 1.7, 2.4}}, {"torus_points", 2}});
  const pcf2017::Pcf2017Stats rb = pcf2017::pcf2017_stats_from_json(r);
  REQUIRE(rb.rectangle);
  CHECK(rb.rectangle->canvas_points == 171);
  REQUIRE(rb.classes.size() == 2);
  CHECK(rb.classes[0].descent->energy_final == 0.006);
  CHECK_FALSE(rb.classes[1].descent);
  CHECK(to_json(rb).dump() == r.dump());

  pcf2017::Pcf2017Stats torus;
  torus.points = 80;
  torus.seconds = 0.05;
  torus.descent = pcf2017::Pcf2017Descent{30, 2.05, 0.027, true, 0.24};
  const json t = to_json(torus);
  CHECK(t == json{{"points", 80}, {"seconds", 0.05}, {"iterations", 30}, {"energy_initial", 2.05}, {"energy_final", 0.027},
                  {"converged", true}, {"target_r_max", 0.24}});
  const pcf2017::Pcf2017Stats tb = pcf2017::pcf2017_stats_from_json(t);
  CHECK_FALSE(tb.rectangle);
  CHECK(tb.descent->iterations == 30);
  CHECK(to_json(tb).dump() == t.dump());

  json bad = r;
  bad["classes"][0]["torus"][2] = "wide";
  refused(bad, "'classes[0].torus[2]' is not a finite number", true);
  bad = r;
  bad["classes"][0]["converged"] = 1;
  refused(bad, "'classes[0].converged' is not true or false", true);
  bad = t;
  bad["iterations"] = -0.5;
  refused(bad, "'iterations' is not an integer", true);
  bad = t;
  bad["points"] = "80";
  refused(bad, "'points' is not a count", true);
  bad = t;
  bad["energy"] = 1;  // a key no field reads
  refused(bad, "'energy' is not a key of these stats", true);
  bad = t;
  bad.erase("target_r_max");
  refused(bad, "'target_r_max' is missing", true);
}

TEST_CASE("roveri2015's stats are one object in run.json, and read back the same", "[baselines][method_stats]") {
  const json r = to_json(roveri_rectangle());
  CHECK(r["scales"][1] == json{{"delta", 0.15}, {"energy_start", 213.6}, {"energy_end", 213.5}, {"points", 176},
                               {"added", 0}, {"removed", 1}, {"merge_iterations", 3}, {"seconds", 3.0}});
  // A rectangle's target is the density's expectation: a number, 107.0 as run.json shows it.
  CHECK(r["target_points"].is_number_float());
  const roveri2015::Roveri2015Stats rb = roveri2015::roveri2015_stats_from_json(r);
  REQUIRE(rb.rectangle);
  REQUIRE(rb.scales.size() == 2);
  CHECK(rb.scales[1].removed == 1);
  CHECK(to_json(rb).dump() == r.dump());

  roveri2015::Roveri2015Stats torus = roveri_rectangle();
  torus.rectangle.reset();
  torus.target_points = 80;
  const json t = to_json(torus);
  CHECK(t["target_points"].is_number_unsigned());  // the paper's path: u^2 M, a count
  for (const char* k : {"output", "canvas", "canvas_points"}) CHECK_FALSE(t.contains(k));
  CHECK(to_json(roveri2015::roveri2015_stats_from_json(t)).dump() == t.dump());

  json bad = r;
  bad["scales"][1]["added"] = 0.5;
  refused(bad, "'scales[1].added' is not an integer", false);
  bad = r;
  bad["canvas"] = json{0, 0, 1};
  refused(bad, "'canvas' is not 4 numbers {x0, y0, x1, y1}", false);
  bad = t;
  bad["target_points"] = 80.5;  // the paper's path counts its points
  refused(bad, "'target_points' is not a count", false);
  bad = r;
  bad["scales"] = json{{"delta", 1}};
  refused(bad, "'scales' is not a list of objects", false);
  refused(json::array(), "the stats are not an object", false);
}

TEST_CASE("what pcf2017 and roveri2015 record of a synthesis reads back typed", "[baselines][method_stats]") {
  const PointSet ex = test::small_exemplar(1, false);
  for (const char* method : {"pcf2017", "roveri2015"}) {
    INFO(method);
    json stats;
    SynthesisContext ctx;
    ctx.output.upscale = 2;
    ctx.quick = true;
    ctx.seed = 3;
    ctx.stats = &stats;
    const PointSet out = MethodRegistry::instance().create(json{{"type", method}}, "method")->synthesize(ex, ctx);
    if (std::string(method) == "pcf2017") {
      const pcf2017::Pcf2017Stats s = pcf2017::pcf2017_stats_from_json(stats);
      CHECK(s.points == out.size());
      REQUIRE(s.descent);
      CHECK(s.descent->energy_final < s.descent->energy_initial);
      CHECK(to_json(s) == stats);
    } else {
      const roveri2015::Roveri2015Stats s = roveri2015::roveri2015_stats_from_json(stats);
      CHECK(s.points == out.size());
      CHECK(s.target_points == 4.0 * ex.size());
      CHECK_FALSE(s.scales.empty());
      CHECK(to_json(s) == stats);
    }
  }
}
