// Outputs of any size and shape: rectangles and point counts in exemplar units,
// clean borders (a padded canvas, cropped, or its pad held by the frozen exemplar), and synthesis window by window
// (optim/gabor/windows/window_plan.hpp): the layout tiles the canvas, a window run resumes bit for bit, the
// pattern has no seam at the windows' meeting lines, and the grid (the memory of an
// iteration) does not grow with the output.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

#include "core/generators/lattices.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/output_shape.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_config.hpp"
#include "optim/gabor/stages/synthesis_state.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"
#include "optim/gabor/windows/window_plan.hpp"

using namespace ppsynth;
using ppsynth::test::same_bits;

namespace {


OutputShape shape_of(const json& output, const PointSet& ex) {
  json config = resolve_run_config(json{{"output", output}}, {});
  return resolve_output_shape(config, ex);
}

struct Run {
  PointSet start;  // the initialization as the run reports it (init.txt, `--init`)
  PointSet output;
  std::vector<std::string> checkpoints;
  json stats;
};

// A tiny Gabor run on `shape`: 16 grid positions per exemplar unit, windows of `pixels`,
// margins of 0.3 exemplar units (the automatic margin, 3 sigma_max, would need larger windows).
// `extra`: more method keys (terms beside the paper's).
Run synthesize(const PointSet& ex, const OutputShape& shape, int pixels, int iterations, const std::string* resume = nullptr,
               bool checkpoints = false, const std::string& statistics = "grid", const json& extra = json::object()) {
  json spec = {{"type", "gabor"},
               {"window", {{"pixels", pixels}, {"margin", 0.3}, {"statistics", statistics}}},
               {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", iterations}, {"num_sigmas", 2}}}};
  spec.update(extra);
  auto method = MethodRegistry::instance().create(spec, "method");
  Run run;
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 3;
  ctx.output = shape;
  ctx.stats = &run.stats;
  if (checkpoints) {
    ctx.checkpoint_seconds = 0;
    ctx.save_checkpoint = [&](const std::string& bytes) { run.checkpoints.push_back(bytes); };
  }
  ctx.resume_state = resume;
  struct : SynthesisObserver {
    PointSet* start = nullptr;
    void on_start(const PointSet& p) override { *start = p; }
  } initial;
  initial.start = &run.start;
  ctx.observers.push_back(&initial);
  run.output = method->synthesize(ex, ctx);
  return run;
}


}  // namespace

TEST_CASE("output shapes: the paper's square, rectangles and point counts, with their errors", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(2, false, 25, 0.005);  // 25 + 9 points on the unit square
  const OutputShape paper = shape_of(json::object(), ex);
  CHECK_FALSE(paper.rectangle);
  CHECK(paper.expected_points(ex) == 4 * 34);

  const OutputShape strip = shape_of(json{{"size", {4, 1}}}, ex);
  CHECK(strip.rectangle);
  CHECK(strip.domain().x1 == 4);
  CHECK(strip.domain().y1 == 1);
  CHECK(strip.class_counts(ex, strip.domain()) == std::vector<size_t>{100, 36});
  CHECK(strip.pad == Approx(2 * mean_nn_distance(ex)));
  CHECK(strip.canvas().x0 == Approx(-strip.pad));

  // A pad given as a length passes the config check (the default is null = "auto").
  CHECK(shape_of(json{{"size", {4, 1}}, {"pad", 0.5}}, ex).pad == 0.5);
  CHECK(shape_of(json{{"size", {4, 1}}, {"pad", "auto"}}, ex).pad == Approx(strip.pad));

  const OutputShape counted = shape_of(json{{"points", 3400}, {"border", "published"}}, ex);
  CHECK(counted.width == Approx(10));
  CHECK(counted.height == Approx(10));
  CHECK(counted.pad == 0);
  CHECK(counted.expected_points(ex) == 3400);

  for (const json& bad : {json{{"size", {4}}}, json{{"size", {4, 1}}, {"points", 10}}, json{{"points", 0}},
                          json{{"size", {0.001, 1}}}, json{{"size", {2, 2}}, {"border", "soft"}}, json{{"size", {2, 2}}, {"border", "crop"}}, json{{"size", {2, 2}}, {"pad", -1}}, json{{"size", {2, 2}}, {"pad", "wide"}}})
    CHECK_THROWS_WITH(shape_of(bad, ex), Catch::Contains("output"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"output", {{"sizes", {1, 1}}}}}, {}), Catch::Contains("output.sizes"));
}

