// The Gabor method's typed options (optim/gabor/settings/gabor_options.hpp, grid_options.hpp,
// window_options.hpp, quick_options.hpp): each reads its keys, names the key on a bad value,
// and is what the method's defaults and ranges list.
#include <catch2/catch.hpp>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "optim/gabor/settings/gabor_options.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/settings/grid_options.hpp"
#include "optim/gabor/settings/quick_options.hpp"
#include "optim/gabor/settings/window_options.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

TEST_CASE("method.grid: res 0 from the exemplar's spacing, coarser grids at coarser sigmas", "[optim][options]") {
  json block = GridOptions::defaults();
  // res 0: clamp(round(9 / d), min_res, max_res)
  CHECK(GridOptions::resolve(block, 9.0 / 200).res == 200);
  CHECK(GridOptions::resolve(block, 9.0 / 1000).res == 256);
  CHECK(GridOptions::resolve(block, 9.0 / 10).res == 128);
  block["res"] = 64;
  const GridOptions fixed = GridOptions::resolve(block, 0.01);
  CHECK(fixed.res == 64);
  CHECK_FALSE(fixed.per_sigma);
  CHECK(fixed.per_stage({0.4, 0.2, 0.1}, 64) == std::vector<int>{64, 64, 64});
  block["per_sigma"] = true;
  const GridOptions coarse = GridOptions::resolve(block, 0.01);
  // The finest sigma keeps the grid; a sigma twice as coarse takes half the positions, at least 8.
  CHECK(coarse.per_stage({0.4, 0.2, 0.1}, 64) == std::vector<int>{16, 32, 64});
  CHECK(coarse.per_stage({10.0, 0.1}, 64) == std::vector<int>{8, 64});
  block["per_sigma"] = "yes";
  CHECK_THROWS_WITH(GridOptions::resolve(block, 0.01), Contains("method.grid.per_sigma"));
}

TEST_CASE("method.window: an auto or fixed margin, the statistics, each error naming its key", "[optim][options]") {
  json block = WindowOptions::defaults();
  WindowOptions w = WindowOptions::resolve(block);
  CHECK(w.pixels == 640);  // a grid of at most 640 x 640 positions, in any aspect
  CHECK_FALSE(w.margin.has_value());
  CHECK_FALSE(w.statistics_in_output);
  // auto: 3 sigma plus the receptive field, where that reaches farthest.
  CHECK(w.auto_margin({0.2, 0.1}, {64, 128}) == Approx(std::max(0.6 + 16.0 / 64, 0.3 + 16.0 / 128)));
  block["margin"] = "auto";
  CHECK_FALSE(WindowOptions::resolve(block).margin.has_value());
  block["margin"] = 0.25;
  block["statistics"] = "output";
  w = WindowOptions::resolve(block);
  REQUIRE(w.margin.has_value());
  CHECK(*w.margin == 0.25);
  CHECK(w.statistics_in_output);
  block["margin"] = -1;
  CHECK_THROWS_WITH(WindowOptions::resolve(block), Contains("method.window.margin"));
  block["margin"] = nullptr;
  block["statistics"] = "tiles";
  CHECK_THROWS_WITH(WindowOptions::resolve(block), Contains("method.window.statistics") && Contains("\"tiles\""));
}

TEST_CASE("method.quick: its caps, and the method lists every block's defaults and ranges from its struct", "[optim][options]") {
  const QuickOptions q = QuickOptions::resolve(QuickOptions::defaults());
  CHECK(q.res == 24);
  CHECK(q.channels == 8);
  CHECK(q.max_iterations == 4);
  CHECK(q.num_sigmas == 2);
  const json defaults = gabor_defaults(), bounds = gabor_bounds();
  CHECK(defaults["grid"] == GridOptions::defaults());
  CHECK(defaults["window"] == WindowOptions::defaults());
  CHECK(defaults["quick"] == QuickOptions::defaults());
  CHECK(bounds["grid"] == GridOptions::bounds());
  CHECK(bounds["window"] == WindowOptions::bounds());
  CHECK(bounds["quick"] == QuickOptions::bounds());
}

TEST_CASE("the method's own keys: the published settings by default, a bad value named", "[optim][options]") {
  json p = GaborOptions::defaults();
  const GaborOptions o = GaborOptions::resolve(p);
  CHECK(o.c1 == 1.0);
  CHECK(o.c2 == 2.6);
  CHECK(o.num_sigmas == 4);
  CHECK(o.max_iterations == 500);
  CHECK(o.k_per_stage);
  CHECK(o.jitter);
  CHECK(o.class_order.empty());
  CHECK(o.measure == GaborOptions::Measure::grid);
  p["measure"] = "rolled";
  p["class_order"] = {1, 0};
  const GaborOptions r = GaborOptions::resolve(p);
  CHECK(r.measure == GaborOptions::Measure::rolled);
  CHECK(std::string(measure_name(r.measure)) == "rolled");
  CHECK(r.class_order == std::vector<int>{1, 0});
  for (const auto& [key, bad] : {std::pair<const char*, json>{"measure", "edges"}, {"class_order", json{0, -1}},
                                 {"class_order", json{0.5}}, {"jitter", 1}, {"k", 0}}) {
    json q = GaborOptions::defaults();
    q[key] = bad;
    INFO(key << " = " << bad.dump());
    CHECK_THROWS_WITH(GaborOptions::resolve(q), Contains(std::string("method.") + key));
  }
  // (Named: a range-for over a temporary's items() would outlive the temporary.)
  const json defaults = gabor_defaults(), bounds = gabor_bounds();
  const json own_defaults = GaborOptions::defaults(), own_bounds = GaborOptions::bounds();
  for (const auto& [key, value] : own_defaults.items()) CHECK(defaults.at(key) == value);
  for (const auto& [key, value] : own_bounds.items()) CHECK(bounds.at(key) == value);
}
