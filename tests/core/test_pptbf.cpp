// PPTBF (Guehl et al. 2020, supplement #4): hand-computed values of simple configurations,
// determinism, tilings that partition the plane, nearest-point queries, mixture models,
// config validation, point exemplars.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/procedural/pptbf.hpp"
#include "core/procedural/pptbf_points.hpp"

using namespace ppsynth;
using namespace ppsynth::pptbf_impl;

namespace {
// Regular grid, no jitter, zoom 1: feature points at (i + 0.5, j + 0.5), cells the unit squares.
PptbfParams simple_grid() {
  PptbfParams p;
  p.zoom = 1;
  p.tile_type = 0;
  p.jitter = 0;
  p.mixture = 0;
  return p;
}
double w2_term(double d, double sig) { return std::max(0.0, std::exp(-sig * d) - std::exp(-sig * 1.5)); }
}  // namespace

TEST_CASE("pptbf: clamped exponential window w2 matches the hand value", "[pptbf]") {
  PptbfParams p = simple_grid();
  p.normblend = 0;  // w2 only
  p.sigw2 = 2;
  // at a feature point: itself (d=0), 4 edge neighbors (d=1), 4 diagonal (d=sqrt 2 < 1.5)
  const double at_point = (1 - std::exp(-3.0)) + 4 * (std::exp(-2.0) - std::exp(-3.0)) +
                          4 * (std::exp(-2 * std::sqrt(2.0)) - std::exp(-3.0));
  CHECK(pptbf(p, 0.5, 0.5) == Approx(at_point).epsilon(1e-9));
  // at (0.25, 0.5): distances 0.25, 0.75, 1.25, 2 x sqrt(0.25^2+1), 2 x sqrt(0.75^2+1)
  const double d1 = std::sqrt(0.0625 + 1), d2 = std::sqrt(0.5625 + 1);
  const double hand = w2_term(0.25, 2) + w2_term(0.75, 2) + w2_term(1.25, 2) + 2 * w2_term(d1, 2) + 2 * w2_term(d2, 2);
  CHECK(pptbf(p, 0.25, 0.5) == Approx(hand).epsilon(1e-9));
  // a translated copy (other cell) gives the same value: the grid is periodic
  CHECK(pptbf(p, 3.25, -6.5) == Approx(hand).epsilon(1e-9));
}

TEST_CASE("pptbf: cellular window w1 follows the cell border", "[pptbf]") {
  PptbfParams p = simple_grid();
  p.normblend = 1;  // w1 only
  p.sigw1 = 3;
  p.wsmooth = 0;  // exact cell border
  auto w1 = [](double cv) { return std::exp((cv - 1) * 3.0) - std::exp(-3.0); };
  // border of the unit cell at 0.5 along +x: cv = 1 - 0.25/0.5; along the diagonal 1 - 0.2/0.5
  for (double larp : {0.0, 1.0}) {
    for (double norm : {2.0, 1.0}) {
      p.larp = larp;
      p.norm = norm;
      INFO("larp " << larp << " norm " << norm);
      CHECK(pptbf(p, 0.75, 0.5) == Approx(w1(0.5)).margin(1e-6));
      CHECK(pptbf(p, 0.7, 0.7) == Approx(w1(0.6)).margin(1e-6));
      CHECK(pptbf(p, 0.5, 0.5) == Approx(w1(1.0)).margin(1e-9));
    }
  }
  // an inscribed 64-gon is close to the exact cell
  p.larp = 0;
  p.norm = 2;
  p.jitter = 0.8;
  p.tile_type = 6;
  PptbfParams poly = p;
  poly.wsmooth = 1;
  poly.arity = 64;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 4);
  for (int i = 0; i < 50; ++i) {
    const double x = U(rng), y = U(rng);
    CHECK(pptbf(poly, x, y) == Approx(pptbf(p, x, y)).margin(0.03));
  }
}

