// GaborStats (optim/gabor/engine/gabor_stats.hpp): run.json's method_stats of the "gabor"
// method as a typed struct, written and read back the same, a wrong-typed key refused by its
// path, and a finished run's record read into it.
#include <catch2/catch.hpp>

#include <ATen/Parallel.h>

#include <stdexcept>

#include "optim/gabor/engine/gabor_stats.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_store.hpp"
#include "optim/run/run_synthesis.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;
using json = nlohmann::json;

namespace {

GaborStats rectangle_stats() {
  GaborStats s;
  s.grid_res = 24;
  s.output_grid_res = 44;
  s.output_grid_rows = 33;
  s.grid_res_per_sigma = {12, 24};
  s.output_grid_res_per_sigma = {22, 44};
  s.output_grid_rows_per_sigma = {17, 33};
  s.k = 30;
  s.sigmas = {0.08, 0.03};
  s.mean_nn_distance = 0.08;
  s.map_terms = {{"class_own", 1.0}};
  s.runtime = {"cuda:0", "tf32", false, json{{"tf32", "on"}}, std::string("cpu_kernel")};
  s.rectangle = GaborRectangle{{"1.5 x 1 exemplar units, clean border", {-0.2, -0.2, 1.7, 1.2}, 171}, 5,
                               {2, 1, 1.0, 1.4, 0.9, 44, 33}};
  s.phase_seconds = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  s.resolved = {json{{"type", "gabor"}}, json{{"type", "random"}}, json::array({json{{"type", "gram"}}})};
  s.kinds = {{"border_relax_terms", {{"separation", 1.0}}}};
  return s;
}

}  // namespace

TEST_CASE("the gabor method's stats are one object in run.json, and read back the same", "[optim][method_stats]") {
  const GaborStats s = rectangle_stats();
  const json j = to_json(s);
  // The keys run.json has shown: the kinds' beside the method's, the rectangle's flat.
  CHECK(j["windows"] == json{{"nx", 2}, {"ny", 1}, {"width", 1.0}, {"height", 1.4}, {"margin", 0.9}, {"grid", {44, 33}}});
  CHECK(j["canvas"] == json{-0.2, -0.2, 1.7, 1.2});
  CHECK(j["border_relax_terms"] == json{{"separation", 1.0}});
  CHECK(j["runtime"]["choices"] == json{{"tf32", "on"}});
  CHECK(j["phase_seconds"]["optimizer_step"] == 0.6);
  const GaborStats back = gabor_stats_from_json(j);
  CHECK(back.grid_res == 24);
  CHECK(back.output_grid_rows_per_sigma == s.output_grid_rows_per_sigma);
  CHECK(back.sigmas == s.sigmas);
  CHECK(back.map_terms == s.map_terms);
  CHECK(back.runtime.gabor_maps == s.runtime.gabor_maps);
  REQUIRE(back.rectangle);
  CHECK(back.rectangle->shape.canvas_points == 171);
  CHECK(back.rectangle->frozen_pad_points == 5);
  CHECK(back.rectangle->windows.grid_rows == 33);
  CHECK(back.phase_seconds.maps_forward == 0.2);
  CHECK(back.kinds == s.kinds);
  CHECK(to_json(back).dump() == j.dump());

  // The unit torus: no rectangle, no choices or maps path, no kinds.
  GaborStats torus = s;
  torus.rectangle.reset();
  torus.runtime = {"cpu", "float32", true, nullptr, std::nullopt};
  torus.kinds = json::object();
  const json t = to_json(torus);
  for (const char* k : {"output", "canvas", "canvas_points", "frozen_pad_points", "windows", "border_relax_terms"})
    CHECK_FALSE(t.contains(k));
  CHECK(t["runtime"] == json{{"device", "cpu"}, {"precision", "float32"}, {"deterministic", true}});
  const GaborStats tb = gabor_stats_from_json(t);
  CHECK_FALSE(tb.rectangle);
  CHECK(tb.runtime.choices.is_null());
  CHECK(to_json(tb).dump() == t.dump());
}

