#pragma once
// PointSet <-> tensor conversions: positions as N x 2 (x, y), per-point map weights as N x A.
#include <torch/torch.h>

#include "core/point_set.hpp"

namespace ppsynth {

torch::Tensor positions_tensor(const PointSet& ps, torch::Dtype dtype = torch::kFloat32);
// Copies N x 2 positions back into `ps` (same size), e.g. after optimization.
void set_positions(PointSet& ps, const torch::Tensor& xy);
// Attribute columns `columns` as N x A, each divided by its maximum over the set (the
// weights w_i of Eq. 5; method.md section 2). An all-zero column gives weight 1.
torch::Tensor normalized_attributes(const PointSet& ps, const std::vector<int>& columns,
                                    torch::Dtype dtype = torch::kFloat32);
// Pairwise distances (n x m) between positions a (n x 2) and b (m x 2) on the unit torus
// (minimum image), differentiable: round() passes no gradient, and a small epsilon keeps
// the gradient of coincident points finite (the point terms of optim/ use it).
torch::Tensor torus_distances(const torch::Tensor& a, const torch::Tensor& b);
// The same in the plane (a window's positions do not wrap).
torch::Tensor plane_distances(const torch::Tensor& a, const torch::Tensor& b);

}  // namespace ppsynth