TEST_CASE("window layout: interiors tile the canvas, overlaps hold two margins, the movable part stays in the grid",
          "[optim][windows]") {
  const Domain canvas{-0.5, -0.5, 9.5, 4.5};
  // 5 x 2 windows of 3 x 3.5: overlaps of (5 x 3 - 10) / 4 = 1.25 and 3.5 x 2 - 5 = 2.
  const WindowLayout w = window_layout(canvas, canvas, WindowSize{3.0, 3.5, 5, 2}, 0.5, 0.6);
  CHECK(w.nx == 5);
  CHECK(w.ny == 2);
  REQUIRE(w.windows.size() == 10);
  double area = 0;
  for (const auto& s : w.windows) {
    area += s.interior.area();
    CHECK(s.grid.width() == Approx(3.0));
    CHECK(s.grid.height() == Approx(3.5));
    CHECK(s.grid.x0 >= canvas.x0 - 1e-12);
    CHECK(s.grid.x1 <= canvas.x1 + 1e-12);
    // a final point never sees a grid border: a margin between interior and grid edge,
    // except on the canvas's own border
    if (s.interior.x0 > canvas.x0) CHECK(s.interior.x0 - s.grid.x0 >= 0.5 - 1e-12);
    if (s.interior.x1 < canvas.x1) CHECK(s.grid.x1 - s.interior.x1 >= 0.5 - 1e-12);
    if (s.interior.y0 > canvas.y0) CHECK(s.interior.y0 - s.grid.y0 >= 0.5 - 1e-12);
    if (s.interior.y1 < canvas.y1) CHECK(s.grid.y1 - s.interior.y1 >= 0.5 - 1e-12);
    CHECK(s.movable.x0 == s.interior.x0);
    CHECK(s.movable.x1 == s.grid.x1);
    CHECK(s.context.x0 == Approx(s.grid.x0 - 0.6));
  }
  CHECK(area == Approx(canvas.area()));  // and no two interiors overlap:
  for (size_t a = 0; a < w.windows.size(); ++a)
    for (size_t b = a + 1; b < w.windows.size(); ++b) {
      const Domain &p = w.windows[a].interior, &q = w.windows[b].interior;
      const double ox = std::min(p.x1, q.x1) - std::max(p.x0, q.x0), oy = std::min(p.y1, q.y1) - std::max(p.y0, q.y0);
      CHECK_FALSE((ox > 1e-9 && oy > 1e-9));
    }
  // A canvas within the budget is one window, the canvas itself, whatever its aspect.
  const auto one = window_size(Domain{0, 0, 2, 1}, 40.0 * 20, 20, 0.5);
  REQUIRE(one);
  CHECK(one->nx * one->ny == 1);
  const WindowLayout whole = window_layout(Domain{0, 0, 2, 1}, Domain{0, 0, 2, 1}, *one, 0.5, 0.6);
  REQUIRE(whole.windows.size() == 1);
  CHECK(whole.windows[0].grid.x1 == 2);
  CHECK(whole.windows[0].grid.y1 == 1);
  CHECK(whole.windows[0].interior.x1 == 2);
  // Windows of at most 10 x 10 positions at 10 per unit cannot hold two margins of 0.5 and an interior.
  CHECK_FALSE(window_size(canvas, 100, 10, 0.5));
}

TEST_CASE("a rectangle output: its domain, counts near the density's, classes and radii kept", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(2, true, 25, 0.005);
  const OutputShape shape = shape_of(json{{"size", {3, 1.5}}}, ex);
  const Run run = synthesize(ex, shape, 24, 3);  // 24 positions = 1.5 units: 2 x 1 windows and more
  const PointSet& out = run.output;
  CHECK(out.domain().x1 == 3);
  CHECK(out.domain().y1 == 1.5);
  CHECK(run.stats["windows"]["nx"].get<int>() >= 2);
  const auto counts = out.class_counts();
  REQUIRE(counts.size() == 2);
  CHECK(std::abs(static_cast<double>(counts[0]) - 25 * 4.5) <= 0.15 * 25 * 4.5);
  CHECK(std::abs(static_cast<double>(counts[1]) - 9 * 4.5) <= 0.2 * 9 * 4.5);
  const int r = *out.attribute_index("radius");
  for (size_t i = 0; i < out.size(); ++i) {
    CHECK(out.domain().contains(out[i], 0.0));
    const double radius = out.attr(i, r);  // exemplar units: the exemplar's own radii, not divided by u
    CHECK(radius >= 0.02 - 1e-12);
    CHECK(radius <= 0.04 + 1e-12);
  }

  // A published border keeps the count exact: the canvas is the rectangle.
  const OutputShape exact = shape_of(json{{"points", 200}, {"border", "published"}}, test::small_exemplar(1, false, 25, 0.005));
  const Run counted = synthesize(test::small_exemplar(1, false, 25, 0.005), exact, 24, 2);
  CHECK(counted.output.size() == 200);
}