TEST_CASE("a wrong-typed or missing key of the gabor stats is refused by its path", "[optim][method_stats]") {
  const json good = to_json(rectangle_stats());
  struct Bad {
    json::json_pointer at;
    json value;
    const char* named;
  };
  for (const Bad& b : {Bad{json::json_pointer("/grid_res"), 2.5, "'grid_res' is not an integer"},
                       Bad{json::json_pointer("/sigmas/1"), "x", "'sigmas[1]' is not a finite number"},
                       Bad{json::json_pointer("/map_terms/class_own"), "heavy", "'map_terms.class_own' is not a finite number"},
                       Bad{json::json_pointer("/runtime/deterministic"), "yes", "'runtime.deterministic' is not true or false"},
                       Bad{json::json_pointer("/windows/nx"), 1.5, "'windows.nx' is not an integer"},
                       Bad{json::json_pointer("/canvas"), json{0, 0, 1}, "'canvas' is not 4 numbers {x0, y0, x1, y1}"},
                       Bad{json::json_pointer("/canvas_points"), -3, "'canvas_points' is not a count"},
                       Bad{json::json_pointer("/phase_seconds/backward"), nullptr, "'phase_seconds.backward' is not a finite number"},
                       Bad{json::json_pointer("/resolved/losses"), json{{"type", "gram"}}, "'resolved.losses' is not a list of objects"},
                       Bad{json::json_pointer("/runtime"), "cpu", "'runtime' is not an object"}}) {
    json j = good;
    j[b.at] = b.value;
    INFO(b.at.to_string());
    CHECK_THROWS_MATCHES(gabor_stats_from_json(j), std::invalid_argument, Catch::Matchers::Message(b.named));
  }
  for (const char* k : {"k", "phase_seconds", "frozen_pad_points"}) {
    json j = good;
    j.erase(k);
    CHECK_THROWS_WITH(gabor_stats_from_json(j), Contains(std::string("'") + k + "' is missing"));
  }
  json j = good;
  j["windows"]["depth"] = 3;  // a key of the windows' record no field reads
  CHECK_THROWS_WITH(gabor_stats_from_json(j), Contains("'windows.depth' is not a key"));
}

TEST_CASE("a finished gabor run's method_stats read back into GaborStats", "[optim][method_stats]") {
  REQUIRE(at::get_num_threads() == 1);
  const auto d = test::scratch_dir("gabor_stats_run");
  RunRequest req;
  req.quick = true;
  SECTION("the unit torus") {
    req.dir = (d / "torus").string();
    run_synthesis(resolve_run_config({{"exemplar", "shared:data/exemplars/gabor-paper/lines.txt"}, {"seed", 11}}, {}), req);
    const RunOutcome run = load_run(req.dir);
    const GaborStats s = gabor_stats_from_json(run.stats);
    CHECK(s.grid_res == 24);  // --quick caps method.grid's res at method.quick.res, 24
    CHECK(s.output_grid_res == 48);  // upscale 2
    CHECK(s.grid_res_per_sigma == std::vector<int>{24, 24});
    CHECK(s.sigmas.size() == 2);
    CHECK(s.runtime.device == "cpu");
    CHECK_FALSE(s.rectangle);
    CHECK(s.phase_seconds.backward > 0);
    // The default's border relax adds its terms of its own.
    CHECK(s.kinds.contains("border_relax_terms"));
    CHECK(to_json(s) == run.stats);
  }
  SECTION("a rectangle") {
    req.dir = (d / "rectangle").string();
    run_synthesis(resolve_run_config({{"exemplar", "shared:data/exemplars/gabor-paper/lines.txt"}, {"seed", 11}},
                                     {"output.size=[1.5, 1]"}),
                  req);
    const RunOutcome run = load_run(req.dir);
    const GaborStats s = gabor_stats_from_json(run.stats);
    CHECK(s.grid_res == 24);
    REQUIRE(s.rectangle);
    CHECK(s.rectangle->shape.output.find("clean border") != std::string::npos);
    CHECK(s.rectangle->windows.nx == 1);
    CHECK(s.rectangle->windows.grid_columns == s.output_grid_res);
    CHECK(s.rectangle->shape.canvas_points >= run.output.size());
    CHECK(to_json(s) == run.stats);
  }
}
