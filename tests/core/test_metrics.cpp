#include <cmath>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/chamfer.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/pcf.hpp"
#include "core/metrics/quadrant.hpp"
#include "core/metrics/spectrum.hpp"
#include "core/metrics/wasserstein.hpp"

using namespace ppsynth;

namespace {
PointSet make(std::initializer_list<Vec2> pts, Domain d = {}) {
  PointSet ps(d);
  for (auto p : pts) ps.add(p);
  return ps;
}
}  // namespace

TEST_CASE("PCF of uniform points is about 1", "[metrics]") {
  for (bool periodic : {false, true}) {
    PointSet ps = uniform_points(2000, periodic ? 5 : 6);
    PcfOptions o;
    o.periodic = periodic;
    Curve c = pcf(ps, o);
    REQUIRE(c.r.size() == 100);
    CHECK(c.r.front() == Approx(0.01));
    CHECK(c.r.back() == Approx(2.5));
    for (size_t k = 0; k < c.r.size(); ++k)
      if (c.r[k] >= 0.5) {
        INFO("periodic " << periodic << " r " << c.r[k]);
        CHECK(std::abs(c.g[k] - 1.0) < 0.1);
      }
  }
}

TEST_CASE("PCF of a jittered grid has a gap at small radii", "[metrics]") {
  Curve c = pcf(jittered_grid_points(400, 3, Domain{}, 0.5));
  CHECK(c.g[0] < 0.05);  // half-jittered cells: no pairs closer than half a cell
  Curve u = pcf(uniform_points(400, 3));
  CHECK(curve_mse(c, u) > 0.05);
}

TEST_CASE("relative radius of a perfect hexagonal lattice is 1", "[metrics]") {
  for (auto [cols, rows] : {std::pair<size_t, size_t>{10, 12}, {16, 18}}) {
    PointSet ps = hexagonal_lattice_exact(cols, rows, hexagonal_domain(cols, rows));
    CHECK(relative_radius(ps) == Approx(1.0).margin(1e-3));
  }
  // relative radius uses toroidal distances: two points across the border are close.
  PointSet ps = make({{0.001, 0.5}, {0.999, 0.5}, {0.5, 0.2}});
  CHECK(min_nn_distance(ps, true) == Approx(0.002));
  CHECK(min_nn_distance(ps, false) > 0.3);
  CHECK(relative_radius(ps) == Approx(0.001 / packing_radius(3)));
  CHECK_THROWS_AS(relative_radius(make({{0.5, 0.5}})), InputError);
}

TEST_CASE("Wasserstein of a shifted copy equals the shift", "[metrics]") {
  PointSet a = uniform_points(120, 9, Domain{0.1, 0.1, 0.9, 0.9});
  PointSet b = a;
  const double tx = 0.01, ty = -0.005;
  for (auto& p : b.positions()) p = {p.x + tx, p.y + ty};
  CHECK(wasserstein_distance(a, b) == Approx(std::hypot(tx, ty)).epsilon(1e-9));
  CHECK(wasserstein_distance(a, a) == Approx(0).margin(1e-12));
}

TEST_CASE("Wasserstein: hand-computed assignments, unequal sizes", "[metrics]") {
  // Greedy would match (0,0)-(0.1,0) and leave (1,0) to (0.2,0)... optimal crosses.
  PointSet a = make({{0, 0}, {0.2, 0}});
  PointSet b = make({{0.1, 0}, {0.3, 0}});
  CHECK(wasserstein_distance(a, b) == Approx(0.1));
  // Smaller set matched into the larger one: the surplus (0.9, 0.9) is ignored.
  PointSet c = make({{0.1, 0}, {0.3, 0}, {0.9, 0.9}});
  CHECK(wasserstein_distance(a, c) == Approx(0.1));
  CHECK(wasserstein_distance(c, a) == Approx(0.1));
  std::vector<double> cost = {4, 1, 3, 2, 0, 5, 3, 2, 2};
  auto m = optimal_assignment(cost, 3, 3);
  CHECK(cost[0 * 3 + m[0]] + cost[1 * 3 + m[1]] + cost[2 * 3 + m[2]] == Approx(5));
  CHECK_THROWS_AS(wasserstein_distance(a, PointSet{}), InputError);
}

