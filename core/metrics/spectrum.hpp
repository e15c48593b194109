#pragma once
// Fourier power spectrum of a point set (Heck et al. 2013 style), positions taken relative
// to the domain (x -> (x - x0)/W, so frequencies are cycles per domain width):
//   P(f) = |sum_j exp(-2 pi i f . x_j)|^2 / N   for integer f = (fx, fy), |fx|,|fy| <= F
// (dimensionless; 1 for white noise away from f = 0; P(0) = N).
// Radial average: mean P over the integer frequencies with round(|f|) = k, k = 0..F.
// Anisotropy per ring: variance of P over the ring / (mean over the ring)^2 (dimensionless;
// about 1 for white noise, ~0 for an isotropic deterministic spectrum). Ring k = 0 has
// anisotropy 0. Cost O(N F^2).
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct SpectrumImage {
  int width = 0, height = 0;  // (2F+1) x (2F+1); pixel (x, y) is f = (x - F, y - F)
  std::vector<float> pixels;  // row-major, P(f)
};

struct Spectrum {
  std::vector<double> frequency;  // ring radius k = 0..F (cycles per domain)
  std::vector<double> radial_power;
  std::vector<double> anisotropy;
  SpectrumImage image;
};

Spectrum power_spectrum(const PointSet& ps, int max_frequency = 64);

}  // namespace ppsynth
