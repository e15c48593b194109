// The Gabor method's typed options (optim/gabor/settings/gabor_options.hpp, grid_options.hpp,
// window_options.hpp, quick_options.hpp; the border relax's block,
// optim/gabor/stages/border_relax/border_relax_options.hpp): each declared once in a table
// (core/config/params.hpp), from which its defaults, ranges, reading and writing come; each
// names the key on a bad value; and the method reads every key its defaults declare, no other.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/output_shape.hpp"
#include "models/random_filter_net.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/settings/gabor_options.hpp"
#include "optim/gabor/stages/border_relax/border_relax_options.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/method/method.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

namespace {

// A table's block: its defaults are the members of a default-constructed struct, reading them
// gives that struct back, and writing it gives the defaults again.
template <class T>
void check_round_trip(const char* name) {
  INFO(name);
  const json d = T::params().defaults();
  CHECK(d == T::params().to_json(T{}));
  CHECK(T::params().to_json(T::params().read(d)) == d);
  CHECK(T::params().docs().size() == d.size());  // a doc line (or a block's lines) per key
}

// The border relax's block as its registration reads it (through its table), resolved.
BorderRelaxSettings relax(const json& block, const BorderRelaxContext& where) {
  return BorderRelaxSettings::resolve(BorderRelaxOptions::params().read(block), where);
}

}  // namespace

TEST_CASE("every Gabor options block: defaults from its struct, read and written back the same", "[optim][options]") {
  check_round_trip<GaborOptions>("method");
  check_round_trip<GridOptions>("method.grid");
  check_round_trip<WindowOptions>("method.window");
  check_round_trip<QuickOptions>("method.quick");
  check_round_trip<BorderRelaxOptions>("method.border_relax");
  check_round_trip<RandomFilterNetOptions>("method.feature_net (random)");
  CHECK(FeatureNetRegistry::instance().entry("random").defaults == RandomFilterNetOptions::params().defaults());
  CHECK(FeatureNetRegistry::instance().entry("random").bounds == RandomFilterNetOptions::params().bounds());
  // The method lists each block's defaults and ranges from its table, and each kind's block.
  const json defaults = gabor_defaults(), bounds = gabor_bounds();
  CHECK(defaults["grid"] == GridOptions::params().defaults());
  CHECK(defaults["window"] == WindowOptions::params().defaults());
  CHECK(defaults["quick"] == QuickOptions::params().defaults());
  CHECK(defaults["border_relax"] == BorderRelaxOptions::params().defaults());
  CHECK(bounds["grid"] == GridOptions::params().bounds());
  CHECK(bounds["window"] == WindowOptions::params().bounds());
  CHECK(bounds["quick"] == QuickOptions::params().bounds());
  CHECK(bounds["border_relax"] == BorderRelaxOptions::params().bounds());
  const json own_defaults = GaborOptions::params().defaults(), own_bounds = GaborOptions::params().bounds();
  for (const auto& [key, value] : own_defaults.items()) CHECK(defaults.at(key) == value);
  for (const auto& [key, value] : own_bounds.items()) CHECK(bounds.at(key) == value);
  // A default-constructed block is the published configuration.
  const GaborOptions o;
  CHECK(o.c1 == 1.0);
  CHECK(o.c2 == 2.6);
  CHECK(o.num_sigmas == 4);
  CHECK(o.max_iterations == 500);
  CHECK(o.grid.min_res == 128);
  CHECK(o.quick.res == 24);
  CHECK(o.window.pixels == 640);
}