TEST_CASE("the exemplar-context border: exact counts inside the rectangle, the pad frozen and left out", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(2, true, 25, 0.005);
  const OutputShape shape = shape_of(json{{"size", {3, 1.5}}, {"border", "context"}}, ex);
  REQUIRE(shape.exemplar_pad);
  REQUIRE(shape.pad > 0);
  CHECK(shape.moving_area().x0 == 0);
  CHECK(shape.moving_area().x1 == 3);
  CHECK(shape.canvas().x0 == Approx(-shape.pad));
  const Run run = synthesize(ex, shape, 24, 3);  // 2 x 1 windows and more
  const PointSet& out = run.output;
  // Nothing is cut off: every class has its density's count exactly, as "published" has.
  CHECK(out.class_counts() == shape.class_counts(ex, shape.domain()));
  for (size_t i = 0; i < out.size(); ++i) CHECK(shape.domain().contains(out[i], 0.0));
  // The pad is the exemplar tiled over the ring: its area's worth of points, not in the output.
  const double ring = shape.canvas().area() - shape.domain().area();
  const double pad_points = run.stats["frozen_pad_points"].get<double>();
  CHECK(pad_points == Approx(ring * static_cast<double>(ex.size())).epsilon(0.25));
  CHECK(run.stats["canvas_points"].get<double>() == Approx(static_cast<double>(out.size()) + pad_points));
  // The initialization it reports is the synthesized points' start (what `--init` takes
  // back), without the pad.
  CHECK(run.start.class_counts() == out.class_counts());
  for (size_t i = 0; i < run.start.size(); ++i) CHECK(shape.domain().contains(run.start[i], 0.0));

  // The tiling under it: copies of the exemplar, classes and radii kept, at its density.
  const Domain big{-0.5, -0.5, 2.5, 1.5};
  const PointSet tiles = ex.tiled_over(big, Vec2{0.5, 0.5});
  CHECK(tiles.size() == 6 * ex.size());
  CHECK(tiles.class_counts() == std::vector<size_t>{6 * 25, 6 * 9});
  CHECK(tiles.attribute_index("radius"));
  for (size_t i = 0; i < tiles.size(); ++i) CHECK(big.contains(tiles[i], 0.0));

  // Methods without a frozen pad refuse it, naming the key.
  for (const char* m : {"roveri2015", "pcf2017"}) {
    auto method = MethodRegistry::instance().create(json{{"type", m}}, "method");
    SynthesisContext ctx;
    ctx.output = shape;
    CHECK_THROWS_WITH(method->synthesize(ex, ctx), Catch::Contains("output.border"));
  }
}

TEST_CASE("a point held at a window's movable edge maps back inside it, not 1e-8 beyond", "[optim][windows]") {
  // A context run wrote (1.09, -3.1e-08) into a [0, 2] x [0, 2] output, which the readers then
  // refused: the edge is held in float grid-local coordinates. Over many pads (grids) the naive
  // map back lands outside for some; WindowGeometry::to_output never does.
  int naive_outside = 0;
  for (int k = 1; k <= 400; ++k) {
    const double pad = 0.001 * k;
    StageWindow w;
    w.grid = {-pad, -pad, 2 + pad, 2 + pad};
    w.movable = w.interior = {0, 0, 2, 2};
    const WindowGeometry window(w);
    const double side = w.grid.width();
    const double lo = static_cast<float>((0 - w.grid.x0) / side), hi = static_cast<float>((2 - w.grid.x0) / side);
    naive_outside += !w.movable.contains({w.grid.x0 + side * lo, w.grid.y0 + side * hi}, 0.0);
    for (double u : {lo, hi})
      for (double v : {lo, hi}) {
        INFO("pad " << pad << ", local " << u << ", " << v);
        CHECK(w.movable.contains(window.to_output(u, v), 0.0));
      }
  }
  CHECK(naive_outside > 0);
  const TorusGeometry torus;  // the paper's square: positions are the output's, unchanged
  CHECK(torus.to_output(0.25, 0.999).x == 0.25);
  CHECK(torus.to_output(0.25, 0.999).y == 0.999);
}

TEST_CASE("window statistics \"output\": the losses measure the grid's part inside the output only", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(2, true, 25, 0.005);
  // Where every window grid lies inside the output (a published border: the canvas is the
  // output), the measured part is the whole grid: the same run, bit for bit.
  const OutputShape exact = shape_of(json{{"size", {2.5, 1.2}}, {"border", "published"}}, ex);
  const Run grid = synthesize(ex, exact, 20, 3);
  CHECK(grid.stats["windows"]["nx"].get<int>() >= 2);
  CHECK(same_bits(synthesize(ex, exact, 20, 3, nullptr, false, "output").output, grid.output));
  // With a pad (clean or context) the pad is seen by the maps but not measured: another run.
  for (const char* border : {"clean", "context"}) {
    INFO("border " << border);
    const OutputShape padded = shape_of(json{{"size", {2.5, 1.2}}, {"border", border}}, ex);
    const Run whole = synthesize(ex, padded, 20, 3);
    const Run inside = synthesize(ex, padded, 20, 3, nullptr, false, "output");
    CHECK_FALSE(same_bits(inside.output, whole.output));
    for (size_t i = 0; i < inside.output.size(); ++i) CHECK(padded.domain().contains(inside.output[i], 0.0));
  }
  CHECK_THROWS_WITH(synthesize(ex, exact, 20, 3, nullptr, false, "pad"), Catch::Contains("method.window.statistics"));
}

