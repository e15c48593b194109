#include "core/render/palette.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth::render {

namespace {
Rgb hex(unsigned v) { return {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0}; }
Rgb lerp(const Rgb& a, const Rgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
// Piecewise-linear ramp through evenly spaced stops.
template <size_t N>
Rgb ramp(const unsigned (&stops)[N], double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (N - 1);
  const size_t i = std::min(static_cast<size_t>(t), N - 2);
  return lerp(hex(stops[i]), hex(stops[i + 1]), t - i);
}
}  // namespace

Rgb class_color(int k) {
  // Tableau-10 (the 2007 "tab10" used by matplotlib).
  static const unsigned tab10[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                   0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
  return hex(tab10[((k % 10) + 10) % 10]);
}

Rgb viridis(double t) {
  // Viridis sampled at 0, 1/8, ..., 1.
  static const unsigned v[] = {0x440154, 0x472d7b, 0x3b528b, 0x2c728e, 0x21918c,
                               0x28ae80, 0x5ec962, 0xaddc30, 0xfde725};
  return ramp(v, t);
}

Rgb diverging(double t) {
  // ColorBrewer RdBu (reversed: negative blue, positive red), 9 stops.
  static const unsigned d[] = {0x2166ac, 0x4393c3, 0x92c5de, 0xd1e5f0, 0xf7f7f7,
                               0xfddbc7, 0xf4a582, 0xd6604d, 0xb2182b};
  const double u = std::isfinite(t) ? (std::clamp(t, -1.0, 1.0) + 1.0) / 2.0 : 0.5;
  return ramp(d, u);
}

Rgb gray(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  return {t, t, t};
}

}  // namespace ppsynth::render
