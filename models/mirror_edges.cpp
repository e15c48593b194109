#include "models/mirror_edges.hpp"

#include <cmath>
#include <vector>

namespace ppsynth {

namespace {

// The images across the edges e0 (low) and e1 (high) of one axis, appended.
MirroredPoints reflect_axis(const MirroredPoints& in, int axis, double e0, double e1, double reach) {
  std::vector<torch::Tensor> pts{in.points}, ws{in.weights};
  const torch::Tensor coord = in.points.select(1, axis).detach();
  for (double e : {e0, e1}) {
    if (!std::isfinite(e)) continue;
    const torch::Tensor idx = ((coord - e).abs() < reach).nonzero().squeeze(1);
    if (idx.numel() == 0) continue;
    const torch::Tensor q = in.points.index_select(0, idx);
    const torch::Tensor reflected = 2 * e - q.select(1, axis), kept = q.select(1, 1 - axis);
    pts.push_back(axis == 0 ? torch::stack({reflected, kept}, 1) : torch::stack({kept, reflected}, 1));
    if (in.weights.defined()) ws.push_back(in.weights.index_select(0, idx));
  }
  if (pts.size() == 1) return in;
  return {torch::cat(pts), in.weights.defined() ? torch::cat(ws) : torch::Tensor()};
}

}  // namespace

MirroredPoints mirror_edges(const torch::Tensor& points, const torch::Tensor& weights, const MirrorEdges& e, double reach) {
  const MirroredPoints along_x = reflect_axis({points, weights}, 0, e.x0, e.x1, reach);
  return reflect_axis(along_x, 1, e.y0, e.y1, reach);
}

}  // namespace ppsynth
