#include <catch2/catch.hpp>

#include "models/feature_grid.hpp"
#include "models/gabor_feature_maps.hpp"

#include <functional>

using namespace ppsynth;

namespace {
torch::Tensor random_points(int n, uint64_t seed) {
  auto g = at::detail::createCPUGenerator(seed);
  return at::rand({n, 2}, g, torch::kFloat64);
}

// Largest |analytic - central difference| over all coordinates of pts, and largest |gradient|.
std::pair<double, double> gradient_vs_finite_differences(const std::function<torch::Tensor(const torch::Tensor&)>& f,
                                                        const torch::Tensor& pts) {
  auto p = pts.clone().set_requires_grad(true);
  f(p).backward();
  auto analytic = p.grad().clone();
  const double h = 1e-6;
  double max_err = 0, max_grad = 0;
  for (int64_t i = 0; i < pts.size(0); ++i)
    for (int c = 0; c < 2; ++c) {
      auto pp = pts.clone(), pm = pts.clone();
      pp[i][c] += h;
      pm[i][c] -= h;
      double fd = (f(pp).item<double>() - f(pm).item<double>()) / (2 * h);
      max_err = std::max(max_err, std::abs(fd - analytic[i][c].item<double>()));
      max_grad = std::max(max_grad, std::abs(fd));
    }
  return {max_err, max_grad};
}
}  // namespace

TEST_CASE("Gabor maps equal a brute-force evaluation of Eq. 5", "[models][gabor]") {
  const int n = 12, res = 9;
  auto pts = random_points(n, 1);
  auto g = at::detail::createCPUGenerator(2);
  auto w = at::rand({n, 2}, g, torch::kFloat64) + 0.1;
  for (int A : {0, 1, 2})
    for (bool spatial_only : {false, true})
      for (int k : {5, n}) {
        GaborMapsOptions o;
        o.res = res;
        o.upscale = 2;
        o.k = k;
        o.spatial_only = spatial_only;
        GaborFeatureMaps maps(o);
        auto wa = A == 0 ? torch::Tensor() : w.narrow(1, 0, A);
        auto fast = maps->forward(pts, wa, 0.15, {});
        auto grid = torch::from_blob(FeatureGrid{res}.positions().data(), {res * res, 2}, torch::kFloat32).to(torch::kFloat64);
        auto ref = gabor_maps_reference(pts, wa, grid, 0.15 / 2, 1.5 * 2, k, gabor_channels(A, spatial_only));
        INFO("A=" << A << " spatial_only=" << spatial_only << " k=" << k);
        REQUIRE(fast.size(1) == static_cast<int64_t>(gabor_channels(A, spatial_only).size()));
        CHECK(torch::allclose(fast.view({fast.size(1), -1}), ref, 1e-12, 1e-12));
      }
}

TEST_CASE("Gabor maps gradient matches finite differences (double)", "[models][gabor]") {
  const int n = 7, res = 8;
  auto pts = random_points(n, 3);
  auto g = at::detail::createCPUGenerator(4);
  auto w = at::rand({n, 2}, g, torch::kFloat64) + 0.1;
  for (int A : {0, 1, 2}) {
    GaborMapsOptions o;
    o.res = res;
    o.k = n;  // all neighbors: the map is smooth in the positions
    GaborFeatureMaps maps(o);
    auto wa = A == 0 ? torch::Tensor() : w.narrow(1, 0, A);
    auto probe = at::randn({1, maps->channels(A), res, res}, g, torch::kFloat64);
    auto f = [&](const torch::Tensor& p) { return (maps->forward(p, wa, 0.2, {}) * probe).sum(); };
    auto [max_err, max_grad] = gradient_vs_finite_differences(f, pts);
    INFO("A=" << A << " max |grad| " << max_grad);
    CHECK(max_grad > 1e-3);
    CHECK(max_err < 1e-6 * std::max(1.0, max_grad));
  }
}

TEST_CASE("Gabor maps: shapes, channel counts, zoom-out grid", "[models][gabor]") {
  CHECK(gabor_channels(0, false).size() == 10);
  CHECK(gabor_channels(1, false).size() == 10);
  CHECK(gabor_channels(2, false).size() == 19);
  CHECK(gabor_channels(0, true).size() == 1);
  GaborMapsOptions o;
  o.res = 16;
  o.upscale = 2;
  o.k = 4;
  GaborFeatureMaps maps(o);
  auto m = maps->forward(random_points(20, 5).to(torch::kFloat32), {}, 0.1, {});
  CHECK(m.sizes() == torch::IntArrayRef({1, 10, 16, 16}));
  // Grid: b = 1/(res+1), x along columns.
  FeatureGrid grid{16};
  auto pos = grid.positions();
  CHECK(pos[0] == Approx(1.0 / 17));
  CHECK(pos[2] > pos[0]);                 // next column: x grows
  CHECK(pos[2 * 16 + 1] > pos[1]);        // next row: y grows
  CHECK(grid_resolution_for(0.1) == 128);  // round(90) clamped up
  CHECK(grid_resolution_for(0.05) == 180);
  CHECK(grid_resolution_for(0.01) == 256);
  // A single point: the spatial map peaks at the pixel nearest to it.
  auto one = torch::tensor({{0.7, 0.2}}, torch::kFloat64);
  GaborMapsOptions o1;
  o1.res = 33;
  o1.k = 1;
  auto m1 = GaborFeatureMaps(o1)->forward(one, {}, 0.05, {})[0][0];
  auto am = m1.argmax().item<int64_t>();
  CHECK(am % 33 == static_cast<int64_t>(std::lround((0.7 - 1.0 / 34) / (1 - 2.0 / 34) * 32)));  // column = x
  CHECK(am / 33 == static_cast<int64_t>(std::lround((0.2 - 1.0 / 34) / (1 - 2.0 / 34) * 32)));  // row = y
}

