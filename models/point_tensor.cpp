#include "models/point_tensor.hpp"

#include <algorithm>

namespace ppsynth {

torch::Tensor positions_tensor(const PointSet& ps, torch::Dtype dtype) {
  auto flat = ps.flat_xy();
  return torch::from_blob(flat.data(), {static_cast<int64_t>(ps.size()), 2}, torch::kFloat64).to(dtype).clone();
}

void set_positions(PointSet& ps, const torch::Tensor& xy) {
  auto t = xy.detach().to(torch::kFloat64).contiguous();
  TORCH_CHECK(t.size(0) == static_cast<int64_t>(ps.size()) && t.size(1) == 2, "set_positions: size mismatch");
  auto a = t.accessor<double, 2>();
  for (size_t i = 0; i < ps.size(); ++i) ps[i] = Vec2{a[i][0], a[i][1]};
}

torch::Tensor normalized_attributes(const PointSet& ps, const std::vector<int>& columns, torch::Dtype dtype) {
  const int64_t n = static_cast<int64_t>(ps.size()), A = static_cast<int64_t>(columns.size());
  auto w = torch::ones({n, A}, torch::kFloat64);
  auto acc = w.accessor<double, 2>();
  for (int64_t a = 0; a < A; ++a) {
    const auto& col = ps.attribute_column(columns[a]);
    double mx = col.empty() ? 0.0 : *std::max_element(col.begin(), col.end());
    if (mx <= 0) continue;
    for (int64_t i = 0; i < n; ++i) acc[i][a] = col[i] / mx;
  }
  return w.to(dtype);
}

torch::Tensor torus_distances(const torch::Tensor& a, const torch::Tensor& b) {
  auto diff = a.unsqueeze(1) - b.unsqueeze(0);
  diff = diff - torch::round(diff);
  return torch::sqrt(diff.pow(2).sum(-1) + 1e-12);
}

torch::Tensor plane_distances(const torch::Tensor& a, const torch::Tensor& b) {
  return torch::sqrt((a.unsqueeze(1) - b.unsqueeze(0)).pow(2).sum(-1) + 1e-12);
}

}  // namespace ppsynth