TEST_CASE("a window run resumed from any checkpoint ends bit for bit as the uninterrupted one", "[optim][windows][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, true, 25, 0.005);
  const std::string border = GENERATE(as<std::string>{}, "clean", "context");
  const OutputShape shape = shape_of(json{{"size", {2.5, 1.2}}, {"border", border}}, ex);
  const Run whole = synthesize(ex, shape, 20, 3, nullptr, true);
  const size_t n = whole.checkpoints.size();
  REQUIRE(n > 10);
  for (size_t i : {size_t{1}, n / 3, n / 2, n - 2}) {
    INFO("border " << border);
    const SynthesisState st = deserialize_state(whole.checkpoints[i], "test");
    INFO("checkpoint " << i << ": stage " << st.stage << ", iteration " << st.iteration);
    const Run resumed = synthesize(ex, shape, 20, 3, &whole.checkpoints[i], true);
    CHECK(same_bits(resumed.output, whole.output));
  }
}

TEST_CASE("terms beside the paper's in windows: separation and class_own act, resume bit for bit; torus-only terms refused",
          "[optim][windows][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, true, 25, 0.005);
  const OutputShape shape = shape_of(json{{"size", {2.5, 1.2}}, {"border", "clean"}}, ex);
  const Run plain = synthesize(ex, shape, 20, 3);
  REQUIRE(plain.stats["windows"]["nx"].get<int>() >= 2);
  // Separation: twice the exemplar's closest pairs, more than the initialization's spacing.
  const json separation = {{"terms", {{"separation", {{"weight", 10.0}, {"fraction", 2.0}}}}}};
  const Run separated = synthesize(ex, shape, 20, 3, nullptr, false, "grid", separation);
  CHECK(separated.stats["terms"]["separation"].get<double>() == 10.0);
  CHECK_FALSE(same_bits(separated.output, plain.output));
  // class_own: class 0 (first in the order: its joint maps are its own) moves as without it,
  // in every window of the sequential pass (no revisit, where class 0 moves again with the
  // term); class 1 moves otherwise. (A published border: the canvas is the output, so its
  // points are the canvas's, in the same order.)
  const OutputShape exact = shape_of(json{{"size", {2.5, 1.2}}, {"border", "published"}}, ex);
  const json own = {{"map_terms", {{"class_own", {{"weight", 1.0}}}}}, {"revisit", {{"iterations", 0}}}};
  const Run plain_exact = synthesize(ex, exact, 20, 3, nullptr, false, "grid",
                                     json{{"map_terms", {{"class_own", {{"weight", 0.0}}}}}, {"revisit", {{"iterations", 0}}}});
  const Run with_own = synthesize(ex, exact, 20, 3, nullptr, false, "grid", own);
  REQUIRE(with_own.output.size() == plain_exact.output.size());
  size_t class1_moved = 0;
  for (size_t i = 0; i < plain_exact.output.size(); ++i) {
    if (plain_exact.output.cls(i) == 0) {
      CHECK(with_own.output[i].x == plain_exact.output[i].x);
      CHECK(with_own.output[i].y == plain_exact.output[i].y);
    } else {
      class1_moved += with_own.output[i].x != plain_exact.output[i].x || with_own.output[i].y != plain_exact.output[i].y;
    }
  }
  CHECK(class1_moved > 0);
  // Both, with the exemplar's frozen pad as context (its class-1 points enter the class's own
  // maps), resumed from checkpoints inside and between windows: the uninterrupted run, bit for bit.
  json both = separation;
  both.update(own);
  const OutputShape context = shape_of(json{{"size", {2.5, 1.2}}, {"border", "context"}}, ex);
  const Run whole = synthesize(ex, context, 20, 3, nullptr, true, "grid", both);
  const size_t n = whole.checkpoints.size();
  REQUIRE(n > 10);
  for (size_t i : {n / 3, n / 2 + 1, n - 2}) {
    const SynthesisState st = deserialize_state(whole.checkpoints[i], "test");
    INFO("checkpoint " << i << ": stage " << st.stage << ", iteration " << st.iteration);
    CHECK(same_bits(synthesize(ex, context, 20, 3, &whole.checkpoints[i], true, "grid", both).output, whole.output));
  }
  // pcf_match's estimator is the torus's: refused, naming the term, before anything runs.
  CHECK_THROWS_WITH(synthesize(ex, shape, 20, 3, nullptr, false, "grid", json{{"terms", {{"pcf_match", {{"weight", 1.0}}}}}}),
                    Catch::Contains("method.terms.pcf_match") && Catch::Contains("u x u"));
}

namespace {

// The pattern along vertical lines of a strip output: per line, the points within 0.25 of it
// (away from the output's border) against all such points of the output: their density, mean
// nearest-neighbor distance and share of points closer than 0.3 mean spacings, as ratios
// (density, spacing) or a difference (close share) to the whole strip's.
struct LineStats {
  double density = 0, spacing = 0, close = 0;
};

LineStats line_stats(const PointSet& out, const std::vector<double>& nn, double mean_nn, double x0, double height) {
  const double half = 0.25, y0 = 0.3, y1 = height - 0.3, x_lo = 0.3, x_hi = out.domain().x1 - 0.3;
  size_t n_all = 0, n = 0, close_all = 0, close = 0;
  double nn_sum = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i].y < y0 || out[i].y > y1 || out[i].x < x_lo || out[i].x > x_hi) continue;
    const bool is_close = nn[i] < 0.3 * mean_nn;
    ++n_all;
    close_all += is_close;
    if (std::abs(out[i].x - x0) >= half) continue;
    ++n;
    close += is_close;
    nn_sum += nn[i];
  }
  LineStats s;
  s.density = (n / (2 * half)) / (n_all / (x_hi - x_lo));
  s.spacing = n ? nn_sum / n / mean_nn : 0;
  s.close = (n ? double(close) / n : 0) - double(close_all) / n_all;
  return s;
}

