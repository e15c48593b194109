// The Gabor maps' backward sums each point's gradient (models/per_point_sum.hpp): the gather
// over the inverse neighbor list, which a deterministic CUDA run takes, against index_add, on
// the CPU (and on CUDA where this process sees a card: tagged [device] for scripts/gpu_check.sh).
#include <catch2/catch.hpp>

#include <ATen/Context.h>
#include <torch/cuda.h>

#include "models/gabor_feature_maps.hpp"
#include "models/per_point_sum.hpp"

using namespace ppsynth;

namespace {

// Grid positions' k nearest points, as the maps' backward gets them, with a few points far
// from the rest (each the neighbor of many positions) and one no position names.
struct Case {
  torch::Tensor values, point;
  int64_t n = 0;
};

Case knn_case(torch::Dtype dtype, const torch::Device& device) {
  auto g = at::detail::createCPUGenerator(7);
  auto pts = at::rand({300, 2}, g, torch::kFloat64) * 0.5;  // a cluster in one corner...
  pts[0][0] = 0.95, pts[0][1] = 0.95;                        // ...and a point alone in the void
  pts[1][0] = 5.0, pts[1][1] = 5.0;                          // one no grid position reaches
  const int res = 48, k = 12;
  auto grid = torch::stack(torch::meshgrid({torch::arange(res, torch::kFloat64), torch::arange(res, torch::kFloat64)}), 2)
                  .reshape({-1, 2}) / res;
  const auto idx = grid_knn_tensor_ops(pts, grid, k);
  Case c;
  c.point = idx.reshape({-1}).to(device);
  c.values = (at::rand({c.point.size(0), 2}, g, torch::kFloat64) - 0.5).to(dtype).to(device);
  c.n = pts.size(0);
  return c;
}

void check_gather(const torch::Device& device) {
  for (auto dtype : {torch::kFloat64, torch::kFloat32}) {
    const Case c = knn_case(dtype, device);
    const auto scattered = sum_per_point(c.values, c.point, c.n, PointSumMethod::scatter);
    const auto gathered = sum_per_point(c.values, c.point, c.n, PointSumMethod::gather);
    CHECK(gathered.sizes() == scattered.sizes());
    CHECK(gathered.scalar_type() == dtype);
    CHECK(torch::allclose(gathered, scattered, dtype == torch::kFloat64 ? 1e-12 : 1e-5, dtype == torch::kFloat64 ? 1e-12 : 1e-5));
    CHECK(gathered[1].abs().sum().item<double>() == 0);  // the point nobody names
    CHECK(torch::equal(gathered, sum_per_point(c.values, c.point, c.n, PointSumMethod::gather)));  // the same bits twice
  }
}

}  // namespace

TEST_CASE("The per-point gather gives index_add's sums, the same bits on every call", "[maps_backward]") {
  check_gather(torch::kCPU);
  // Uneven runs in blocks of points: one point named 30000 times among 2000.
  auto g = at::detail::createCPUGenerator(3);
  auto point = at::randint(0, 2000, {40000}, g, torch::kLong);
  point.slice(0, 0, 30000).fill_(17);
  const auto values = at::rand({40000, 3}, g, torch::kFloat64);
  CHECK(torch::allclose(sum_per_point(values, point, 2000, PointSumMethod::gather),
                        sum_per_point(values, point, 2000, PointSumMethod::scatter), 1e-12, 1e-9));
  // Nothing to sum.
  CHECK(sum_per_point(torch::zeros({0, 2}), torch::zeros({0}, torch::kLong), 5, PointSumMethod::gather).abs().sum().item<double>() == 0);
}

TEST_CASE("The maps' backward gathers on CUDA in deterministic mode and keeps index_add elsewhere", "[maps_backward]") {
  auto& context = at::globalContext();
  const bool was = context.deterministicAlgorithms(), warned = context.deterministicAlgorithmsWarnOnly();
  context.setDeterministicAlgorithms(true, true);
  CHECK(point_sum_method(torch::Device("cuda:0")) == PointSumMethod::gather);
  CHECK(point_sum_method(torch::kCPU) == PointSumMethod::scatter);  // index_add is sequential there, and faster
  context.setDeterministicAlgorithms(false, false);
  CHECK(point_sum_method(torch::Device("cuda:0")) == PointSumMethod::scatter);
  context.setDeterministicAlgorithms(was, warned);
}

TEST_CASE("On CUDA, the per-point gather gives index_add's sums, the same bits twice", "[maps_backward][device][cuda]") {
  if (!torch::cuda::is_available()) {
    WARN("skipped (no CUDA device)");
    return;
  }
  check_gather(torch::Device("cuda:0"));
}
