#include "models/gabor_feature_maps.hpp"

#include <ATen/Parallel.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/neighbors.hpp"
#include "models/feature_grid.hpp"
#include "models/gabor_maps_params.hpp"

namespace ppsynth {

torch::Tensor grid_knn(const torch::Tensor& points, const torch::Tensor& grid, int k, bool periodic) {
  auto p = points.detach().to(torch::kFloat64).contiguous();
  const int64_t n = p.size(0);
  std::vector<Vec2> pts(n);
  auto pa = p.accessor<double, 2>();
  for (int64_t i = 0; i < n; ++i) pts[i] = Vec2{pa[i][0], pa[i][1]};
  NeighborIndex index(pts, Domain{}, periodic);
  auto g = grid.detach().to(torch::kFloat64).contiguous();
  const int64_t G = g.size(0);
  auto idx = torch::empty({G, k}, torch::kInt64);
  auto ga = g.accessor<double, 2>();
  auto ia = idx.accessor<int64_t, 2>();
  at::parallel_for(0, G, 256, [&](int64_t b, int64_t e) {
    std::vector<size_t> nb(k);
    std::vector<double> d2(k);
    for (int64_t q = b; q < e; ++q) {
      if (periodic) {
        // Nearest image of each point (allocating query; the plane path below is the hot one).
        auto found = index.knn(Vec2{ga[q][0], ga[q][1]}, static_cast<size_t>(k));
        for (int j = 0; j < k; ++j) ia[q][j] = static_cast<int64_t>(found[j]);
        continue;
      }
      index.knn_into(Vec2{ga[q][0], ga[q][1]}, static_cast<size_t>(k), nb.data(), d2.data());
      for (int j = 0; j < k; ++j) ia[q][j] = static_cast<int64_t>(nb[j]);
    }
  });
  return idx;
}

namespace {

// cos and sin of a*x and a*y for a set of positions (a = 2 pi f). The pair terms need
// cos/sin(a (p - g)), which the angle-difference identities build from these per-point and
// per-grid-position values: 4 trig calls per position instead of 4 per (point, grid) pair.
template <typename T>
struct Phases {
  std::vector<T> cx, sx, cy, sy;
  Phases(const T* xy, int64_t n, T a) : cx(n), sx(n), cy(n), sy(n) {
    for (int64_t i = 0; i < n; ++i) {
      cx[i] = std::cos(a * xy[2 * i]);
      sx[i] = std::sin(a * xy[2 * i]);
      cy[i] = std::cos(a * xy[2 * i + 1]);
      sy[i] = std::sin(a * xy[2 * i + 1]);
    }
  }
};

// Per-neighbor terms shared by forward and backward.
template <typename T>
struct Term {
  T e, dx, dy;
  T cos_t[9], sin_t[9];
};

// Periodic maps (unit torus): d is the minimum image of p_i - g, d = (p_i - g) - s with an
// integer shift s per axis; the phase identities then need a rotation by -a s, whose cos and
// sin for s = +-1 are precomputed here (s is 0 except for terms across the wrap).
template <typename T>
struct Wrap {
  bool on = false;
  T ca = 1, sa = 0;  // cos(a), sin(a), a = 2 pi f
  Wrap(bool periodic, T a) : on(periodic), ca(std::cos(a)), sa(std::sin(a)) {}
  // Rotates (c, s) = (cos th, sin th) to (cos(th - a n), sin(th - a n)) for n in {-1, 0, 1}.
  void rotate(T& c, T& s, T n) const {
    if (n == T(0)) return;
    const T cn = ca, sn = n * sa;
    const T c2 = c * cn + s * sn, s2 = s * cn - c * sn;
    c = c2;
    s = s2;
  }
};

// Point i, grid position g: d = p_i - g (minimum image when periodic); e = exp(-|d|^2 / 2 s^2);
// cos/sin(2 pi nu . d) for the 9 frequencies from cos/sin of the x and y parts.
template <typename T>
inline void eval_term(T dx, T dy, T inv2s2, const Phases<T>& P, int64_t i, const Phases<T>& G, int64_t g,
                      const Wrap<T>& wrap, Term<T>& t) {
  T wx = 0, wy = 0;  // wrap shifts: non-zero only for periodic terms across the border
  if (wrap.on) {
    wx = std::nearbyint(dx);
    wy = std::nearbyint(dy);
    dx -= wx;
    dy -= wy;
  }
  t.dx = dx;
  t.dy = dy;
  t.e = std::exp(-(dx * dx + dy * dy) * inv2s2);
  // cos(a(p - g)) = cos ap cos ag + sin ap sin ag ; sin(a(p - g)) = sin ap cos ag - cos ap sin ag
  T cx = P.cx[i] * G.cx[g] + P.sx[i] * G.sx[g], sx = P.sx[i] * G.cx[g] - P.cx[i] * G.sx[g];
  T cy = P.cy[i] * G.cy[g] + P.sy[i] * G.sy[g], sy = P.sy[i] * G.cy[g] - P.cy[i] * G.sy[g];
  wrap.rotate(cx, sx, wx);  // no-ops for a zero shift
  wrap.rotate(cy, sy, wy);
  for (int f = 0; f < 9; ++f) {
    const int nx = f % 3 - 1, ny = f / 3 - 1;
    const T Cx = nx == 0 ? T(1) : cx, Sx = T(nx) * sx;
    const T Cy = ny == 0 ? T(1) : cy, Sy = T(ny) * sy;
    t.cos_t[f] = Cx * Cy - Sx * Sy;  // cos(a + b)
    t.sin_t[f] = Sx * Cy + Cx * Sy;  // sin(a + b)
  }
}

template <typename T>
void maps_forward(const torch::Tensor& P, const torch::Tensor& W, const torch::Tensor& grid,
                  const torch::Tensor& idx, const MapsParams& mp, torch::Tensor& out) {
  auto pa = P.accessor<T, 2>();
  auto ga = grid.accessor<T, 2>();
  auto ia = idx.accessor<int64_t, 2>();
  auto oa = out.accessor<T, 2>();
  const bool has_w = W.defined() && W.numel() > 0;
  const T* wp = has_w ? W.data_ptr<T>() : nullptr;
  const int64_t A = has_w ? W.size(1) : 0;
  const T inv2s2 = T(1) / (T(2) * T(mp.sigma) * T(mp.sigma));
  const T w2pi = T(kTwoPi * mp.frequency);
  const T invk = T(1) / T(mp.divisor);
  const int C = static_cast<int>(mp.channels.size());
  const Phases<T> PP(P.data_ptr<T>(), P.size(0), w2pi), GP(grid.data_ptr<T>(), grid.size(0), w2pi);
  const Wrap<T> wrap(mp.periodic, w2pi);
  at::parallel_for(0, grid.size(0), 512, [&](int64_t b, int64_t e) {
    Term<T> t;
    for (int64_t g = b; g < e; ++g) {
      for (int j = 0; j < mp.k; ++j) {
        const int64_t i = ia[g][j];
        eval_term<T>(pa[i][0] - ga[g][0], pa[i][1] - ga[g][1], inv2s2, PP, i, GP, g, wrap, t);
        for (int c = 0; c < C; ++c) {
          const auto& ch = mp.channels[c];
          T v = ch.freq < 0 ? t.e : t.e * t.cos_t[ch.freq];
          if (ch.weight >= 0) v *= wp[i * A + ch.weight];
          oa[c][g] += v * invk;
        }
      }
    }
  });
}

template <typename T>
void maps_backward(const torch::Tensor& P, const torch::Tensor& W, const torch::Tensor& grid,
                   const torch::Tensor& idx, const MapsParams& mp, const torch::Tensor& gout,
                   torch::Tensor& gpts) {
  auto pa = P.accessor<T, 2>();
  auto ga = grid.accessor<T, 2>();
  auto ia = idx.accessor<int64_t, 2>();
  auto go = gout.accessor<T, 2>();
  const bool has_w = W.defined() && W.numel() > 0;
  const T* wp = has_w ? W.data_ptr<T>() : nullptr;
  const int64_t A = has_w ? W.size(1) : 0;
  const int64_t N = P.size(0);
  const T inv_s2 = T(1) / (T(mp.sigma) * T(mp.sigma));
  const T inv2s2 = inv_s2 / T(2);
  const T w2pi = T(kTwoPi * mp.frequency);
  const T invk = T(1) / T(mp.divisor);
  const int C = static_cast<int>(mp.channels.size());
  // One accumulator per thread: grid positions scatter into shared points.
  const int nthreads = at::get_num_threads();
  std::vector<std::vector<T>> acc(nthreads, std::vector<T>(2 * N, T(0)));
  const Phases<T> PP(P.data_ptr<T>(), N, w2pi), GP(grid.data_ptr<T>(), grid.size(0), w2pi);
  const Wrap<T> wrap(mp.periodic, w2pi);
  at::parallel_for(0, grid.size(0), 512, [&](int64_t b, int64_t e) {
    auto& my = acc[at::get_thread_num()];
    Term<T> t;
    for (int64_t g = b; g < e; ++g) {
      for (int j = 0; j < mp.k; ++j) {
        const int64_t i = ia[g][j];
        eval_term<T>(pa[i][0] - ga[g][0], pa[i][1] - ga[g][1], inv2s2, PP, i, GP, g, wrap, t);
        T gx = 0, gy = 0;
        for (int c = 0; c < C; ++c) {
          const auto& ch = mp.channels[c];
          T s = go[c][g] * invk;
          if (ch.weight >= 0) s *= wp[i * A + ch.weight];
          if (s == T(0)) continue;
          // d/dp [e] = -e d / sigma^2 ; d/dp [e cos th] = -e cos th d/s^2 - e sin th 2 pi nu.
          if (ch.freq < 0) {
            gx -= s * t.e * t.dx * inv_s2;
            gy -= s * t.e * t.dy * inv_s2;
          } else {
            const int nx = ch.freq % 3 - 1, ny = ch.freq / 3 - 1;
            const T ec = t.e * t.cos_t[ch.freq], es = t.e * t.sin_t[ch.freq];
            gx -= s * (ec * t.dx * inv_s2 + es * w2pi * T(nx));
            gy -= s * (ec * t.dy * inv_s2 + es * w2pi * T(ny));
          }
        }
        my[2 * i] += gx;
        my[2 * i + 1] += gy;
      }
    }
  });
  auto ra = gpts.accessor<T, 2>();
  for (auto& a : acc)
    for (int64_t i = 0; i < N; ++i) {
      ra[i][0] += a[2 * i];
      ra[i][1] += a[2 * i + 1];
    }
}

class GaborMapsFunction : public torch::autograd::Function<GaborMapsFunction> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* ctx, torch::Tensor points,
                               torch::Tensor weights, torch::Tensor grid, torch::Tensor idx,
                               const MapsParams& params) {
    const MapsParams* mp = &params;
    auto P = points.contiguous();
    auto G = grid.to(P.scalar_type()).contiguous();
    // No weights travel as a 0 x 0 tensor: autograd functions take no undefined inputs.
    auto W = weights.numel() > 0 ? weights.to(P.scalar_type()).contiguous() : torch::Tensor();
    auto out = torch::zeros({static_cast<int64_t>(mp->channels.size()), G.size(0)}, P.options());
    AT_DISPATCH_FLOATING_TYPES(P.scalar_type(), "gabor_maps_forward",
                               [&] { maps_forward<scalar_t>(P, W, G, idx, *mp, out); });
    ctx->save_for_backward({P, W.defined() ? W : torch::empty({0, 0}, P.options()), G, idx});
    params.save(ctx);
    return out;
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_out) {
    auto saved = ctx->get_saved_variables();
    const MapsParams params = MapsParams::load(ctx);
    const MapsParams* mp = &params;
    auto P = saved[0], W = saved[1], G = saved[2], idx = saved[3];
    auto gout = grad_out[0].to(P.scalar_type()).contiguous();
    auto gpts = torch::zeros_like(P);
    AT_DISPATCH_FLOATING_TYPES(P.scalar_type(), "gabor_maps_backward",
                               [&] { maps_backward<scalar_t>(P, W, G, idx, *mp, gout, gpts); });
    return {gpts, torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor()};
  }
};

}  // namespace