// A strip output of seed `seed` and the x of its windows' meeting lines.
struct Strip {
  PointSet out;
  std::vector<double> meeting;
};

Strip synthesize_strip(uint64_t seed) {
  const PointSet ex = test::small_exemplar(1, false, 25, 0.005);
  auto method = MethodRegistry::instance().create(
      json{{"type", "gabor"}, {"window", {{"pixels", 72}}}, {"quick", {{"res", 24}, {"channels", 8}, {"max_iterations", 20}, {"num_sigmas", 2}}}},
      "method");
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = seed;
  ctx.output = shape_of(json{{"size", {8, 3}}}, ex);
  json stats;
  ctx.stats = &stats;
  Strip strip{method->synthesize(ex, ctx), {}};
  REQUIRE(stats["windows"]["nx"].get<int>() >= 3);
  // the meeting lines: half-way in each overlap (window_plan.cpp); recomputed from the layout
  const json& w = stats["windows"];
  const WindowLayout layout = window_layout(ctx.output.canvas(), ctx.output.moving_area(),
                                            WindowSize{w["width"], w["height"], w["nx"], w["ny"]}, w["margin"], 0);
  for (int i = 0; i + 1 < layout.nx; ++i) strip.meeting.push_back(layout.windows[i].interior.x1);
  return strip;
}

// Adds the stats of the strip's meeting lines to `seams` and of lines well inside the windows
// (>= 0.5 from any meeting line, every 0.25) to `controls`.
void strip_lines(const Strip& strip, std::vector<LineStats>& seams, std::vector<LineStats>& controls) {
  const auto nn = nearest_neighbor_distances(strip.out, false);
  double mean_nn = 0;
  for (double d : nn) mean_nn += d;
  mean_nn /= nn.size();
  for (double x : strip.meeting) seams.push_back(line_stats(strip.out, nn, mean_nn, x, 3));
  for (double x = 0.55; x < 7.5; x += 0.25) {
    bool near = false;
    for (double m : strip.meeting) near |= std::abs(x - m) < 0.5;
    if (!near) controls.push_back(line_stats(strip.out, nn, mean_nn, x, 3));
  }
}

// How far the seams' mean lies from the other lines' mean, in standard deviations of one of
// the other lines (their spread measured on the same outputs): a seam that a reader could not
// tell from any other line of the pattern stays within about one.
struct Departure {
  double density, spacing, close;
};
Departure departure(const std::vector<LineStats>& seams, const std::vector<LineStats>& controls) {
  auto in_sd = [&](double LineStats::*f) {
    double ms = 0, mc = 0, vc = 0;
    for (const auto& s : seams) ms += s.*f;
    for (const auto& c : controls) mc += c.*f;
    ms /= seams.size();
    mc /= controls.size();
    for (const auto& c : controls) vc += (c.*f - mc) * (c.*f - mc);
    return (ms - mc) / std::sqrt(vc / (controls.size() - 1));
  };
  return {in_sd(&LineStats::density), in_sd(&LineStats::spacing), in_sd(&LineStats::close)};
}

}  // namespace

