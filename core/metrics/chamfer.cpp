#include "core/metrics/chamfer.hpp"

#include "core/error.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

double directed_chamfer(const PointSet& a, const PointSet& b) {
  if (a.empty() || b.empty()) throw InputError("chamfer_distance: empty point set");
  NeighborIndex index(b.positions());
  std::vector<double> d;
  double s = 0;
  for (const Vec2& p : a.positions()) {
    index.knn(p, 1, &d);
    s += d.front();
  }
  return s / a.size();
}

double chamfer_distance(const PointSet& a, const PointSet& b) {
  return directed_chamfer(a, b) + directed_chamfer(b, a);
}

}  // namespace ppsynth