TEST_CASE("pptbf: normalized-sum and max mixtures match hand values", "[pptbf]") {
  PptbfParams p = simple_grid();
  p.normblend = 0;
  p.sigw2 = 2;
  p.Jmin = p.Jmax = 1;
  p.winfeatcorrel = 1;  // kernel on the feature point
  p.sigcos = 1.5;       // fdist = |x - p| / (1.5 / 1.5)
  p.freq = 0;
  p.mixture = 2;
  const double at_point = (1 - std::exp(-3.0)) + 4 * (std::exp(-2.0) - std::exp(-3.0)) * std::exp(-1.0) +
                          4 * (std::exp(-2 * std::sqrt(2.0)) - std::exp(-3.0)) * std::exp(-std::sqrt(2.0));
  CHECK(pptbf(p, 0.5, 0.5) == Approx(at_point).epsilon(1e-9));
  p.mixture = 3;  // 1 - sum
  const double carved = 4 * (std::exp(-2.0) - std::exp(-3.0)) * (1 - std::exp(-1.0)) +
                        4 * (std::exp(-2 * std::sqrt(2.0)) - std::exp(-3.0)) * (1 - std::exp(-std::sqrt(2.0)));
  CHECK(pptbf(p, 0.5, 0.5) == Approx(carved).epsilon(1e-9));
  p.mixture = 5;  // max of exp(-|x - p|): the nearest point
  CHECK(pptbf(p, 0.6, 0.5) == Approx(std::exp(-0.1)).epsilon(1e-12));
  p.mixture = 4;  // highest-priority kernel with fdist < 1: own (0.1) or right neighbor (0.9)
  const double v = pptbf(p, 0.6, 0.5);
  CHECK((v == Approx(std::exp(-0.1)) || v == Approx(std::exp(-0.9))));
}

TEST_CASE("pptbf: every mixture model and tiling gives finite values", "[pptbf]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  for (int mixture = 0; mixture <= 5; ++mixture)
    for (int tile : {0, 3, 6, 11, 14, 17}) {
      PptbfParams p;
      p.mixture = mixture;
      p.tile_type = tile;
      p.Jmin = 2;
      p.Jmax = 5;
      p.freq = 3;
      p.thickness = 0.4;
      p.deltaorient = 1.0;
      p.feataniso = 2;
      p.wsmooth = 1.5;
      p.larp = 0.3;
      p.ampli = {0.02, 1, 0.5};
      PptbfEvaluator ev(p);
      for (int i = 0; i < 40; ++i) {
        const double v = ev(U(rng), U(rng));
        INFO("mixture " << mixture << " tile " << tile);
        REQUIRE(std::isfinite(v));
      }
    }
}

TEST_CASE("pptbf: deterministic by seed, independent of threads and caches", "[pptbf]") {
  PptbfParams p;
  p.tile_type = 3;  // relaxation exercises the cell cache
  p.mixture = 1;
  p.Jmin = 2;
  p.Jmax = 4;
  p.wsmooth = 2;
  p.normblend = 0.7;
  p.seed = 7;
  const GrayImage a = render_pptbf(p, 40, 40, Domain{}, 1);
  const GrayImage b = render_pptbf(p, 40, 40, Domain{}, 2);
  CHECK(a.pixels == b.pixels);
  // a fresh evaluator per value equals the cached one
  PptbfEvaluator ev(p);
  for (int r : {3, 17, 31})
    for (int c : {0, 20, 39}) {
      const double x = (c + 0.5) / 40, y = 1 - (r + 0.5) / 40;
      CHECK(ev(x, y) == Approx(a.pixels[r * 40 + c]).epsilon(1e-6));
      CHECK(pptbf(p, x, y) == Approx(a.pixels[r * 40 + c]).epsilon(1e-6));
    }
  p.seed = 8;
  const GrayImage c = render_pptbf(p, 40, 40, Domain{}, 2);
  CHECK(a.pixels != c.pixels);
}

TEST_CASE("pptbf: each tiling partitions the plane into its cells", "[pptbf]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-5, 5);
  for (int t = 0; t < kNumTileTypes; ++t) {
    INFO("tile_type " << t << " " << tiling_spec(t).name);
    PointProcess pp(t, 1.0, 42);
    for (int i = 0; i < 300; ++i) {
      const Vec2 x{U(rng), U(rng)};
      std::vector<BaseCell> cells;
      pp.base_cells_in_box(Rect{{x.x - 1e-7, x.y - 1e-7}, {x.x + 1e-7, x.y + 1e-7}}, cells);
      int containing = 0;
      for (const BaseCell& c : cells) {
        if (!c.rect.contains(x)) continue;
        ++containing;
        // the subcells partition the base cell; each feature point lies in its own subcell
        int sub_containing = 0;
        double area = 0;
        for (const FeaturePoint& fp : pp.points_of(c)) {
          const Rect sr{fp.c, {fp.c.x + fp.d.x, fp.c.y + fp.d.y}};
          area += fp.d.x * fp.d.y;
          if (sr.contains(x)) ++sub_containing;
          CHECK(sr.contains(fp.p));
        }
        CHECK(sub_containing == 1);
        CHECK(area == Approx(c.rect.size().x * c.rect.size().y).epsilon(1e-9));
      }
      REQUIRE(containing == 1);
    }
  }
}