torch::Tensor gabor_maps_cpu_kernel(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& grid,
                                    const torch::Tensor& idx, const MapsParams& params) {
  TORCH_CHECK(points.device().is_cpu(), "Gabor maps: the CPU kernel takes CPU tensors, not ", points.device());
  return GaborMapsFunction::apply(points, weights, grid, idx, params);
}

bool gabor_maps_tensor_ops_forced() {
  static const bool forced = [] {
    const char* env = std::getenv("PPSYNTH_GABOR_MAPS");
    const std::string v = env ? env : "";
    if (v.empty() || v == "auto") return false;
    if (v == "tensor_ops") return true;
    throw InputError("PPSYNTH_GABOR_MAPS='" + v + "': expected auto (the CPU kernel on the CPU) or tensor_ops");
  }();
  return forced;
}

GaborMapsPath gabor_maps_path(GaborMapsPath requested, const torch::Device& device) {
  if (requested == GaborMapsPath::automatic)
    return device.is_cpu() && !gabor_maps_tensor_ops_forced() ? GaborMapsPath::cpu_kernel : GaborMapsPath::tensor_ops;
  TORCH_CHECK(requested != GaborMapsPath::cpu_kernel || device.is_cpu(), "Gabor maps: the CPU kernel cannot run on ", device);
  return requested;
}

