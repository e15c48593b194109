#include "core/metrics/wasserstein.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace ppsynth {

// Hungarian algorithm, shortest augmenting paths with row/column potentials (the
// Jonker-Volgenant / Kuhn-Munkres O(n^2 m) formulation). 1-based internally; column 0 is
// the virtual start column.
std::vector<size_t> optimal_assignment(const std::vector<double>& cost, size_t rows, size_t cols) {
  if (rows > cols) throw InputError("optimal_assignment: more rows than columns");
  if (cost.size() != rows * cols) throw InputError("optimal_assignment: cost matrix has the wrong size");
  const double INF = std::numeric_limits<double>::infinity();
  std::vector<double> u(rows + 1, 0), v(cols + 1, 0);
  std::vector<size_t> p(cols + 1, 0), way(cols + 1, 0);
  std::vector<double> minv(cols + 1);
  std::vector<char> used(cols + 1);
  for (size_t i = 1; i <= rows; ++i) {
    p[0] = i;
    size_t j0 = 0;
    std::fill(minv.begin(), minv.end(), INF);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const size_t i0 = p[j0];
      double delta = INF;
      size_t j1 = 0;
      const double* crow = &cost[(i0 - 1) * cols];
      for (size_t j = 1; j <= cols; ++j) {
        if (used[j]) continue;
        const double cur = crow[j - 1] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (size_t j = 0; j <= cols; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<size_t> assignment(rows, 0);
  for (size_t j = 1; j <= cols; ++j)
    if (p[j] != 0) assignment[p[j] - 1] = j - 1;
  return assignment;
}

double wasserstein_distance(const PointSet& a, const PointSet& b) {
  if (a.empty() || b.empty()) throw InputError("wasserstein_distance: empty point set");
  const PointSet& small = a.size() <= b.size() ? a : b;
  const PointSet& large = a.size() <= b.size() ? b : a;
  const size_t n = small.size(), m = large.size();
  std::vector<double> cost(n * m);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < m; ++j)
      cost[i * m + j] = std::hypot(small[i].x - large[j].x, small[i].y - large[j].y);
  auto match = optimal_assignment(cost, n, m);
  double s = 0;
  for (size_t i = 0; i < n; ++i) s += cost[i * m + match[i]];
  return s / n;
}

}  // namespace ppsynth