TEST_CASE("pptbf: nearest feature point query agrees with brute force", "[pptbf]") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-3, 3);
  for (int t = 0; t < kNumTileTypes; ++t) {
    INFO("tile_type " << t);
    PointProcess pp(t, 1.0, 5);
    std::vector<FeaturePoint> all;
    pp.points_in_box(Rect{{-6, -6}, {6, 6}}, all);
    for (int i = 0; i < 200; ++i) {
      const Vec2 x{U(rng), U(rng)};
      size_t best = 0;
      double bd = 1e300;
      for (size_t k = 0; k < all.size(); ++k) {
        const double d = std::hypot(all[k].p.x - x.x, all[k].p.y - x.y);
        if (d < bd) { bd = d; best = k; }
      }
      std::vector<FeaturePoint> near;
      pp.points_near(x, pp.reach(), near);
      std::vector<int> order;
      nth_closest(x, near, 2.0, 0.0, order);
      REQUIRE(!order.empty());
      CHECK(near[order[0]].key == all[best].key);
      CHECK(std::hypot(near[order[0]].p.x - x.x, near[order[0]].p.y - x.y) == Approx(bd));
    }
  }
}

TEST_CASE("pptbf: config keys are checked and named", "[pptbf]") {
  CHECK_THROWS_WITH(pptbf_params_from_json(json{{"jiter", 0.5}}, "pptbf"), Catch::Contains("pptbf.jiter"));
  CHECK_THROWS_AS(pptbf_params_from_json(json{{"jiter", 0.5}}), InputError);
  CHECK_THROWS_WITH(pptbf_params_from_json(json{{"jitter", 2.0}}), Catch::Contains("jitter"));
  CHECK_THROWS_WITH(pptbf_params_from_json(json{{"Jmin", 3}, {"Jmax", 2}}), Catch::Contains("Jmax"));
  CHECK_THROWS_WITH(pptbf_params_from_json(json{{"tile_type", 18}}), Catch::Contains("tile_type"));
  CHECK_THROWS_WITH(pptbf_params_from_json(json{{"ampli", {1, 2}}}), Catch::Contains("ampli"));
  const PptbfParams p = pptbf_params_from_json(json{{"mixture", 4}, {"Jmax", 3}});
  CHECK(p.mixture == 4);
  CHECK(p.Jmax == 3);
  CHECK(p.zoom == PptbfParams{}.zoom);
  // every shipped config loads
  const std::filesystem::path dir = std::filesystem::path(PPSYNTH_SOURCE_DIR) / "configs" / "pptbf";
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    INFO(e.path().string());
    CHECK_NOTHROW(pptbf_params_from_json(load_config(e.path().string())));
    ++n;
  }
  CHECK(n >= 5);
}

TEST_CASE("pptbf: point exemplars", "[pptbf]") {
  PptbfParams p;
  p.zoom = 10;
  p.jitter = 0;
  // (a) regular grid without jitter: the 10 x 10 cell centers
  PointSet grid = pptbf_process_points(p);
  REQUIRE(grid.size() == 100);
  for (const Vec2& q : grid.positions()) {
    CHECK(std::abs(q.x * 10 - 0.5 - std::round(q.x * 10 - 0.5)) < 1e-9);
    CHECK(std::abs(q.y * 10 - 0.5 - std::round(q.y * 10 - 0.5)) < 1e-9);
  }
  p.tile_type = 7;
  p.jitter = 0.7;
  p.rotation = 0.3;
  PointSet proc = pptbf_process_points(p);
  CHECK(proc.size() > 80);
  for (const Vec2& q : proc.positions()) CHECK((q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1));
  {  // the process points are where the cellular window peaks (cv = 1 at the feature point)
    PptbfParams w = p;
    w.normblend = 1;
    w.mixture = 0;
    w.sigw1 = 2;
    PptbfEvaluator wev(w);
    for (const Vec2& q : proc.positions()) CHECK(wev(q.x, q.y) == Approx(1 - std::exp(-2.0)).epsilon(1e-6));
  }
  // (b) thresholded dart throwing: every point above the threshold and min_dist apart
  p.mixture = 2;
  ThresholdSampling s;
  s.n = 150;
  s.threshold = pptbf_quantile(p, 0.5, 64);
  s.min_dist = 0.02;
  s.seed = 4;
  PointSet th = pptbf_threshold_points(p, s);
  CHECK(th.size() == 150);
  PptbfEvaluator ev(p);
  for (size_t i = 0; i < th.size(); ++i) {
    CHECK(ev(th[i].x, th[i].y) > s.threshold);
    for (size_t j = 0; j < i; ++j) CHECK(std::hypot(th[i].x - th[j].x, th[i].y - th[j].y) >= s.min_dist);
  }
  PointSet again = pptbf_threshold_points(p, s);
  CHECK(again.flat_xy() == th.flat_xy());
}