TEST_CASE("no seam: where windows meet, the pattern is as along any line inside the windows", "[optim][windows][isa]") {
  // One class of 25 jittered-grid points per unit, an 8 x 3 strip in windows of 3 units with
  // the automatic margin (3 sigma_max + the 7 x 7 network's reach): the interiors meet at
  // several x. Decided over three seeds against the spread of the same statistics along
  // lines inside the windows, on the same outputs: the seams' mean density, spacing and
  // close-pair share each lie within 1.5 standard deviations of one line of the others.
  // Measured on an AVX2 EPYC: -0.2, -0.3 and +0.8: the seams hold slightly more close pairs
  // than the average line, within what lines vary by.
  std::vector<Strip> strips;
  for (uint64_t seed : {4, 5, 6}) strips.push_back(synthesize_strip(seed));
  auto departure_of = [&](const std::vector<Strip>& outputs) {
    std::vector<LineStats> seams, controls;
    for (const auto& strip : outputs) strip_lines(strip, seams, controls);
    REQUIRE(seams.size() >= 6);
    REQUIRE(controls.size() >= 15);
    return departure(seams, controls);
  };
  const Departure d = departure_of(strips);
  INFO("seams' departure in standard deviations of a line: density " << d.density << ", spacing " << d.spacing << ", close pairs "
                                                                       << d.close);
  CHECK(std::abs(d.density) < 1.5);
  CHECK(std::abs(d.spacing) < 1.5);
  CHECK(std::abs(d.close) < 1.5);

  SECTION("the statistics see a seam where there is one") {
    // The same outputs with what a seam would look like: a gap one spacing (0.2) wide on each
    // meeting line, or a pile (every point within half a spacing doubled a tenth of the
    // output's mean nearest-neighbor distance away). The copy's offset follows the output, not
    // the exemplar: these quick outputs' mean distance is 0.065-0.09, so a fixed 0.02 sat on
    // the close threshold (0.3 of the seamed output's mean) and counted on some CPUs' bits and
    // not on others'.
    auto with_seams = [&](bool gap) {
      std::vector<Strip> seamed;
      for (const auto& strip : strips) {
        const auto nn = nearest_neighbor_distances(strip.out, false);
        const double offset = 0.1 * std::accumulate(nn.begin(), nn.end(), 0.0) / nn.size();
        Strip t{PointSet{}, strip.meeting};
        for (size_t i = 0; i < strip.out.size(); ++i) {
          double dx = 1e9;
          for (double m : strip.meeting) dx = std::min(dx, std::abs(strip.out[i].x - m));
          if (gap && dx < 0.1) continue;
          t.out.add(strip.out[i], 0);
          if (!gap && dx < 0.1) t.out.add({strip.out[i].x + offset, strip.out[i].y}, 0);
        }
        t.out.set_domain(strip.out.domain());
        seamed.push_back(t);
      }
      return seamed;
    };
    const Departure gap = departure_of(with_seams(true)), pile = departure_of(with_seams(false));
    INFO("gap: density " << gap.density << "; pile: density " << pile.density << ", close pairs " << pile.close);
    CHECK(gap.density < -1.5);
    CHECK(pile.density > 1.5);
    CHECK(pile.close > 1.5);
  }
}

TEST_CASE("the window grid, the memory of an iteration, does not grow with the output", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(1, false, 25, 0.005);
  const json p = [] {
    json m;
    MethodRegistry::instance().create(json{{"type", "gabor"}}, "method", &m);
    return m;
  }();
  const double budget = std::pow(p["window"]["pixels"].get<double>(), 2);
  for (const long long points : {100000LL, 1000000LL, 10000000LL}) {
    INFO(points << " points");
    const GaborSettings s = resolve_gabor_settings(p, ex, shape_of(json{{"points", points}}, ex), false);
    CHECK(s.window.nx * s.window.ny > 1);
    CHECK(static_cast<double>(s.out_res) * s.out_rows <= budget);  // one window's grid, whatever the canvas
  }
  // a canvas within the budget: the grid is the canvas's, at the exemplar's positions per unit
  const OutputShape shape = shape_of(json{{"size", {1, 1}}}, ex);
  const GaborSettings tiny = resolve_gabor_settings(p, ex, shape, false);
  CHECK(tiny.window.nx * tiny.window.ny == 1);
  CHECK(tiny.out_res == std::lround(shape.canvas().width() * tiny.res));
  CHECK(tiny.out_rows == tiny.out_res);
}

TEST_CASE("per-sigma grids: coarser at coarse sigmas, the finest unchanged, margins for the farthest reach", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(1, false, 25, 0.005);
  auto params = [](bool per_sigma) {
    json m;
    MethodRegistry::instance().create(json{{"type", "gabor"}, {"grid", {{"per_sigma", per_sigma}}}}, "method", &m);
    return m;
  };
  for (const json& output : {json::object(), json{{"size", {6, 6}}}}) {
    INFO("output " << output.dump());
    const OutputShape shape = output.empty() ? OutputShape{} : shape_of(output, ex);
    const GaborSettings fixed = resolve_gabor_settings(params(false), ex, shape, false);
    const GaborSettings scaled = resolve_gabor_settings(params(true), ex, shape, false);
    REQUIRE(scaled.sigma_res.size() == scaled.sigmas.size());
    REQUIRE(scaled.sigma_out_res.size() == scaled.sigmas.size());
    for (size_t i = 0; i < fixed.sigmas.size(); ++i) {
      CHECK(fixed.sigma_res[i] == fixed.res);
      CHECK(fixed.sigma_out_res[i] == fixed.out_res);
      // the same grid positions per sigma as the finest stage, never finer than it
      CHECK(scaled.sigma_res[i] <= scaled.res);
      CHECK(scaled.sigma_res[i] * scaled.sigmas[i] >= scaled.res * scaled.sigmas.back() - 1e-6);
      CHECK((scaled.sigma_res[i] - 1) * scaled.sigmas[i] < scaled.res * scaled.sigmas.back());
      if (i > 0) CHECK(scaled.sigma_res[i] >= scaled.sigma_res[i - 1]);
    }
    CHECK(scaled.sigma_res.back() == scaled.res);
    CHECK(scaled.sigma_out_res.back() == scaled.out_res);
    CHECK(scaled.sigma_res.front() < scaled.res);  // c2 / c1 = 2.6: about 2.6 x coarser
    if (!output.empty()) CHECK(scaled.window_margin > fixed.window_margin);  // the coarse grid's receptive field reaches farther
  }
}