const char* gabor_maps_path_name(GaborMapsPath path) {
  switch (path) {
    case GaborMapsPath::cpu_kernel: return "cpu_kernel";
    case GaborMapsPath::tensor_ops: return "tensor_ops";
    default: return "automatic";
  }
}

GaborFeatureMapsImpl::GaborFeatureMapsImpl(GaborMapsOptions options) : opt_(options) {
  TORCH_CHECK(opt_.res >= 2, "GaborFeatureMaps: res must be >= 2");
  TORCH_CHECK(opt_.k >= 1, "GaborFeatureMaps: k must be >= 1");
  TORCH_CHECK(opt_.rows == 0 || opt_.rows >= 2, "GaborFeatureMaps: rows must be 0 (square) or >= 2");
  const FeatureGrid g{opt_.res, opt_.rows};
  auto pos = g.positions();
  grid_ = register_buffer("grid", torch::from_blob(pos.data(), {int64_t{g.num_rows()} * opt_.res, 2}, torch::kFloat32).clone());
}

int GaborFeatureMapsImpl::channels(int A) const {
  return static_cast<int>(gabor_channels(A, opt_.spatial_only).size());
}

torch::Tensor GaborFeatureMapsImpl::forward(const torch::Tensor& points, const torch::Tensor& weights,
                                            double sigma, const torch::Tensor& jitter) {
  TORCH_CHECK(points.dim() == 2 && points.size(1) == 2, "GaborFeatureMaps: points must be N x 2");
  const int64_t n = points.size(0);
  TORCH_CHECK(n >= 1, "GaborFeatureMaps: no points");
  const int A = weights.defined() && weights.numel() > 0 ? static_cast<int>(weights.size(1)) : 0;
  auto mp = std::make_shared<MapsParams>();
  mp->sigma = sigma / opt_.upscale;
  mp->frequency = opt_.base_frequency * opt_.upscale;
  mp->k = static_cast<int>(std::min<int64_t>(opt_.k, n));
  mp->divisor = opt_.divisor > 0 ? opt_.divisor : mp->k;
  mp->periodic = opt_.periodic;
  mp->channels = gabor_channels(A, opt_.spatial_only);
  torch::Tensor grid = grid_.to(points.scalar_type());
  if (jitter.defined()) grid = grid + jitter.to(points.scalar_type());
  auto w = A > 0 ? weights : torch::empty({0, 0}, points.options());
  torch::Tensor out;
  if (gabor_maps_path(opt_.path, points.device()) == GaborMapsPath::cpu_kernel) {
    out = gabor_maps_cpu_kernel(points, w, grid, grid_knn(points, grid, mp->k, opt_.periodic), *mp);
  } else {
    out = gabor_maps_tensor_ops(points, w, grid, grid_knn_tensor_ops(points, grid, mp->k, opt_.periodic), *mp);
  }
  return out.view({1, static_cast<int64_t>(mp->channels.size()), FeatureGrid{opt_.res, opt_.rows}.num_rows(), opt_.res});
}

