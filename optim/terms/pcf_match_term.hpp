#pragma once
// PcfMatchTerm: not in the paper (method.terms.pcf_match, off by default; a point term, optim/terms/point_term.hpp). A differentiable
// pair-correlation loss for the moving class of a class stage, after the PCF-matching
// synthesis of Oztireli & Gross 2012 and the thesis's Chapter 4 (optim/baselines/pcf2017).
//
// Why: in the paper's multi-class scheme a later class is optimized inside the JOINT maps of
// classes 0..k (no class channel), so nothing asks it for its own spacing; with a class of 3
// or 6 exemplar points (lemon_4c_v2) the per-class PCF stays near the initialization's
// (docs/explanation/method.md "Beyond the paper"). This term asks each class for the exemplar's own PCF
// and, with `cross`, for the exemplar's cross-PCF to every frozen (earlier) class:
//
//   term = sum over curves of mean_b (g_out(r_b) - g_ex(r_b))^2
//   g_out(r) = 1 / (n_a n_b 2 pi r) sum_{i in a, j in b, i != j} k(r - d_ij)      (unit torus)
//   k(t) = exp(-t^2 / s^2) / (sqrt(pi) s)
//
// with n_a n_b -> n (n - 1) for the auto-PCF. g_ex is core's estimator (core/metrics/pcf.hpp:
// the exemplar's rectangle with translation edge correction), and the output curve uses the
// same radii and kernel in r_max units, r_max_out = r_max_ex / u (the output holds u^2 times
// the points in the same unit area). Bins beyond half the torus (r > 0.5) are dropped: the
// minimum-image distance is not a distance there. The output on the torus has no edges, so a
// stationary output whose PCF matches g_ex also matches it in expectation in every crop.
// Pairs are dense (n x n x bins floats per evaluation; ~26 M for 512 moving points).
#include <torch/torch.h>

#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

class PcfMatchTerm {
 public:
  // One class stage: `moving` (all of one class) and `frozen` index `output`; the exemplar's
  // class of the moving points gives the auto-PCF target, every frozen class with at least
  // one exemplar point a cross target (when `cross`). Curves whose exemplar side has fewer
  // than two points (auto) or no points (cross) are skipped: their target says nothing.
  // The curves are kept on `device`, where the positions will be.
  PcfMatchTerm(const PointSet& exemplar, const PointSet& output, const std::vector<size_t>& moving,
               const std::vector<size_t>& frozen, int upscale, bool cross, torch::Device device = torch::kCPU);
  // moving: n x 2 wrapped positions (may require grad); frozen: m x 2 in `frozen`'s order.
  torch::Tensor operator()(const torch::Tensor& moving, const torch::Tensor& frozen) const;
  // The number of curves matched (0 = the term is a constant zero).
  size_t curves() const { return curves_.size(); }

 private:
  struct Curve {
    torch::Tensor frozen_rows;  // undefined = the auto-PCF; else rows of `frozen` (one class)
    torch::Tensor radii;        // bins kept, output units
    torch::Tensor target;       // g_ex at those bins
    double sigma = 0;           // kernel width, output units
  };
  std::vector<Curve> curves_;
};

}  // namespace ppsynth
