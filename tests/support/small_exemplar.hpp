#pragma once
// Test support: the small exemplar the engine tests synthesize from. Class c is a jittered
// grid (seed 11 + c) of `first_class_points` points for class 0 and 9 for the others; with
// disks every point has a radius 0.02 + radius_step * (i % 3) + 0.01 c.
#include <vector>

#include "core/generators/lattices.hpp"
#include "core/point_set.hpp"

namespace ppsynth::test {

inline PointSet small_exemplar(int classes, bool disks, int first_class_points = 16, double radius_step = 0) {
  PointSet ps;
  if (disks) ps.add_attribute("radius");
  for (int c = 0; c < classes; ++c) {
    auto pts = jittered_grid_points(c == 0 ? first_class_points : 9, 11 + c);
    for (size_t i = 0; i < pts.size(); ++i)
      ps.add(pts[i], c, disks ? std::vector<double>{0.02 + radius_step * (i % 3) + 0.01 * c} : std::vector<double>{});
  }
  return ps;
}

}  // namespace ppsynth::test
