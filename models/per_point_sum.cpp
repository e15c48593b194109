#include "models/per_point_sum.hpp"

#include <ATen/Context.h>

#include <algorithm>

namespace ppsynth {

PointSumMethod point_sum_method(const torch::Device& device) {
  return device.is_cuda() && at::globalContext().deterministicAlgorithms() ? PointSumMethod::gather : PointSumMethod::scatter;
}

namespace {

torch::Tensor gather_sum(const torch::Tensor& values, const torch::Tensor& point, int64_t n) {
  const int64_t M = point.size(0), D = values.size(1);
  auto out = torch::zeros({n, D}, values.options());
  if (M == 0 || n == 0) return out;
  const auto idx = point.to(torch::kLong);
  // Stable: a point's values keep their order (grid position, then neighbor rank) on every run.
  const auto sorted = torch::sort(idx, /*stable=*/true, /*dim=*/0, /*descending=*/false);
  const auto& by_point = std::get<0>(sorted);
  const auto& order = std::get<1>(sorted);
  // A zero row at index M: the padding of the shorter runs reads it.
  const auto padded = torch::cat({values.index_select(0, order), torch::zeros({1, D}, values.options())});
  const auto ids = torch::arange(n, idx.options());
  const auto start = torch::searchsorted(by_point, ids), end = torch::searchsorted(by_point, ids, false, /*right=*/true);
  const auto count = end - start;
  const int64_t longest = count.max().item<int64_t>();
  if (longest == 0) return out;
  // Points in blocks, so that the table stays within a few times the values' own size however
  // uneven the runs are (a point alone in a void is the neighbor of many grid positions).
  const int64_t rows = std::max<int64_t>(1, std::max<int64_t>(4 * M, int64_t{1} << 20) / longest);
  const auto column = torch::arange(longest, idx.options()).unsqueeze(0);
  for (int64_t a = 0; a < n; a += rows) {
    const int64_t b = std::min(n, a + rows);
    const auto s = start.slice(0, a, b).unsqueeze(1), c = count.slice(0, a, b).unsqueeze(1);
    const auto at = torch::where(column < c, s + column, torch::full_like(s, M));  // (b - a) x longest
    out.slice(0, a, b).copy_(padded.index_select(0, at.reshape({-1})).view({b - a, longest, D}).sum(1));
  }
  return out;
}

}  // namespace

torch::Tensor sum_per_point(const torch::Tensor& values, const torch::Tensor& point, int64_t n, PointSumMethod method) {
  TORCH_CHECK(values.dim() == 2 && point.dim() == 1 && values.size(0) == point.size(0), "sum_per_point: values M x D, point M");
  if (method == PointSumMethod::automatic) method = point_sum_method(values.device());
  if (method == PointSumMethod::gather) return gather_sum(values, point, n);
  return torch::zeros({n, values.size(1)}, values.options()).index_add_(0, point, values);
}

}  // namespace ppsynth