// --- rectangles on one grid: the cost follows the canvas's grid positions, not a window count

namespace {

// An exemplar of `width` x `height` (two classes: a jittered grid and a sparser one), as
// amacrine (1.601 x 1) and swedishpines (1 x 1.042) are exported.
PointSet rectangle_exemplar(double width, double height) {
  PointSet ex(Domain{0, 0, width, height});
  const PointSet a = test::small_exemplar(2, false, 25, 0.005);
  for (size_t i = 0; i < a.size(); ++i) ex.add({a[i].x * width, a[i].y * height}, a.cls(i));
  return ex;
}

json gabor_params(const json& method = json{{"type", "gabor"}}) {
  json m;
  MethodRegistry::instance().create(method, "method", &m);
  return m;
}

}  // namespace

TEST_CASE("a rectangle output within the budget is one grid in the exemplar's aspect, whatever the aspect", "[optim][windows]") {
  // The default output of a rectangular exemplar: u x u copies of its rectangle, with a clean
  // border. Cut into square windows of at most 384 positions across, amacrine's 3.2 x 2 took
  // 6 windows and swedishpines' 2 x 2.08 took 2, each costing an iteration of a grid about
  // the whole output's size.
  for (const auto& [w, h] : {std::pair{1.601, 1.0}, std::pair{1.0, 1.042}, std::pair{1.0, 3.0}}) {
    INFO("exemplar " << w << " x " << h);
    const PointSet ex = rectangle_exemplar(w, h);
    const OutputShape shape = resolve_output_shape(resolve_run_config(json::object(), {}), ex);
    REQUIRE(shape.rectangle);
    const GaborSettings s = resolve_gabor_settings(gabor_params(), ex, shape, false);
    CHECK(s.window.nx == 1);
    CHECK(s.window.ny == 1);
    const Domain c = shape.canvas();
    CHECK(s.out_res == std::lround(c.width() * s.res));
    // rows at the columns' spacing, the last within a spacing of the canvas's top (as a square's)
    for (size_t i = 0; i < s.sigmas.size(); ++i) {
      const double spacing = c.width() / (s.sigma_out_res[i] + 1);
      CHECK(s.sigma_out_rows[i] * spacing < c.height());
      CHECK((s.sigma_out_rows[i] + 1) * spacing >= c.height() - 1e-9);
    }
    CHECK(s.sigma_out_rows.back() == s.out_rows);
    const WindowLayout layout = window_layout(c, shape.moving_area(), s.window, s.window_margin, 0.1);
    REQUIRE(layout.windows.size() == 1);
    CHECK(layout.windows[0].grid.x0 == c.x0);
    CHECK(layout.windows[0].grid.y1 == c.y1);
    CHECK(layout.windows[0].interior.x1 == c.x1);
  }
}

TEST_CASE("a 1.6 x 1 rectangle within the budget runs one group per class on one grid", "[optim][windows]") {
  const PointSet ex = rectangle_exemplar(1.6, 1.0);
  const OutputShape shape = shape_of(json{{"size", {2, 2}}}, ex);  // exemplar sides: 3.2 x 2
  // 16 positions per unit: a canvas of about 60 x 40 positions, within windows of 64 x 64.
  const Run run = synthesize(ex, shape, 64, 2);
  CHECK(run.stats["windows"]["nx"].get<int>() == 1);
  CHECK(run.stats["windows"]["ny"].get<int>() == 1);
  CHECK(run.stats["output_grid_res"].get<int>() > run.stats["output_grid_rows"].get<int>());
  CHECK(run.output.domain().x1 == 3.2);
  const auto counts = run.output.class_counts();
  REQUIRE(counts.size() == 2);
  CHECK(std::abs(static_cast<double>(counts[0]) - 4 * 25) <= 0.15 * 4 * 25);
}

TEST_CASE("past the budget: the fewest rectangular windows, each within it, overlaps of two margins", "[optim][windows]") {
  const Domain strip{0, 0, 10, 2};  // 100 x 20 positions at 10 per unit
  const double margin = 0.5, budget = 30 * 30;
  const auto size = window_size(strip, budget, 10, margin);
  REQUIRE(size);
  // Square windows of 30 across (3 units, cut to the strip's height: 2) took 9; three of 4 x 2 fit.
  CHECK(size->nx == 3);
  CHECK(size->ny == 1);
  CHECK(size->width == Approx(4.0));
  CHECK(size->height == Approx(2.0));
  const auto [cols, rows] = window_grid(size->width, size->height, 10);
  CHECK(cols * rows <= budget);
  // No fewer windows fit: n windows along an axis of length L with overlaps of two margins are
  // at least (L + 2 margin (n - 1)) / n long.
  for (int a = 1; a <= 3; ++a)
    for (int b = 1; a * b < 3; ++b) {
      const auto [c, r] = window_grid((10 + 2 * margin * (a - 1)) / a, (2 + 2 * margin * (b - 1)) / b, 10);
      CHECK(c * r > budget);
    }
  const WindowLayout layout = window_layout(strip, strip, *size, margin, 0.3);
  REQUIRE(layout.windows.size() == 3);
  for (size_t i = 0; i + 1 < layout.windows.size(); ++i) {
    const StageWindow &p = layout.windows[i], &q = layout.windows[i + 1];
    CHECK(p.grid.x1 - q.grid.x0 >= 2 * margin - 1e-9);                  // overlap
    CHECK(p.interior.x1 == Approx(q.interior.x0));                       // interiors meet
    CHECK(p.grid.x1 - p.interior.x1 >= margin - 1e-9);                   // a margin beyond the interior
  }
  // A tall canvas: the windows stack along y.
  const auto tall = window_size(Domain{0, 0, 2, 10}, budget, 10, margin);
  REQUIRE(tall);
  CHECK(tall->nx == 1);
  CHECK(tall->ny == 3);
}

