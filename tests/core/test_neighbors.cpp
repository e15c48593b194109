#include <algorithm>
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/neighbors.hpp"

using namespace ppsynth;

namespace {

std::vector<Vec2> random_points(size_t n, uint64_t seed, const Domain& d) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(d.x0, d.x1), uy(d.y0, d.y1);
  std::vector<Vec2> v;
  for (size_t i = 0; i < n; ++i) {
    double x = ux(rng);
    v.push_back({x, uy(rng)});
  }
  return v;
}

// Brute force: all distances from q, sorted.
std::vector<std::pair<double, size_t>> brute(const std::vector<Vec2>& pts, Vec2 q, const Domain& d, bool periodic) {
  std::vector<std::pair<double, size_t>> v;
  for (size_t i = 0; i < pts.size(); ++i) v.push_back({point_distance(q, pts[i], d, periodic), i});
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("NeighborIndex knn and radius match brute force", "[neighbors]") {
  const Domain d{0, 0, 2, 1};
  auto pts = random_points(300, 7, d);
  auto queries = random_points(40, 8, Domain{-0.2, -0.2, 2.2, 1.2});  // some outside: wrap
  for (bool periodic : {false, true}) {
    NeighborIndex index(pts, d, periodic);
    CHECK(index.periodic() == periodic);
    for (Vec2 q : queries) {
      auto ref = brute(pts, q, d, periodic);
      std::vector<double> dist;
      auto got = index.knn(q, 12, &dist);
      REQUIRE(got.size() == 12);
      for (size_t t = 0; t < got.size(); ++t) {
        CHECK(dist[t] == Approx(ref[t].first).margin(1e-12));
        CHECK(point_distance(q, pts[got[t]], d, periodic) == Approx(ref[t].first).margin(1e-12));
      }
      const double r = 0.15;
      auto within = index.radius(q, r, &dist);
      size_t expect = 0;
      for (auto& e : ref) expect += e.first <= r;
      CHECK(within.size() == expect);
      CHECK(std::is_sorted(dist.begin(), dist.end()));
      for (size_t t = 0; t < within.size(); ++t) CHECK(dist[t] <= r);
    }
  }
}

TEST_CASE("NeighborIndex periodic knn returns each point once, even for large k", "[neighbors]") {
  const Domain d{};
  auto pts = random_points(20, 3, d);
  NeighborIndex index(pts, d, true);
  auto all = index.knn({0.5, 0.5}, 50);
  CHECK(all.size() == 20);
  std::sort(all.begin(), all.end());
  CHECK(std::unique(all.begin(), all.end()) == all.end());
}

TEST_CASE("nearest_other wraps on the torus and excludes the point itself", "[neighbors]") {
  std::vector<Vec2> pts = {{0.02, 0.5}, {0.97, 0.5}, {0.5, 0.5}};
  NeighborIndex plane(pts), torus(pts, Domain{}, true);
  double dist = 0;
  CHECK(plane.nearest_other(0, &dist) == 2);
  CHECK(dist == Approx(0.48));
  CHECK(torus.nearest_other(0, &dist) == 1);
  CHECK(dist == Approx(0.05));
  CHECK_THROWS_AS(NeighborIndex(std::vector<Vec2>{{0.1, 0.1}}).nearest_other(0), InputError);
}
