#pragma once
// Test support: two point sets are the same to the last bit (positions and classes, in order):
// what a resumed run must give against the run never stopped.
#include "core/point_set.hpp"

namespace ppsynth::test {

inline bool same_bits(const PointSet& a, const PointSet& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y || a.cls(i) != b.cls(i)) return false;
  return true;
}

}  // namespace ppsynth::test
