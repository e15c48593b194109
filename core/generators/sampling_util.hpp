#pragma once
// Small helpers shared by the generators' .cpp files (not a public API): uniform draws in a
// domain, toroidal wrapping and minimum-image offsets.
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/point_set.hpp"

namespace ppsynth::gen_detail {

inline Vec2 uniform_in(std::mt19937_64& rng, const Domain& d) {
  std::uniform_real_distribution<double> ux(d.x0, d.x1), uy(d.y0, d.y1);
  double x = ux(rng);
  double y = uy(rng);
  return {x, y};
}

inline double wrap1(double v, double lo, double w) {
  double t = std::fmod(v - lo, w);
  if (t < 0) t += w;
  if (t >= w) t = 0;  // fmod rounding
  return lo + t;
}

inline Vec2 wrap(Vec2 p, const Domain& d) {
  return {wrap1(p.x, d.x0, d.width()), wrap1(p.y, d.y0, d.height())};
}

// Minimum-image offset b - a on the torus of `d`.
inline Vec2 torus_delta(Vec2 a, Vec2 b, const Domain& d) {
  double dx = b.x - a.x, dy = b.y - a.y;
  const double W = d.width(), H = d.height();
  dx -= W * std::round(dx / W);
  dy -= H * std::round(dy / H);
  return {dx, dy};
}

inline void check_domain(const Domain& d, const char* who) {
  if (!(d.width() > 0) || !(d.height() > 0) || !std::isfinite(d.area()))
    throw InputError(std::string(who) + ": the domain must have a positive finite size");
}

}  // namespace ppsynth::gen_detail
