// The evaluation suite on large inputs: every metric that `ppsynth eval` runs is
// checked against a brute-force O(N^2) reference on a few hundred random points, in the plane
// and on the torus, so the neighbor-search versions stay numerically what they were; then
// inputs that used to take minutes (exact Wasserstein on thousands of points, periodic
// nearest neighbors on 10^5 points) must come back promptly, saying what they estimated.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/chamfer.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/pcf.hpp"
#include "core/metrics/quadrant.hpp"
#include "core/metrics/wasserstein.hpp"
#include "core/neighbors.hpp"

using namespace ppsynth;

namespace {

PointSet random_set(size_t n, uint64_t seed, Domain d = {}, int classes = 1, bool radius = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(d.x0, d.x1), uy(d.y0, d.y1), ur(0.0, 1.0);
  PointSet ps(d);
  if (radius) ps.add_attribute("radius");
  for (size_t i = 0; i < n; ++i) {
    const double x = ux(rng), y = uy(rng);
    const int c = static_cast<int>(i % classes);
    if (radius) {
      // Mostly small disks, a few large ones (they reach across the torus seam).
      const double u = ur(rng);
      ps.add({x, y}, c, {u < 0.05 ? 0.25 * u / 0.05 : 0.01 * u});
    } else {
      ps.add({x, y}, c);
    }
  }
  return ps;
}

// The thesis estimator, every ordered pair, every bin (no neighbor search, no cutoff).
Curve brute_pcf(const PointSet& a, const PointSet& b, bool same, const PcfOptions& o, double r_max, double lambda2) {
  const Domain& dom = a.domain();
  const bool periodic = o.periodic || dom.periodic;
  Curve c;
  c.r.resize(o.bins);
  c.g.assign(o.bins, 0.0);
  for (int k = 0; k < o.bins; ++k) c.r[k] = o.r_min_factor + (o.r_max_factor - o.r_min_factor) * k / (o.bins - 1);
  const double sigma = o.sigma_factor * r_max;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) {
      if (same && i == j) continue;
      const double h = point_distance(a[i], b[j], dom, periodic);
      double w;
      if (periodic) {
        w = 1.0 / dom.area();
      } else {
        const double ax = dom.width() - std::abs(b[j].x - a[i].x), ay = dom.height() - std::abs(b[j].y - a[i].y);
        if (ax <= 0 || ay <= 0) continue;
        w = 1.0 / (ax * ay);
      }
      for (int k = 0; k < o.bins; ++k) {
        const double u = (c.r[k] * r_max - h) / sigma;
        if (u * u > 16) continue;
        c.g[k] += w * std::exp(-u * u) / (std::sqrt(M_PI) * sigma);
      }
    }
  for (int k = 0; k < o.bins; ++k) c.g[k] /= lambda2 * 2 * M_PI * c.r[k] * r_max;
  return c;
}

void check_curves_equal(const Curve& got, const Curve& ref) {
  REQUIRE(got.g.size() == ref.g.size());
  double scale = 0;
  for (double v : ref.g) scale = std::max(scale, std::abs(v));
  for (size_t k = 0; k < ref.g.size(); ++k) {
    INFO("bin " << k << " got " << got.g[k] << " ref " << ref.g[k]);
    CHECK(got.r[k] == ref.r[k]);
    CHECK(std::abs(got.g[k] - ref.g[k]) <= 1e-12 * scale);
  }
}

double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

std::vector<double> brute_nn(const PointSet& ps, bool periodic) {
  std::vector<double> d(ps.size(), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = 0; j < ps.size(); ++j)
      if (i != j) d[i] = std::min(d[i], point_distance(ps[i], ps[j], ps.domain(), periodic));
  return d;
}

}  // namespace

