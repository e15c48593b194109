#include "core/metrics/nearest_neighbor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {
std::vector<double> nn_distances(const PointSet& ps, bool periodic, const char* who) {
  if (ps.size() < 2) throw InputError(std::string(who) + ": need at least 2 points");
  NeighborIndex index(ps.positions(), ps.domain(), periodic);
  std::vector<double> d(ps.size());
  for (size_t i = 0; i < ps.size(); ++i) index.nearest_other(i, &d[i]);
  return d;
}
}  // namespace

std::vector<double> nearest_neighbor_distances(const PointSet& ps, bool periodic) {
  return nn_distances(ps, periodic, "nearest_neighbor_distances");
}

double packing_radius(size_t n, double area) {
  if (n == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(area / (2.0 * std::sqrt(3.0) * static_cast<double>(n)));
}

NnStats nn_stats(const PointSet& ps, bool periodic) {
  auto d = nn_distances(ps, periodic, "nn_stats");
  NnStats st;
  double s = 0;
  for (double v : d) s += v;
  st.mean = s / d.size();
  st.min = *std::min_element(d.begin(), d.end());
  return st;
}

double mean_nn_distance(const PointSet& ps, bool periodic) {
  auto d = nn_distances(ps, periodic, "mean_nn_distance");
  double s = 0;
  for (double v : d) s += v;
  return s / d.size();
}

double min_nn_distance(const PointSet& ps, bool periodic) {
  auto d = nn_distances(ps, periodic, "min_nn_distance");
  return *std::min_element(d.begin(), d.end());
}

double relative_radius(const PointSet& ps) {
  const double dmin = min_nn_distance(ps, /*periodic=*/true);
  return (dmin / 2.0) / packing_radius(ps.size(), ps.domain().area());
}

}  // namespace ppsynth