TEST_CASE("the gabor method reads every key its defaults declare, and reads no other", "[optim][options][params]") {
  // resolve_gabor_settings reads the params through a ParamReader: a key read that its
  // defaults do not hold, or a key they hold that nothing reads, is a logic_error there.
  const PointSet ex = test::small_exemplar(2, false);
  const json p = test::method_params(json{{"type", "gabor"}});
  OutputShape square;
  CHECK_NOTHROW(resolve_gabor_settings(p, ex, square, false));
  CHECK_NOTHROW(resolve_gabor_settings(p, ex, square, true));
  // The method's defaults are its table's keys and each stage kind's block, nothing else.
  json declared = GaborOptions::params().defaults();
  declared["type"] = "gabor";  // the spec as the registry resolved it
  for (const std::string& kind : StageKindRegistry::instance().names()) declared[kind] = p.at(kind);
  CHECK(p == declared);
  // A key the user writes that the defaults do not declare is refused by the registry, naming it.
  CHECK_THROWS_WITH(test::method_params(json{{"type", "gabor"}, {"colour", 1}}), Contains("method.colour"));
  // Read but not declared: the params lack a key a table reads (as if its line had no default
  // in the method's defaults). Declared but not read: the params hold a key no table reads (as
  // if the method's defaults listed a key by hand). Both are programming errors, named.
  json missing = p;
  missing.erase("jitter");
  CHECK_THROWS_AS(resolve_gabor_settings(missing, ex, square, false), std::logic_error);
  CHECK_THROWS_WITH(resolve_gabor_settings(missing, ex, square, false), Contains("method.jitter"));
  json unread = p;
  unread["colour"] = 1;
  CHECK_THROWS_AS(resolve_gabor_settings(unread, ex, square, false), std::logic_error);
  CHECK_THROWS_WITH(resolve_gabor_settings(unread, ex, square, false), Contains("method.colour"));
  unread = p;
  unread["grid"]["colour"] = 1;  // inside a block too
  CHECK_THROWS_WITH(resolve_gabor_settings(unread, ex, square, false), Contains("method.grid.colour"));
}

TEST_CASE("the gabor method reads its params once, when it is created, naming a bad key", "[optim][options][params]") {
  // A value of the wrong kind that no range catches is refused by the registry's create, as
  // every other part's is, not first by the synthesis.
  const auto& methods = MethodRegistry::instance();
  CHECK_THROWS_WITH(methods.create(json{{"type", "gabor"}, {"measure", "edges"}}, "method"), Contains("method.measure"));
  CHECK_THROWS_WITH(methods.create(json{{"type", "gabor"}, {"grid", {{"per_sigma", "yes"}}}}, "method"),
                    Contains("method.grid.per_sigma"));
  // The read params: the table's keys typed, each kind's block as merged (the kind reads it
  // through its own table as the settings resolve: its factory needs them).
  const GaborParams g = read_gabor_params(test::method_params(json{{"type", "gabor"}, {"measure", "rolled"}}));
  CHECK(g.options.measure == GaborOptions::Measure::rolled);
  CHECK(g.stage_kinds.at("border_relax") == BorderRelaxOptions::params().defaults());
}

TEST_CASE("method.grid: res 0 from the exemplar's spacing, coarser grids at coarser sigmas", "[optim][options]") {
  json block = GridOptions::params().defaults();
  // res 0: clamp(round(9 / d), min_res, max_res)
  const GridOptions automatic = GridOptions::params().read(block);
  CHECK(automatic.resolved_res(9.0 / 200) == 200);
  CHECK(automatic.resolved_res(9.0 / 1000) == 256);
  CHECK(automatic.resolved_res(9.0 / 10) == 128);
  block["res"] = 64;
  const GridOptions fixed = GridOptions::params().read(block);
  CHECK(fixed.resolved_res(0.01) == 64);
  CHECK_FALSE(fixed.per_sigma);
  CHECK(fixed.per_stage({0.4, 0.2, 0.1}, 64) == std::vector<int>{64, 64, 64});
  block["per_sigma"] = true;
  const GridOptions coarse = GridOptions::params().read(block);
  // The finest sigma keeps the grid; a sigma twice as coarse takes half the positions, at least 8.
  CHECK(coarse.per_stage({0.4, 0.2, 0.1}, 64) == std::vector<int>{16, 32, 64});
  CHECK(coarse.per_stage({10.0, 0.1}, 64) == std::vector<int>{8, 64});
  block["per_sigma"] = "yes";
  CHECK_THROWS_WITH(GridOptions::params().read(block), Contains("method.grid.per_sigma"));
  block["per_sigma"] = false;
  block["res"] = 4;  // neither 0 nor in [8, 8192]
  CHECK_THROWS_WITH(GridOptions::params().read(block), Contains("method.grid.res"));
}