TEST_CASE("PCF by radius search equals the all-pairs estimator, plane and torus", "[metrics][scaling]") {
  const Domain dom{0, 0, 2, 1};
  const PointSet ps = random_set(400, 21, dom, 2);
  const PointSet a = ps.subset_class(0), b = ps.subset_class(1);
  for (bool periodic : {false, true})
    for (double r_max : {0.0, 0.08}) {
      INFO("periodic " << periodic << " r_max " << r_max);
      PcfOptions o;
      o.periodic = periodic;
      o.r_max = r_max;
      const double A = dom.area(), n = static_cast<double>(ps.size());
      const double rm_auto = r_max > 0 ? r_max : pcf_unit(ps.size(), A);
      check_curves_equal(pcf(ps, o), brute_pcf(ps, ps, true, o, rm_auto, n * (n - 1) / (A * A)));
      const double rm_cross = r_max > 0 ? r_max : pcf_unit(a.size() + b.size(), A);
      check_curves_equal(cross_pcf(a, b, o),
                         brute_pcf(a, b, false, o, rm_cross, static_cast<double>(a.size()) * b.size() / (A * A)));
    }
  // A domain flagged periodic in the file uses the torus estimator too.
  Domain torus = dom;
  torus.periodic = true;
  PointSet pt = ps;
  pt.set_domain(torus);
  PcfOptions o;
  const double n = static_cast<double>(pt.size()), A = torus.area();
  check_curves_equal(pcf(pt, o), brute_pcf(pt, pt, true, o, pcf_unit(pt.size(), A), n * (n - 1) / (A * A)));
}

TEST_CASE("nearest-neighbor statistics and Chamfer equal brute force, plane and torus", "[metrics][scaling]") {
  const PointSet ps = random_set(350, 22, Domain{0, 0, 1.5, 1});
  for (bool periodic : {false, true}) {
    INFO("periodic " << periodic);
    const auto d = brute_nn(ps, periodic);
    const double mean = std::accumulate(d.begin(), d.end(), 0.0) / d.size();
    CHECK(rel_diff(mean_nn_distance(ps, periodic), mean) <= 1e-12);
    CHECK(min_nn_distance(ps, periodic) == *std::min_element(d.begin(), d.end()));
  }
  const PointSet a = random_set(300, 23), b = random_set(200, 24);
  double ab = 0, ba = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    double m = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < b.size(); ++j) m = std::min(m, point_distance(a[i], b[j]));
    ab += m;
  }
  for (size_t j = 0; j < b.size(); ++j) {
    double m = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < a.size(); ++i) m = std::min(m, point_distance(a[i], b[j]));
    ba += m;
  }
  CHECK(rel_diff(chamfer_distance(a, b), ab / a.size() + ba / b.size()) <= 1e-12);
}

TEST_CASE("disk overlaps by radius search equal the all-pairs count, plane and torus", "[metrics][scaling]") {
  const PointSet ps = random_set(400, 25, Domain{}, 3, true);
  const auto& rad = ps.attribute_column(*ps.attribute_index("radius"));
  const int K = ps.num_classes();
  for (bool periodic : {false, true}) {
    INFO("periodic " << periodic);
    std::vector<std::vector<size_t>> pairs(K, std::vector<size_t>(K, 0));
    std::vector<std::vector<char>> hit(ps.size(), std::vector<char>(K, 0));
    size_t total = 0;
    for (size_t i = 0; i < ps.size(); ++i)
      for (size_t j = 0; j < ps.size(); ++j) {
        if (i == j || point_distance(ps[i], ps[j], ps.domain(), periodic) >= rad[i] + rad[j]) continue;
        hit[i][ps.cls(j)] = 1;
        if (j < i) continue;
        ++pairs[std::min(ps.cls(i), ps.cls(j))][std::max(ps.cls(i), ps.cls(j))];
        ++total;
      }
    const auto got = disk_overlaps(ps, periodic);
    REQUIRE(got.size() == 1 + static_cast<size_t>(K * (K + 1) / 2));
    CHECK(got[0].pairs == total);
    CHECK(total > 20);  // the large disks do overlap
    size_t e = 1;
    const auto counts = ps.class_counts();
    for (int a = 0; a < K; ++a)
      for (int b = a; b < K; ++b, ++e) {
        CHECK(got[e].pairs == pairs[a][b]);
        size_t pts = 0, hits = 0;
        for (size_t i = 0; i < ps.size(); ++i) {
          const int c = ps.cls(i);
          if (c != a && c != b) continue;
          ++pts;
          hits += hit[i][c == a ? b : a];
        }
        CHECK(got[e].point_fraction == Approx(static_cast<double>(hits) / pts).epsilon(1e-12));
        const double cand = a == b ? 0.5 * counts[a] * (counts[a] - 1.0) : static_cast<double>(counts[a]) * counts[b];
        CHECK(got[e].pair_fraction == Approx(pairs[a][b] / cand).epsilon(1e-12));
      }
  }
}

