// Outputs of any size and shape (issue 20): rectangles and point counts in exemplar units,
// clean borders (a padded canvas, cropped, or its pad held by the frozen exemplar), and synthesis window by window
// (optim/window_plan.hpp): the layout tiles the canvas, a window run resumes bit for bit, the
// pattern has no seam at the windows' meeting lines, and the grid (the memory of an
// iteration) does not grow with the output.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/generators/lattices.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/output_shape.hpp"
#include "optim/gabor_pipeline.hpp"
#include "optim/method.hpp"
#include "optim/run/run_config.hpp"
#include "optim/synthesis_state.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"
#include "optim/window_plan.hpp"

using namespace ppsynth;
using ppsynth::test::same_bits;

namespace {


OutputShape shape_of(const json& output, const PointSet& ex) {
  json config = resolve_run_config(json{{"output", output}}, {});
  return resolve_output_shape(config, ex);
}

struct Run {
  PointSet start;  // the initialisation as the run reports it (init.txt, `--init`)
  PointSet output;
  std::vector<std::string> checkpoints;
  json stats;
};

// A tiny Gabor run on `shape`: 16 grid positions per exemplar unit, windows of `pixels`,
// margins of 0.3 exemplar units (the automatic margin, 3 sigma_max, would need larger windows).
Run synthesize(const PointSet& ex, const OutputShape& shape, int pixels, int iterations, const std::string* resume = nullptr,
               bool checkpoints = false, const std::string& statistics = "grid") {
  auto method = MethodRegistry::instance().create(
      json{{"type", "gabor"},
           {"window", {{"pixels", pixels}, {"margin", 0.3}, {"statistics", statistics}}},
           {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", iterations}, {"num_sigmas", 2}}}},
      "method");
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
  const WindowLayout w = window_layout(canvas, canvas, 3.0, 0.5, 0.6, "method.window");
  CHECK(w.side == 3.0);
  CHECK(w.nx == 5);  // (10 - 3) / (3 - 1) = 3.5 -> 4 steps
  CHECK(w.ny == 2);  // (5 - 3) / (3 - 1) = 1 step
  double area = 0;
  for (const auto& s : w.windows) {
    area += s.interior.area();
    CHECK(s.grid.width() == Approx(3.0));
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
  CHECK(window_layout(Domain{0, 0, 2, 2}, Domain{0, 0, 2, 2}, 3.0, 0.5, 0.6, "k").windows.size() == 1);
  CHECK_THROWS_WITH(window_layout(canvas, canvas, 1.0, 0.5, 0.6, "method.window"), Catch::Contains("method.window"));
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
  // The initialisation it reports is the synthesised points' start (what `--init` takes
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
  // map back lands outside for some; to_output never does.
  int naive_outside = 0;
  for (int k = 1; k <= 400; ++k) {
    const double pad = 0.001 * k;
    StageWindow w;
    w.torus = false;
    w.grid = {-pad, -pad, 2 + pad, 2 + pad};
    w.movable = w.interior = {0, 0, 2, 2};
    const double side = w.grid.width();
    const double lo = static_cast<float>((0 - w.grid.x0) / side), hi = static_cast<float>((2 - w.grid.x0) / side);
    naive_outside += !w.movable.contains({w.grid.x0 + side * lo, w.grid.y0 + side * hi}, 0.0);
    for (double u : {lo, hi})
      for (double v : {lo, hi}) {
        INFO("pad " << pad << ", local " << u << ", " << v);
        CHECK(w.movable.contains(to_output(w, u, v), 0.0));
      }
  }
  CHECK(naive_outside > 0);
  StageWindow torus;  // the paper's square: positions are the output's, unchanged
  CHECK(to_output(torus, 0.25, 0.999).x == 0.25);
  CHECK(to_output(torus, 0.25, 0.999).y == 0.999);
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

TEST_CASE("no seam: where windows meet, the pattern's density and spacing are those inside the windows", "[optim][windows]") {
  // One class of 25 jittered-grid points per unit, a 8 x 3 strip in windows of 3 units with
  // the automatic margin (3 sigma_max + the 7 x 7 network's reach: about 1 unit at 32 grid
  // positions per unit): the interiors meet at several x. The points within 0.25 of a meeting
  // line against the others (both away from the output's border): density, mean
  // nearest-neighbour distance, and the share of points closer than 0.3 mean spacings.
  const PointSet ex = test::small_exemplar(1, false, 25, 0.005);
  auto method = MethodRegistry::instance().create(
      json{{"type", "gabor"}, {"window", {{"pixels", 96}}},
           {"quick", {{"res", 32}, {"channels", 8}, {"max_iterations", 30}, {"num_sigmas", 2}}}},
      "method");
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  ctx.output = shape_of(json{{"size", {8, 3}}}, ex);
  json stats;
  ctx.stats = &stats;
  const PointSet out = method->synthesize(ex, ctx);
  REQUIRE(stats["windows"]["nx"].get<int>() >= 3);
  // the meeting lines: half-way in each overlap (window_plan.cpp); recomputed from the layout
  const WindowLayout layout =
      window_layout(ctx.output.canvas(), ctx.output.moving_area(), stats["windows"]["side"], stats["windows"]["margin"], 0, "k");
  std::vector<double> seams;
  for (int i = 0; i + 1 < layout.nx; ++i) seams.push_back(layout.windows[i].interior.x1);
  std::vector<size_t> near, far;
  for (size_t i = 0; i < out.size(); ++i) {
    double dx = 1e9;
    for (double s : seams) dx = std::min(dx, std::abs(out[i].x - s));
    if (out[i].y < 0.3 || out[i].y > 2.7 || out[i].x < 0.3 || out[i].x > 7.7) continue;
    (dx < 0.25 ? near : far).push_back(i);
  }
  REQUIRE(near.size() > 50);
  const double band = 2.4, near_area = seams.size() * 0.5 * band, far_area = 7.4 * band - near_area;
  const double density_ratio = (near.size() / near_area) / (far.size() / far_area);
  const auto nn = nearest_neighbor_distances(out, false);
  double sn = 0, sf = 0;
  for (size_t i : near) sn += nn[i];
  for (size_t i : far) sf += nn[i];
  const double mean_near = sn / near.size(), mean_far = sf / far.size();
  double close_near = 0, close_far = 0;
  for (size_t i : near) close_near += nn[i] < 0.3 * mean_far;
  for (size_t i : far) close_far += nn[i] < 0.3 * mean_far;
  close_near /= near.size();
  close_far /= far.size();
  INFO("near " << near.size() << " far " << far.size() << " density " << density_ratio << " mean nn " << mean_near << " / "
               << mean_far << " close " << close_near << " / " << close_far);
  CHECK(density_ratio > 0.85);
  CHECK(density_ratio < 1.15);
  CHECK(mean_near / mean_far > 0.9);
  CHECK(mean_near / mean_far < 1.1);
  CHECK(close_near <= close_far + 0.05);
}

TEST_CASE("the window grid, the memory of an iteration, does not grow with the output", "[optim][windows]") {
  const PointSet ex = test::small_exemplar(1, false, 25, 0.005);
  GaborSettings small, large;
  const json p = [] {
    json m;
    MethodRegistry::instance().create(json{{"type", "gabor"}}, "method", &m);
    return m;
  }();
  small = resolve_gabor_settings(p, ex, shape_of(json{{"size", {4, 4}}}, ex), false);
  large = resolve_gabor_settings(p, ex, shape_of(json{{"points", 1000000}}, ex), false);
  CHECK(small.out_res == large.out_res);  // one window's grid, whatever the canvas
  CHECK(large.out_res == 384);
  // a canvas smaller than a window: the grid shrinks to it
  const GaborSettings tiny = resolve_gabor_settings(p, ex, shape_of(json{{"size", {1, 1}}}, ex), false);
  CHECK(tiny.out_res < 384);
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
