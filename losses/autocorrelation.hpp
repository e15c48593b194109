#pragma once
// Deep correlation (paper Eq. 3, method.md §4) of every channel t of a feature map F:
//
//   C_t(a, b) = sum_ij f(i, j) f(i - a, j - b) / ((H - |a|)(W - |b|)),  zero padding,
//
// computed for all lags by FFT (O(HW log HW) per channel instead of the published direct
// O(H^2 W^2) convolution), then cropped to the central q_h x q_w lags
// a in [-floor(q/2), ceil(q/2) - 1] (the published crop; for q = 32: -16..15).
//
// Gradient modes:
//   Exact     : the gradient of this function (default; what the paper defines).
//   Published : what the published code computes: the kernel side carries no gradient and
//               every channel's input gradient uses the LAST channel's map as the kernel
//               (its conv module's weight is swapped through .data in a loop). Same values.
#include <torch/torch.h>

namespace ppsynth {

enum class CorrelationGradient { Exact, Published };

// F: 1 x C x H x W. Returns C x q_h x q_w.
torch::Tensor deep_correlation(const torch::Tensor& F, int q_h, int q_w,
                               CorrelationGradient mode = CorrelationGradient::Exact);

// Direct (non-FFT) evaluation for tests: O(C H^2 W^2), exact gradient.
torch::Tensor deep_correlation_direct(const torch::Tensor& F, int q_h, int q_w);

}  // namespace ppsynth