TEST_CASE("Periodic Gabor maps see the nearest image of each point across the border", "[models][gabor]") {
  // A point near the corner (0.995, 0.985): on the torus its images at x - 1 and y - 1 are the
  // ones grid positions near x = 0 / y = 0 see. For a small sigma every grid position sees at
  // most one image with non-negligible weight, so the periodic map of the one point (k = 1)
  // equals 4 x the plane map of its four images (k = 4). u = 1 (f = 1.5, not an integer) so
  // the phase of the wrapped terms must be rotated, not merely re-used.
  const double x = 0.995, y = 0.985, sigma = 0.04;
  auto one = torch::tensor({{x, y}}, torch::kFloat64);
  auto images = torch::tensor({{x, y}, {x - 1, y}, {x, y - 1}, {x - 1, y - 1}}, torch::kFloat64);
  for (double u : {1.0, 2.0}) {
    GaborMapsOptions op;
    op.res = 24;
    op.upscale = u;
    op.k = 1;
    op.periodic = true;
    GaborMapsOptions oq = op;
    oq.k = 4;
    oq.periodic = false;
    auto periodic = GaborFeatureMaps(op)->forward(one, {}, sigma, {});
    auto plane = GaborFeatureMaps(oq)->forward(images, {}, sigma, {});
    INFO("u = " << u);
    CHECK(torch::allclose(periodic, 4 * plane, 1e-9, 1e-9));
    // Grid positions near x = 0 do see the point: not a vacuous comparison.
    CHECK(periodic[0][0][0][0].item<double>() > 1e-3);
    // The plane maps of the point alone do not reach the opposite corner.
    auto alone = GaborFeatureMaps(oq)->forward(one, {}, sigma, {});
    CHECK(alone[0][0][0][0].item<double>() < 1e-6);
  }
}

TEST_CASE("Periodic Gabor maps gradient matches finite differences near the border", "[models][gabor]") {
  // Points within a sigma of the border, so terms across the wrap carry gradient.
  auto pts = torch::tensor({{0.01, 0.5}, {0.98, 0.52}, {0.5, 0.995}, {0.47, 0.02}, {0.985, 0.015}}, torch::kFloat64);
  const int n = 5, res = 10;
  auto g = at::detail::createCPUGenerator(6);
  for (double u : {1.0, 2.0}) {
    GaborMapsOptions o;
    o.res = res;
    o.upscale = u;
    o.k = n;
    o.periodic = true;
    GaborFeatureMaps maps(o);
    auto probe = at::randn({1, maps->channels(0), res, res}, g, torch::kFloat64);
    auto f = [&](const torch::Tensor& p) { return (maps->forward(p, {}, 0.15, {}) * probe).sum(); };
    auto [max_err, max_grad] = gradient_vs_finite_differences(f, pts);
    INFO("u = " << u << " max |grad| " << max_grad);
    CHECK(max_grad > 1e-3);
    CHECK(max_err < 1e-6 * std::max(1.0, max_grad));
  }
}

TEST_CASE("Rectangle Gabor maps: rows at the columns' spacing, each position the square grid's", "[models][gabor]") {
  // A grid of 12 columns and 7 rows is the first 7 rows of the 12 x 12 square's positions, and
  // its maps those rows of the square's maps, bit for bit; 12 x 19 runs past y = 1 at the same
  // spacing and equals Eq. 5 there.
  CHECK(grid_rows(12, 1.0) == 12);
  CHECK(grid_rows(12, 0.5) == 6);  // 13 x 0.5 - 1 = 5.5 spacings up
  CHECK(grid_rows(662, 414.0 / 662) == 414);
  auto pts = random_points(30, 7) * torch::tensor({{1.0, 1.6}}, torch::kFloat64);
  GaborMapsOptions square;
  square.res = 12;
  square.upscale = 2;
  square.k = 6;
  GaborMapsOptions wide = square, tall = square;
  wide.rows = 7;
  tall.rows = 19;
  auto s = GaborFeatureMaps(square)->forward(pts, {}, 0.15, {});
  auto w = GaborFeatureMaps(wide)->forward(pts, {}, 0.15, {});
  auto t = GaborFeatureMaps(tall)->forward(pts, {}, 0.15, {});
  CHECK(w.sizes() == torch::IntArrayRef({1, 10, 7, 12}));
  CHECK(t.sizes() == torch::IntArrayRef({1, 10, 19, 12}));
  CHECK(torch::equal(w, s.narrow(2, 0, 7)));
  CHECK(torch::equal(t.narrow(2, 0, 12), s));
  const FeatureGrid tall_grid{12, 19};
  auto grid = torch::from_blob(tall_grid.positions().data(), {19 * 12, 2}, torch::kFloat32).to(torch::kFloat64);
  CHECK(grid[19 * 12 - 1][1].item<double>() == Approx(19.0 / 13));  // the last row, 19 spacings up
  auto ref = gabor_maps_reference(pts, {}, grid, 0.15 / 2, 1.5 * 2, 6, gabor_channels(0, false));
  CHECK(torch::allclose(t.view({10, -1}), ref, 1e-12, 1e-12));
}