TEST_CASE("Chamfer: hand-computed case", "[metrics]") {
  PointSet a = make({{0, 0}, {1, 0}});
  PointSet b = make({{0, 0.5}});
  // a->b: (0.5 + sqrt(1.25)) / 2; b->a: 0.5.
  CHECK(directed_chamfer(a, b) == Approx((0.5 + std::sqrt(1.25)) / 2));
  CHECK(directed_chamfer(b, a) == Approx(0.5));
  CHECK(chamfer_distance(a, b) == Approx((0.5 + std::sqrt(1.25)) / 2 + 0.5));
  CHECK(chamfer_distance(a, a) == 0);
}

TEST_CASE("quadrant split: each point lands in one patch, rescaled", "[metrics]") {
  PointSet out = make({{0.1, 0.2}, {0.6, 0.2}, {0.2, 0.7}, {0.75, 0.9}, {0.5, 0.5}, {1.0, 1.0}});
  auto q = quadrant_patches(out);
  REQUIRE(q.size() == 4);
  CHECK(q[0].size() == 1);
  CHECK(q[1].size() == 1);
  CHECK(q[2].size() == 1);
  CHECK(q[3].size() == 3);  // (0.75,0.9), (0.5,0.5) on the half-open edge, (1,1) on the far edge
  CHECK(q[0][0].x == Approx(0.2));
  CHECK(q[0][0].y == Approx(0.4));
  CHECK(q[1][0].x == Approx(0.2));
  CHECK(q[2][0].y == Approx(0.4));
  // An output made of 4 scaled copies of the exemplar matches it exactly.
  PointSet ex = uniform_points(50, 4);
  PointSet tiled;
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx)
      for (const auto& p : ex.positions()) tiled.add({0.5 * (p.x + qx), 0.5 * (p.y + qy)});
  PatchMetrics m = quadrant_metrics(ex, tiled);
  CHECK(m.pcf_mse == Approx(0).margin(1e-12));
  CHECK(m.wasserstein == Approx(0).margin(1e-9));
  CHECK(m.chamfer == Approx(0).margin(1e-9));
  PatchMetrics u = quadrant_metrics(ex, uniform_points(200, 5));
  CHECK(u.wasserstein > 0.01);
  CHECK(u.chamfer > 0.01);
  CHECK(u.pcf_mse > 0);
}

TEST_CASE("spectrum: white noise is flat, lattice is peaked", "[metrics]") {
  Spectrum s = power_spectrum(uniform_points(500, 2), 16);
  REQUIRE(s.image.width == 33);
  CHECK(s.image.pixels[16 * 33 + 16] == Approx(500).epsilon(1e-6));  // f = 0: P = N
  double mean = 0;
  for (int k = 4; k <= 16; ++k) mean += s.radial_power[k];
  CHECK(mean / 13 == Approx(1).margin(0.25));
  Spectrum g = power_spectrum(regular_grid_points(100, 0), 12);  // 10x10 grid: peaks at |f| = 10
  CHECK(g.image.pixels[12 * 25 + 22] == Approx(100).epsilon(1e-6));  // f = (10, 0): P = N
  CHECK(g.radial_power[10] > 5);
  CHECK(g.radial_power[3] < 1e-6);
  CHECK(g.anisotropy[10] > 1);
}

TEST_CASE("disk overlap counts pairs per class pair", "[metrics]") {
  PointSet ps;
  ps.add_attribute("radius");
  ps.add({0.1, 0.1}, 0, {0.05});
  ps.add({0.18, 0.1}, 0, {0.05});  // overlaps the first
  ps.add({0.5, 0.5}, 1, {0.02});
  ps.add({0.53, 0.5}, 0, {0.02});  // touches class 1 at 0.03 < 0.04
  ps.add({0.9, 0.9}, 1, {0.01});
  auto o = disk_overlaps(ps);
  REQUIRE(o.size() == 4);  // all, (0,0), (0,1), (1,1)
  CHECK(o[0].pairs == 2);
  CHECK(o[1].pairs == 1);
  CHECK(o[1].pair_fraction == Approx(1.0 / 3));
  CHECK(o[2].pairs == 1);
  CHECK(o[2].pair_fraction == Approx(1.0 / 6));
  CHECK(o[3].pairs == 0);
  CHECK_THROWS_AS(disk_overlaps(uniform_points(5, 1)), InputError);
}