torch::Tensor gabor_maps_reference(const torch::Tensor& points, const torch::Tensor& weights,
                                   const torch::Tensor& grid, double sigma, double frequency, int k,
                                   const std::vector<GaborChannel>& channels) {
  // diff[g, i, :] = p_i - g over ALL points, then keep the k nearest per g.
  auto diff = points.unsqueeze(0) - grid.unsqueeze(1);           // G x N x 2
  auto d2 = (diff * diff).sum(-1);                                // G x N
  auto nearest = std::get<1>(d2.topk(k, 1, /*largest=*/false));   // G x k
  auto dk = torch::gather(diff, 1, nearest.unsqueeze(-1).expand({-1, -1, 2}));  // G x k x 2
  auto e = torch::exp(-(dk * dk).sum(-1) / (2 * sigma * sigma));  // G x k
  std::vector<torch::Tensor> maps;
  for (const auto& ch : channels) {
    torch::Tensor v = e;
    if (ch.freq >= 0) {
      const double nx = ch.freq % 3 - 1, ny = ch.freq / 3 - 1;
      auto dot = dk.select(-1, 0) * (nx * frequency) + dk.select(-1, 1) * (ny * frequency);
      v = v * torch::cos(kTwoPi * dot);
    }
    if (ch.weight >= 0) v = v * weights.select(1, ch.weight).index({nearest});
    maps.push_back(v.sum(1) / k);
  }
  return torch::stack(maps);
}

}  // namespace ppsynth
