#include <catch2/catch.hpp>

#include "models/feature_grid.hpp"
#include "models/gabor_feature_maps.hpp"

using namespace ppsynth;

namespace {
torch::Tensor random_points(int n, uint64_t seed) {
  auto g = at::detail::createCPUGenerator(seed);
  return at::rand({n, 2}, g, torch::kFloat64);
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
    o.k = n;  // all neighbours: the map is smooth in the positions
    GaborFeatureMaps maps(o);
    auto wa = A == 0 ? torch::Tensor() : w.narrow(1, 0, A);
    auto probe = at::randn({1, maps->channels(A), res, res}, g, torch::kFloat64);
    auto f = [&](const torch::Tensor& p) { return (maps->forward(p, wa, 0.2, {}) * probe).sum(); };
    auto p = pts.clone().set_requires_grad(true);
    f(p).backward();
    auto analytic = p.grad().clone();
    const double h = 1e-6;
    double max_err = 0, max_grad = 0;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c) {
        auto pp = pts.clone(), pm = pts.clone();
        pp[i][c] += h;
        pm[i][c] -= h;
        double fd = (f(pp).item<double>() - f(pm).item<double>()) / (2 * h);
        max_err = std::max(max_err, std::abs(fd - analytic[i][c].item<double>()));
        max_grad = std::max(max_grad, std::abs(fd));
      }
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
