#include "core/procedural/pptbf_noise.hpp"

#include <cmath>

#include "core/procedural/pptbf_random.hpp"

namespace ppsynth::pptbf_impl {

namespace {
double lattice(std::uint64_t seed, std::uint64_t stream, std::int64_t i, std::int64_t j) {
  return CellRng(seed, stream, i, j).rand();
}
}  // namespace

double value_noise(std::uint64_t seed, std::uint64_t stream, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  double tx = x - fx, ty = y - fy;
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  const double v00 = lattice(seed, stream, ix, iy), v10 = lattice(seed, stream, ix + 1, iy);
  const double v01 = lattice(seed, stream, ix, iy + 1), v11 = lattice(seed, stream, ix + 1, iy + 1);
  const double a = v00 + (v10 - v00) * tx, b = v01 + (v11 - v01) * tx;
  return a + (b - a) * ty;
}

Vec2 brownnoise(std::uint64_t seed, Vec2 v, double falloff) {
  Vec2 out;
  double amp = 1.0, f = 1.0;
  for (int o = 0; o < 4; ++o) {
    out.x += amp * value_noise(seed, kStreamNoiseX, f * v.x + 17.3 * o, f * v.y);
    out.y += amp * value_noise(seed, kStreamNoiseY, f * v.x, f * v.y + 5.7 * o);
    amp *= falloff;
    f *= 2.0;
  }
  return out;
}

}  // namespace ppsynth::pptbf_impl
