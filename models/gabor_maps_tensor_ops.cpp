// The Gabor maps (paper Eq. 5) with LibTorch operations, on the device the tensors are on:
// the path a CUDA run takes (models/gabor_feature_maps.hpp). The same sum and the same
// analytic backward as the CPU kernel in gabor_feature_maps.cpp, organized for a device
// instead of a thread: the k neighbors of every grid position are gathered once into
// res^2 x k offsets, each channel is a few element-wise operations over them, and the
// backward sums the per-neighbor gradients into the points (models/per_point_sum.hpp: one
// index_add, or, on CUDA in a deterministic run, a gather over the inverse neighbor list,
// which is deterministic without LibTorch's slow deterministic index_add). Memory: a few res^2 x k tensors at a time, not
// res^2 x k x C; nothing but the inputs is kept for the backward, which gathers again.
#include <algorithm>
#include <vector>

#include "models/gabor_feature_maps.hpp"
#include "models/gabor_maps_params.hpp"
#include "models/per_point_sum.hpp"

namespace ppsynth {

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

// The offsets d = p_i - g of the k neighbors of every grid position (G x k per axis, the
// minimum image on the torus), their Gaussian e = exp(-|d|^2 / 2 sigma^2), and the weight
// columns gathered the same way (one G x k tensor per attribute).
struct Neighborhood {
  torch::Tensor dx, dy, e;
  std::vector<torch::Tensor> w;
};

Neighborhood gather(const torch::Tensor& P, const torch::Tensor& W, const torch::Tensor& grid, const torch::Tensor& idx,
                     const MapsParams& mp) {
  const int64_t G = idx.size(0), k = idx.size(1);
  const auto flat = idx.reshape({-1});
  auto d = P.index_select(0, flat).view({G, k, 2}) - grid.unsqueeze(1);
  // round() is half to even, as the kernel's nearbyint: the same image at exactly half a period.
  if (mp.periodic) d = d - torch::round(d);
  Neighborhood n;
  n.dx = d.select(2, 0);
  n.dy = d.select(2, 1);
  n.e = torch::exp((n.dx * n.dx + n.dy * n.dy) * (-1.0 / (2.0 * mp.sigma * mp.sigma)));
  for (int64_t a = 0; a < W.size(1) && W.numel() > 0; ++a) n.w.push_back(W.select(1, a).index_select(0, flat).view({G, k}));
  return n;
}

// nu . d for the channel's frequency nu = (nx, ny), nx and ny in {-1, 0, 1} (undefined for nu = 0).
torch::Tensor dot_nu(const Neighborhood& n, int nx, int ny) {
  torch::Tensor t;
  if (nx != 0) t = nx > 0 ? n.dx : -n.dx;
  if (ny != 0) t = !t.defined() ? (ny > 0 ? n.dy : -n.dy) : (ny > 0 ? t + n.dy : t - n.dy);
  return t;
}

int nu_x(const GaborChannel& c) { return c.freq % 3 - 1; }
int nu_y(const GaborChannel& c) { return c.freq / 3 - 1; }

class GaborMapsTensorOpsFunction : public torch::autograd::Function<GaborMapsTensorOpsFunction> {
 public:
  static torch::Tensor forward(AutogradContext* ctx, torch::Tensor points, torch::Tensor weights, torch::Tensor grid,
                               torch::Tensor idx, const MapsParams& mp) {
    const auto P = points.detach();
    const auto G = grid.to(P.scalar_type());
    // No weights travel as a 0 x 0 tensor: autograd functions take no undefined inputs.
    const auto W = weights.numel() > 0 ? weights.to(P.scalar_type()) : torch::empty({0, 0}, P.options());
    const Neighborhood n = gather(P, W, G, idx, mp);
    const double w2pi = kTwoPi * mp.frequency;
    std::vector<torch::Tensor> maps;
    for (const auto& ch : mp.channels) {
      torch::Tensor v = n.e;
      const auto t = ch.freq >= 0 ? dot_nu(n, nu_x(ch), nu_y(ch)) : torch::Tensor();
      if (t.defined()) v = v * torch::cos(t * w2pi);
      if (ch.weight >= 0) v = v * n.w[ch.weight];
      maps.push_back(v.sum(1) * (1.0 / mp.divisor));
    }
    ctx->save_for_backward({P, W, G, idx});
    mp.save(ctx);
    return torch::stack(maps);
  }

