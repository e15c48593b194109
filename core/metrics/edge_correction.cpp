#include "core/metrics/edge_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ppsynth {

const char* edge_correction_name(EdgeCorrection c) {
  return c == EdgeCorrection::Translation ? "translation" : "isotropic";
}

double translation_weight(const Domain& w, double dx, double dy) {
  const double W = w.width(), H = w.height();
  const double overlap = (W - std::abs(dx)) * (H - std::abs(dy));
  if (!(overlap > 0)) return kMaxEdgeWeight;
  return std::min(kMaxEdgeWeight, W * H / overlap);
}

double isotropic_weight(const Domain& w, Vec2 c, double r) {
  if (!(r > 0)) return 1.0;
  // Distances to the left, right, lower and upper edges.
  const double dL = c.x - w.x0, dR = w.x1 - c.x, dD = c.y - w.y0, dU = w.y1 - c.y;
  // Half the angle of the arc beyond an edge at distance d (0 when the circle does not reach it).
  auto half_arc = [r](double d) { return d < r ? std::acos(std::max(-1.0, d / r)) : 0.0; };
  const double aL = half_arc(dL), aR = half_arc(dR), aD = half_arc(dD), aU = half_arc(dU);
  // Each half arc stops at the direction of the corner next to it: beyond it the arc of the
  // adjacent edge takes over, so arcs meeting at a corner inside the circle are not counted
  // twice (spatstat's ripleybox).
  const double outside = std::min(aL, std::atan2(dU, dL)) + std::min(aL, std::atan2(dD, dL)) +
                         std::min(aR, std::atan2(dU, dR)) + std::min(aR, std::atan2(dD, dR)) +
                         std::min(aU, std::atan2(dL, dU)) + std::min(aU, std::atan2(dR, dU)) +
                         std::min(aD, std::atan2(dL, dD)) + std::min(aD, std::atan2(dR, dD));
  // A point on a corner (on two edges): the two arcs above stop at the corner's direction,
  // which is along the edges there; the quarter beyond the corner is added as spatstat does.
  const double eps = std::numeric_limits<double>::epsilon();
  const int on_edges = (dL < eps) + (dR < eps) + (dD < eps) + (dU < eps);
  const double inside = 1.0 - (outside + (on_edges >= 2 ? M_PI / 2 : 0.0)) / (2.0 * M_PI);
  if (!(inside > 0)) return kMaxEdgeWeight;
  return std::clamp(1.0 / inside, 1.0, kMaxEdgeWeight);
}

}  // namespace ppsynth
