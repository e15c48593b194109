#pragma once
// The two edge corrections of spatstat's K, L, g and mark correlation estimators on a
// rectangular window W (Baddeley, Rubak & Turner 2015, "Spatial Point Patterns", 7.4.2-7.4.3),
// written as spatstat.explore 3.0 computes them (edge.Trans, edge.Ripley):
//
//   translation  e(h) = |W| / |W ∩ (W + h)| = w h / ((w - |h_x|) (h - |h_y|)) for the pair
//                vector h; symmetric in the pair.
//   isotropic    e(x, r) = 1 / (share of the circle of radius r around x that lies in W)
//   (Ripley)     for the pair (x, y) with r = |y - x|; centered on the first point, so the
//                two orders of a pair weigh differently.
//
// Both are capped as spatstat caps them: the translation weight at 100 (its option
// "maxedgewt"), the isotropic weight to [1, 100] (edge.Ripley's maxweight and repair).
#include "core/point_set.hpp"

namespace ppsynth {

enum class EdgeCorrection { Translation, Isotropic };

// "translation" / "isotropic" (spatstat's column names: "trans" / "iso").
const char* edge_correction_name(EdgeCorrection c);

// The largest weight either correction gives (spatstat's cap).
inline constexpr double kMaxEdgeWeight = 100.0;

double translation_weight(const Domain& w, double dx, double dy);
double isotropic_weight(const Domain& w, Vec2 center, double r);

// The weight of the ordered pair (a, b) under `c`.
inline double edge_weight(EdgeCorrection c, const Domain& w, Vec2 a, Vec2 b, double d) {
  return c == EdgeCorrection::Translation ? translation_weight(w, b.x - a.x, b.y - a.y) : isotropic_weight(w, a, d);
}

}  // namespace ppsynth
