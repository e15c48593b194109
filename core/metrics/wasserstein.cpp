#include "core/metrics/wasserstein.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "core/poll.hpp"

namespace ppsynth {

// Hungarian algorithm, shortest augmenting paths with row/column potentials (the
// Jonker-Volgenant / Kuhn-Munkres O(n^2 m) formulation). 1-based internally; column 0 is
// the virtual start column.
std::vector<size_t> optimal_assignment(const std::vector<double>& cost, size_t rows, size_t cols) {
  if (rows > cols) throw InputError("optimal_assignment: more rows than columns");
  if (cost.size() != rows * cols) throw InputError("optimal_assignment: cost matrix has the wrong size");
  // A NaN or infinite cost never lowers `delta` below infinity: the augmenting loop below
  // would run forever (it did, for points mapped from a 1e-310-wide domain).
  for (size_t k = 0; k < cost.size(); ++k)
    if (!std::isfinite(cost[k]))
      throw InputError("optimal_assignment: cost (" + std::to_string(k / std::max<size_t>(cols, 1)) + ", " +
                       std::to_string(k % std::max<size_t>(cols, 1)) + ") is not finite");
  const double INF = std::numeric_limits<double>::infinity();
  std::vector<double> u(rows + 1, 0), v(cols + 1, 0);
  std::vector<size_t> p(cols + 1, 0), way(cols + 1, 0);
  std::vector<double> minv(cols + 1);
  std::vector<char> used(cols + 1);
  for (size_t i = 1; i <= rows; ++i) {
    poll();  // a caller's stop check (core/poll.hpp): a few thousand rows take a second
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

namespace {

double exact_mean_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  const std::vector<Vec2>& small = a.size() <= b.size() ? a : b;
  const std::vector<Vec2>& large = a.size() <= b.size() ? b : a;
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

// k of the n positions, uniformly without replacement (partial Fisher-Yates), in index order.
std::vector<Vec2> sample(const std::vector<Vec2>& pts, size_t k, std::mt19937_64& rng) {
  std::vector<size_t> idx(pts.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  for (size_t i = 0; i < k; ++i) {
    std::uniform_int_distribution<size_t> pick(i, idx.size() - 1);
    std::swap(idx[i], idx[pick(rng)]);
  }
  idx.resize(k);
  std::sort(idx.begin(), idx.end());
  std::vector<Vec2> out;
  out.reserve(k);
  for (size_t i : idx) out.push_back(pts[i]);
  return out;
}

void check_sets(const PointSet& a, const PointSet& b, size_t max_pairs) {
  if (a.empty() || b.empty()) throw InputError("wasserstein_distance: empty point set");
  if (max_pairs < 1) throw InputError("wasserstein_distance: the pair limit must be >= 1");
}

}  // namespace

double wasserstein_distance(const PointSet& a, const PointSet& b, size_t max_pairs) {
  check_sets(a, b, max_pairs);
  if (static_cast<double>(a.size()) * b.size() > static_cast<double>(max_pairs))
    throw InputError("wasserstein_distance: the exact assignment of " + std::to_string(a.size()) + " x " +
                     std::to_string(b.size()) + " points exceeds the limit of " + std::to_string(max_pairs) +
                     " pairs (O(n^2 m) time, n m memory); use wasserstein_estimate for a subsample estimate");
  return exact_mean_distance(a.positions(), b.positions());
}

WassersteinResult wasserstein_estimate(const PointSet& a, const PointSet& b, size_t max_pairs, uint64_t seed) {
  check_sets(a, b, max_pairs);
  WassersteinResult r;
  const size_t na = a.size(), nb = b.size();
  if (static_cast<double>(na) * nb <= static_cast<double>(max_pairs)) {
    r.value = exact_mean_distance(a.positions(), b.positions());
    r.sample_a = na;
    r.sample_b = nb;
    return r;
  }
  // Largest samples with the size ratio of the sets: sa * sb <= max_pairs, sa / sb ~ na / nb.
  const double ratio = static_cast<double>(na) / nb;
  size_t sa = static_cast<size_t>(std::floor(std::sqrt(max_pairs * ratio)));
  size_t sb = static_cast<size_t>(std::floor(std::sqrt(max_pairs / ratio)));
  sa = std::clamp<size_t>(sa, 1, na);
  sb = std::clamp<size_t>(sb, 1, nb);
  // One side may be small enough to keep whole: give the other side what is left.
  if (sa == na) sb = std::clamp<size_t>(max_pairs / sa, 1, nb);
  if (sb == nb) sa = std::clamp<size_t>(max_pairs / sb, 1, na);
  std::mt19937_64 rng(seed);
  const std::vector<Vec2> pa = sample(a.positions(), sa, rng);
  const std::vector<Vec2> pb = sample(b.positions(), sb, rng);
  r.value = exact_mean_distance(pa, pb);
  r.exact = false;
  r.sample_a = sa;
  r.sample_b = sb;
  return r;
}

}  // namespace ppsynth