TEST_CASE("huge disks overlap everything without a quadratic search", "[metrics][scaling]") {
  // Two disks of radius 1e300 among 20,000 small ones: every pair with a huge disk overlaps.
  PointSet ps = random_set(20000, 26, Domain{}, 2, true);
  const int ra = *ps.attribute_index("radius");
  for (size_t i = 0; i < ps.size(); ++i) ps.set_attr(i, ra, 1e-5);
  ps.set_attr(0, ra, 1e300);
  ps.set_attr(1, ra, 1e30);
  for (bool periodic : {false, true}) {
    const auto o = disk_overlaps(ps, periodic);
    const size_t n = ps.size();
    CHECK(o[0].pairs >= 2 * (n - 2) + 1);
    CHECK(o[0].pairs < 2 * (n - 2) + 1 + 200);  // small disks rarely touch
  }
  // A negative radius is not a disk: refused, naming the point.
  ps.set_attr(5, ra, -1.0);
  CHECK_THROWS_WITH(disk_overlaps(ps), Catch::Contains("point 5"));
}

TEST_CASE("exact Wasserstein equals brute-force assignment; large sets are estimated and say so", "[metrics][scaling]") {
  // Brute force over all injections of the 6 points into the 7.
  const PointSet a = random_set(6, 27), b = random_set(7, 28);
  std::vector<size_t> perm(7);
  std::iota(perm.begin(), perm.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {
    double s = 0;
    for (size_t i = 0; i < 6; ++i) s += point_distance(a[i], b[perm[i]]);
    best = std::min(best, s / 6);
  } while (std::next_permutation(perm.begin(), perm.end()));
  CHECK(rel_diff(wasserstein_distance(a, b), best) <= 1e-12);
  CHECK(rel_diff(wasserstein_distance(b, a), best) <= 1e-12);

  // Below the exact limit the estimate IS the exact value.
  const PointSet c = random_set(300, 29), d = random_set(320, 30);
  const WassersteinResult w = wasserstein_estimate(c, d);
  CHECK(w.exact);
  CHECK(w.value == wasserstein_distance(c, d));
  // Above it: a subsample of each side keeping the size ratio, reported.
  const WassersteinResult s = wasserstein_estimate(c, d, 100 * 100);
  CHECK_FALSE(s.exact);
  CHECK(s.sample_a * s.sample_b <= 100 * 100);
  CHECK(s.sample_a >= 90);
  // Same distribution, thinner samples: larger matched distances (documented), same scale.
  CHECK(s.value > 0.8 * w.value);
  CHECK(s.value < 2.5 * w.value);
  CHECK_THROWS_WITH(wasserstein_distance(c, d, 100 * 100), Catch::Contains("exact"));
}

TEST_CASE("quadrant metrics and evaluate stay the brute-force numbers on small inputs", "[metrics][scaling]") {
  const PointSet ex = random_set(200, 31, Domain{}, 2);
  const PointSet out = random_set(800, 32, Domain{}, 2);
  for (bool periodic : {false, true}) {
    PcfOptions o;
    o.periodic = periodic;
    Curve ce, co;
    const PatchMetrics m = quadrant_metrics(ex, out, o, &ce, &co);
    // Reference: the protocol spelled out with the brute-force pieces.
    const double rm = pcf_unit(ex.size(), 1.0);
    const double ne = static_cast<double>(ex.size());
    const Curve ref_e = brute_pcf(ex, ex, true, o, rm, ne * (ne - 1));
    double mse = 0, wass = 0, ch = 0;
    std::vector<Curve> pc;
    for (const PointSet& p : quadrant_patches(out)) {
      const double np = static_cast<double>(p.size());
      pc.push_back(brute_pcf(p, p, true, o, rm, np * (np - 1)));
      mse += curve_mse(ref_e, pc.back());
      wass += wasserstein_distance(ex, p);
      ch += chamfer_distance(ex, p);
    }
    check_curves_equal(ce, ref_e);
    check_curves_equal(co, mean_curve(pc));
    CHECK(rel_diff(m.pcf_mse, mse / 4) <= 1e-10);
    CHECK(rel_diff(m.wasserstein, wass / 4) <= 1e-12);
    CHECK(rel_diff(m.chamfer, ch / 4) <= 1e-12);
    const double cross = quadrant_cross_pcf_mse(ex, out, 0, 1, o);
    EvalOptions eo;
    eo.pcf = o;
    const auto r = evaluate(ex, out, eo);
    CHECK(r["all"]["pcf_mse"].get<double>() == m.pcf_mse);
    CHECK(r["all"]["wasserstein"].get<double>() == m.wasserstein);
    CHECK(r["all"]["wasserstein_method"] == "exact");
    CHECK(r["cross"][0]["pcf_mse"].get<double>() == cross);
    const auto c1 = quadrant_metrics(ex.subset_class(1), out.subset_class(1), o);
    CHECK(r["classes"][1]["pcf_mse"].get<double>() == c1.pcf_mse);
    CHECK(r["classes"][1]["chamfer"].get<double>() == c1.chamfer);
  }
}

TEST_CASE("periodic neighbor queries on many points (and many coincident ones) are not quadratic",
          "[neighbors][scaling]") {
  // 200,000 points on the torus: each query used to clear a 200,000-entry table (4e10 bytes
  // written in all); now a query costs what it returns.
  const PointSet ps = uniform_points(200000, 33);
  const double mean = mean_nn_distance(ps, true);
  CHECK(mean == Approx(0.5 / std::sqrt(200000.0)).epsilon(0.05));  // Poisson: 1 / (2 sqrt(lambda))
  // 2,000 copies of one point: every image of it is at distance 0; each index once.
  std::vector<Vec2> same(2000, Vec2{0.3, 0.7});
  NeighborIndex idx(same, Domain{}, true);
  auto k = idx.knn({0.3, 0.7}, 5);
  std::sort(k.begin(), k.end());
  CHECK(k.size() == 5);
  CHECK(std::unique(k.begin(), k.end()) == k.end());
  std::vector<double> dist;
  auto r = idx.radius({0.3, 0.7}, 0.01, &dist);
  CHECK(r.size() == 2000);
  std::sort(r.begin(), r.end());
  CHECK(std::unique(r.begin(), r.end()) == r.end());
}

TEST_CASE("evaluate on 8,000 vs 32,000 points returns promptly with a labeled Wasserstein estimate",
          "[metrics][scaling]") {
  // The exact assignment of 8,000 x 8,000 points per quadrant needed a 512 MB cost matrix
  // and about a minute per quadrant; it is now a subsample estimate, named as such.
  const PointSet ex = jittered_grid_points(8000, 34);
  const PointSet out = uniform_points(32000, 35);
  EvalOptions o;
  o.include_curves = false;
  const auto r = evaluate(ex, out, o);
  CHECK(r["all"]["wasserstein"].is_null());
  CHECK(r["all"]["wasserstein_method"] == "subsample");
  CHECK(r["all"]["wasserstein_estimate"].get<double>() > 0);
  // Largest samples over the 4 quadrants (each quadrant within the limit on its own).
  CHECK(r["all"]["wasserstein_sample"][0].get<size_t>() * r["all"]["wasserstein_sample"][1].get<size_t>() <=
        1.05 * kWassersteinExactPairs);
  CHECK(r["all"]["wasserstein_sample"][0].get<size_t>() >= 1900);
  CHECK(r["all"]["chamfer"].get<double>() > 0);
  const std::string t = format_evaluation(r);
  CHECK(t.find("~") != std::string::npos);
  CHECK(t.find("subsample") != std::string::npos);
}

TEST_CASE("evaluate refuses domains whose squared distances overflow or underflow", "[metrics][scaling]") {
  // A 1e-310-wide domain mapped onto the unit square gave NaN positions and the assignment
  // loop never ended; a 1e300-wide one lost every neighbor ("no other point found").
  for (double side : {1e-310, 1e300}) {
    INFO("side " << side);
    PointSet ps(Domain{0, 0, side, side});
    ps.add({0, 0});
    ps.add({side, side});
    ps.add({side / 2, side / 10});
    CHECK_THROWS_WITH(evaluate(ps, ps), Catch::Contains("rescale the coordinates"));
  }
  // NaN costs are refused by the assignment itself instead of looping.
  CHECK_THROWS_AS(optimal_assignment({0.0, std::nan(""), 1.0, 2.0}, 2, 2), InputError);
  PointSet a;
  a.add({std::nan(""), 0.5});
  CHECK_THROWS_AS(wasserstein_distance(a, a), InputError);
}
