#include "losses/autocorrelation.hpp"

namespace ppsynth {

namespace {

// Lags kept along an axis of length n for a crop of q: -floor(q/2) .. ceil(q/2)-1.
std::vector<int64_t> kept_lags(int q) {
  std::vector<int64_t> lags;
  for (int a = -(q / 2); a <= (q + 1) / 2 - 1; ++a) lags.push_back(a);
  return lags;
}

// Smallest 2,3,5-smooth size >= n (fast FFT lengths).
int64_t smooth_size(int64_t n) {
  for (int64_t m = std::max<int64_t>(n, 1);; ++m) {
    int64_t r = m;
    for (int64_t f : {2, 3, 5})
      while (r % f == 0) r /= f;
    if (r == 1) return m;
  }
}

// Padding that keeps the kept lags free of wrap-around: the circular correlation at lag a
// adds the linear one at a -+ P, which vanishes when P >= H + max|a|. For the loss's crop
// (max|a| = q/2) this is ~1.25 H instead of the 2 H a full linear correlation needs.
int64_t fft_size(int64_t n, const std::vector<int64_t>& lags) {
  int64_t L = 0;
  for (auto a : lags) L = std::max<int64_t>(L, std::abs(a));
  return smooth_size(n + L);
}

// Cross-correlation r(a,b) = sum_ij x(i+a, j+b) k(i, j) for the kept lags, by FFT.
torch::Tensor cross_corr(const torch::Tensor& x, const torch::Tensor& k, const std::vector<int64_t>& la,
                         const std::vector<int64_t>& lb) {
  const int64_t H = x.size(-2), W = x.size(-1), Ph = fft_size(H, la), Pw = fft_size(W, lb);
  auto X = torch::fft::rfft2(x, std::vector<int64_t>{Ph, Pw});
  auto K = torch::fft::rfft2(k, std::vector<int64_t>{Ph, Pw});
  auto r = torch::fft::irfft2(X * K.conj(), std::vector<int64_t>{Ph, Pw});
  // The kept lags are consecutive, so their indices are made on the device (no host copy
  // per evaluation): lag a sits at a mod P.
  auto wrap = [&](const std::vector<int64_t>& lags, int64_t P) {
    return torch::arange(lags.front(), lags.back() + 1, x.options().dtype(torch::kLong)).remainder(P);
  };
  return r.index_select(-2, wrap(la, Ph)).index_select(-1, wrap(lb, Pw));
}

// (H - |a|)(W - |b|) for the kept lags, made on the device of `opt` as cross_corr's indices.
torch::Tensor overlap_norm(int64_t H, int64_t W, const std::vector<int64_t>& la, const std::vector<int64_t>& lb,
                           const torch::TensorOptions& opt) {
  const auto f64 = opt.dtype(torch::kFloat64);
  auto th = H - torch::arange(la.front(), la.back() + 1, f64).abs();
  auto tw = W - torch::arange(lb.front(), lb.back() + 1, f64).abs();
  return torch::outer(th, tw).to(opt.dtype());
}

}  // namespace

torch::Tensor deep_correlation(const torch::Tensor& F, int q_h, int q_w, CorrelationGradient mode) {
  TORCH_CHECK(F.dim() == 4 && F.size(0) == 1, "deep_correlation: expected 1 x C x H x W");
  const int64_t H = F.size(2), W = F.size(3);
  TORCH_CHECK(q_h <= 2 * H - 1 && q_w <= 2 * W - 1, "deep_correlation: crop larger than the lag range");
  auto x = F[0];
  auto la = kept_lags(q_h), lb = kept_lags(q_w);
  torch::Tensor r;
  if (mode == CorrelationGradient::Exact) {
    r = cross_corr(x, x, la, lb);
  } else {
    // Value of the true autocorrelation, gradient of sum_ij x(i+a) k_last(i) w.r.t. x only.
    auto xd = x.detach();
    auto k_last = xd.narrow(0, xd.size(0) - 1, 1).expand_as(xd);
    auto through = cross_corr(x, k_last, la, lb);
    r = through + (cross_corr(xd, xd, la, lb) - through.detach());
  }
  return r / overlap_norm(H, W, la, lb, r.options());
}

torch::Tensor deep_correlation_direct(const torch::Tensor& F, int q_h, int q_w) {
  const int64_t H = F.size(2), W = F.size(3);
  auto x = F[0];
  auto la = kept_lags(q_h), lb = kept_lags(q_w);
  std::vector<torch::Tensor> rows;
  for (auto a : la) {
    std::vector<torch::Tensor> cols;
    for (auto b : lb) {
      // sum over i, j with both (i, j) and (i + a, j + b) inside.
      int64_t i0 = std::max<int64_t>(0, -a), i1 = std::min<int64_t>(H, H - a);
      int64_t j0 = std::max<int64_t>(0, -b), j1 = std::min<int64_t>(W, W - b);
      auto s = (x.slice(1, i0 + a, i1 + a).slice(2, j0 + b, j1 + b) * x.slice(1, i0, i1).slice(2, j0, j1)).sum({1, 2});
      cols.push_back(s / static_cast<double>((H - std::abs(a)) * (W - std::abs(b))));
    }
    rows.push_back(torch::stack(cols, 1));
  }
  return torch::stack(rows, 1);
}

}  // namespace ppsynth