TEST_CASE("method.window: an auto or fixed margin, the statistics, each error naming its key", "[optim][options]") {
  json block = WindowOptions::params().defaults();
  WindowOptions w = WindowOptions::params().read(block);
  CHECK(w.pixels == 640);  // a grid of at most 640 x 640 positions, in any aspect
  CHECK_FALSE(w.margin.has_value());
  CHECK_FALSE(w.statistics_in_output);
  // auto: 3 sigma plus the receptive field, where that reaches farthest.
  CHECK(w.auto_margin({0.2, 0.1}, {64, 128}) == Approx(std::max(0.6 + 16.0 / 64, 0.3 + 16.0 / 128)));
  block["margin"] = "auto";
  CHECK_FALSE(WindowOptions::params().read(block).margin.has_value());
  block["margin"] = 0.25;
  block["statistics"] = "output";
  w = WindowOptions::params().read(block);
  REQUIRE(w.margin.has_value());
  CHECK(*w.margin == 0.25);
  CHECK(w.statistics_in_output);
  CHECK(WindowOptions::params().to_json(w) == block);
  block["margin"] = -1;
  CHECK_THROWS_WITH(WindowOptions::params().read(block), Contains("method.window.margin"));
  block["margin"] = "wide";
  CHECK_THROWS_WITH(WindowOptions::params().read(block), Contains("method.window.margin"));
  block["margin"] = nullptr;
  block["statistics"] = "tiles";
  CHECK_THROWS_WITH(WindowOptions::params().read(block), Contains("method.window.statistics") && Contains("\"tiles\""));
}

TEST_CASE("the method's own keys: the published settings by default, a bad value named", "[optim][options]") {
  json p = GaborOptions::params().defaults();
  const GaborOptions o = GaborOptions::params().read(p);
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
  const GaborOptions r = GaborOptions::params().read(p);
  CHECK(r.measure == GaborOptions::Measure::rolled);
  CHECK(std::string(measure_name(r.measure)) == "rolled");
  CHECK(r.class_order == std::vector<int>{1, 0});
  CHECK(GaborOptions::params().to_json(r) == p);
  // Each range is the declared bound, checked where the key is read (no second check).
  for (const auto& [key, bad] : {std::pair<const char*, json>{"measure", "edges"}, {"class_order", json{0, -1}},
                                 {"class_order", json{0.5}}, {"jitter", 1}, {"k", 0}, {"c1", 0}, {"c2", -1},
                                 {"num_sigmas", 0}, {"max_iterations", 0}}) {
    json q = GaborOptions::params().defaults();
    q[key] = bad;
    INFO(key << " = " << bad.dump());
    CHECK_THROWS_WITH(GaborOptions::params().read(q), Contains(std::string("method.") + key));
  }
}

TEST_CASE("method.border_relax: auto, --quick's cap, the band in output units, errors named", "[optim][options]") {
  BorderRelaxContext square;
  square.max_iterations = 4;
  square.mean_nn_distance = 0.1;
  square.upscale = 2;
  json block = BorderRelaxOptions::params().defaults();
  BorderRelaxSettings s = relax(block, square);
  CHECK(s.iterations == 60);  // auto, where the grid has an edge
  CHECK(s.band == Approx(0.05));
  CHECK(s.lr == 0);
  CHECK(s.after_all);
  BorderRelaxContext quick = square;
  quick.quick = true;
  CHECK(relax(block, quick).iterations == 4);
  BorderRelaxContext rect = square;
  rect.rectangle = true;
  CHECK(relax(block, rect).iterations == 0);
  block["iterations"] = 10;
  CHECK_THROWS_WITH(relax(block, rect), Contains("method.border_relax"));
  block["after"] = "class";
  block["lr"] = 0.5;
  s = relax(block, square);
  CHECK(s.iterations == 10);
  CHECK(s.lr == 0.5);
  CHECK_FALSE(s.after_all);
  for (const auto& [key, bad] : {std::pair<const char*, json>{"iterations", 2.5}, {"iterations", "many"}, {"iterations", -1},
                                 {"lr", 0}, {"band", 0}, {"parked", -1}, {"separation", -1}, {"after", "first"}}) {
    json q = BorderRelaxOptions::params().defaults();
    q[key] = bad;
    INFO(key << " = " << bad.dump());
    CHECK_THROWS_WITH(relax(q, square), Contains(std::string("method.border_relax.") + key));
  }
}