  // d/dp [e] = -e d / sigma^2 ; d/dp [e cos th] = -e cos th d / sigma^2 - e sin th 2 pi f nu.
  // Summed over the channels per neighbor first (three G x k accumulators), then scattered.
  static variable_list backward(AutogradContext* ctx, variable_list grad_out) {
    const auto saved = ctx->get_saved_variables();
    const MapsParams mp = MapsParams::load(ctx);
    const auto &P = saved[0], &W = saved[1], &G = saved[2], &idx = saved[3];
    const auto gout = grad_out[0].to(P.scalar_type());
    const Neighborhood n = gather(P, W, G, idx, mp);
    const double w2pi = kTwoPi * mp.frequency;
    auto radial = torch::zeros_like(n.e), along_x = torch::zeros_like(n.e), along_y = torch::zeros_like(n.e);
    for (size_t c = 0; c < mp.channels.size(); ++c) {
      const auto& ch = mp.channels[c];
      auto s = gout[static_cast<int64_t>(c)].unsqueeze(1) * (1.0 / mp.divisor) * n.e;
      if (ch.weight >= 0) s = s * n.w[ch.weight];
      const auto t = ch.freq >= 0 ? dot_nu(n, nu_x(ch), nu_y(ch)) : torch::Tensor();
      if (!t.defined()) {
        radial.add_(s);
        continue;
      }
      const auto th = t * w2pi;
      radial.add_(s * torch::cos(th));
      const auto ss = s * torch::sin(th);
      if (nu_x(ch) != 0) along_x.add_(ss, nu_x(ch));
      if (nu_y(ch) != 0) along_y.add_(ss, nu_y(ch));
    }
    const double inv_s2 = 1.0 / (mp.sigma * mp.sigma);
    const auto gx = -(radial * n.dx * inv_s2 + along_x * w2pi), gy = -(radial * n.dy * inv_s2 + along_y * w2pi);
    auto gpts = sum_per_point(torch::stack({gx, gy}, 2).view({-1, 2}), idx.reshape({-1}), P.size(0));
    return {gpts, torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor()};
  }
};

}  // namespace

torch::Tensor gabor_maps_tensor_ops(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& grid,
                                    const torch::Tensor& idx, const MapsParams& params) {
  return GaborMapsTensorOpsFunction::apply(points, weights, grid, idx, params);
}

torch::Tensor grid_knn_tensor_ops(const torch::Tensor& points, const torch::Tensor& grid, int k, bool periodic) {
  torch::NoGradGuard no_grad;
  const auto p = points.detach();
  const auto g = grid.detach().to(p.scalar_type());
  const int64_t N = p.size(0), G = g.size(0);
  TORCH_CHECK(k >= 1 && k <= N, "grid_knn_tensor_ops: k = ", k, " of ", N, " points");
  const auto px = p.select(1, 0).unsqueeze(0), py = p.select(1, 1).unsqueeze(0);
  // About 2^24 distances (64 MB in float32) at a time, whatever the point count.
  const int64_t rows = std::max<int64_t>(1, (int64_t{1} << 24) / N);
  std::vector<torch::Tensor> parts;
  for (int64_t a = 0; a < G; a += rows) {
    const auto gc = g.slice(0, a, std::min(G, a + rows));
    auto dx = px - gc.select(1, 0).unsqueeze(1), dy = py - gc.select(1, 1).unsqueeze(1);
    if (periodic) {
      dx = dx - torch::round(dx);
      dy = dy - torch::round(dy);
    }
    parts.push_back(std::get<1>((dx * dx + dy * dy).topk(k, 1, /*largest=*/false, /*sorted=*/true)));
  }
  return parts.size() == 1 ? parts.front() : torch::cat(parts);
}

}  // namespace ppsynth