TEST_CASE("a rectangle on one grid resumed from any checkpoint ends bit for bit as the uninterrupted one",
          "[optim][windows][checkpoint]") {
  const PointSet ex = rectangle_exemplar(1.6, 1.0);
  const std::string border = GENERATE(as<std::string>{}, "clean", "context");
  const OutputShape shape = shape_of(json{{"size", {2, 2}}, {"border", border}}, ex);
  const Run whole = synthesize(ex, shape, 64, 3, nullptr, true);
  REQUIRE(whole.stats["windows"]["nx"].get<int>() == 1);
  const size_t n = whole.checkpoints.size();
  REQUIRE(n > 6);
  for (size_t i : {size_t{1}, n / 3, n / 2, n - 2}) {
    INFO("border " << border);
    const SynthesisState st = deserialize_state(whole.checkpoints[i], "test");
    INFO("checkpoint " << i << ": stage " << st.stage << ", iteration " << st.iteration);
    const Run resumed = synthesize(ex, shape, 64, 3, &whole.checkpoints[i], true);
    CHECK(same_bits(resumed.output, whole.output));
  }
}

TEST_CASE("a rectangle grid's local coordinates: the width is the unit along both axes", "[optim][windows]") {
  StageWindow w;
  w.grid = {-0.5, -0.5, 3.5, 1.5};  // 4 x 2
  w.movable = w.interior = {0, 0, 3, 1};
  const WindowGeometry g(w);
  PointSet ps(Domain{0, 0, 3, 1});
  ps.add({3, 1});
  ps.add({0, 0});
  const auto local = g.to_local(ps);
  CHECK(local[0][0].item<float>() == Approx(0.875));
  CHECK(local[0][1].item<float>() == Approx(0.375));  // (1 + 0.5) / 4, not / 2
  CHECK(local[1][1].item<float>() == Approx(0.125));
  // Held inside the movable part: a point pushed above it sits on its top edge.
  const auto held = g.confine(torch::tensor({{0.5f, 0.9f}}));
  CHECK(held[0][1].item<float>() == Approx(0.375));
  const Vec2 back = g.to_output(0.5, 0.25);
  CHECK(back.x == Approx(1.5));
  CHECK(back.y == Approx(0.5));
}

TEST_CASE("a rectangular exemplar's targets come from its whole domain, not its unit square", "[optim][windows]") {
  // amacrine is 1.601 x 1: its raster covered the unit square of its coordinates, so the part
  // beyond x = 1 (38 % of its points) reached the targets only through the grid's right edge.
  const PointSet a = rectangle_exemplar(1.6, 1.0);
  PointSet b(a.domain());  // the same exemplar with another pattern beyond x = 1.3
  for (size_t i = 0; i < a.size(); ++i)
    b.add(a[i].x > 1.3 ? Vec2{a[i].x, std::fmod(a[i].y + 0.37, 1.0)} : a[i], a.cls(i));
  const json params = gabor_params(json{{"type", "gabor"}, {"quick", {{"res", 24}, {"channels", 4}, {"num_sigmas", 2}}}});
  const GaborSettings s = resolve_gabor_settings(params, a, shape_of(json{{"size", {2, 2}}}, a), true);
  REQUIRE(3 * s.sigmas.back() < 0.3);  // the moved points lie beyond the maps' reach of x <= 1
  GaborPipeline pipe(s, 3);
  pipe.set_grid(static_cast<int>(s.sigmas.size()) - 1);
  auto gen = at::detail::createCPUGenerator(5);
  const auto out = at::rand({120, 2}, gen, torch::kFloat32) * torch::tensor({{1.0f, 0.65f}});  // a fixed output, local coordinates
  auto loss_for = [&](const PointSet& ex) {
    torch::NoGradGuard ng;
    pipe.set_targets(positions_tensor(ex), {}, s.sigmas.back());
    return pipe.loss(pipe.features(pipe.output_maps(out, {}, s.sigmas.back(), {}))).item<double>();
  };
  const double la = loss_for(a), lb = loss_for(b);
  INFO("loss against the exemplar " << la << ", against the one with its right part moved " << lb);
  CHECK(std::abs(la - lb) > 1e-3 * la);
}
