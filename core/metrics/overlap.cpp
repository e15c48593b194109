#include "core/metrics/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

std::vector<OverlapCount> disk_overlaps(const PointSet& ps, bool periodic, int max_pair_classes) {
  auto ra = ps.attribute_index("radius");
  if (!ra) throw InputError("disk_overlaps: the point set has no \"radius\" attribute");
  const auto& rad = ps.attribute_column(*ra);
  const size_t n = ps.size();
  for (size_t i = 0; i < n; ++i)
    if (!(rad[i] >= 0)) {
      std::ostringstream s;
      s << "disk_overlaps: point " << i << " has radius " << rad[i] << " (a disk radius must be >= 0)";
      throw InputError(s.str());
    }
  const int K = ps.num_classes();
  const bool per_pair = K <= max_pair_classes;
  const int KP = per_pair ? K : 0;  // class-pair tables only when asked for
  const auto counts = ps.class_counts();

  // No two points are farther apart than the diagonal of their bounding box (on the torus:
  // than the domain's diagonal): a disk with a larger radius overlaps every other disk. Such
  // "giant" disks are counted, not searched (a radius of 1e300 made every query return all).
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2& p = ps[i];
    if (i == 0 || p.x < xlo) xlo = p.x;
    if (i == 0 || p.x > xhi) xhi = p.x;
    if (i == 0 || p.y < ylo) ylo = p.y;
    if (i == 0 || p.y > yhi) yhi = p.y;
  }
  double diag = std::hypot(xhi - xlo, yhi - ylo);
  if (periodic || ps.domain().periodic) diag = std::max(diag, std::hypot(ps.domain().width(), ps.domain().height()));
  const double giant_radius = diag * (1 + 1e-9);
  std::vector<char> giant(n, 0);
  std::vector<size_t> giants_of(K, 0);
  size_t n_giants = 0;
  for (size_t i = 0; i < n; ++i)
    if (rad[i] > giant_radius) giant[i] = 1, ++giants_of[ps.cls(i)], ++n_giants;

  NeighborIndex index(ps.positions(), ps.domain(), periodic);
  // pairs[a * K + b] (a <= b); hit[i * K + c] = point i overlaps a disk of class c.
  std::vector<size_t> pairs(static_cast<size_t>(KP) * KP, 0);
  std::vector<char> hit(n * static_cast<size_t>(KP), 0);
  std::vector<char> any(n, 0);
  size_t total = 0;

  // Pairs of ordinary disks: each is searched from its endpoint with the larger radius (ties:
  // the lower index), within 2 r_i >= r_i + r_j: O(N log N + pairs within that reach).
  std::vector<double> dist;
  const bool report = n >= 200000;
  for (size_t i = 0; i < n; ++i) {
    if (report && i > 0 && i % (n / 10) == 0) spdlog::info("disk overlaps: {}% of {} disks", 100 * i / n, n);
    if (giant[i] || rad[i] == 0) continue;
    auto js = index.radius(ps[i], 2 * rad[i], &dist);
    for (size_t t = 0; t < js.size(); ++t) {
      const size_t j = js[t];
      if (j == i || giant[j]) continue;
      if (rad[j] > rad[i] || (rad[j] == rad[i] && j < i)) continue;  // searched from j
      if (dist[t] >= rad[i] + rad[j]) continue;
      any[i] = any[j] = 1;
      ++total;
      if (!per_pair) continue;
      const int ci = ps.cls(i), cj = ps.cls(j);
      hit[i * KP + cj] = 1;
      hit[j * KP + ci] = 1;
      ++pairs[std::min(ci, cj) * KP + std::max(ci, cj)];
    }
  }
  // Pairs with a giant disk: all of them.
  if (n_giants > 0) {
    auto c2 = [](double m) { return m * (m - 1) / 2; };
    total += static_cast<size_t>(c2(static_cast<double>(n)) - c2(static_cast<double>(n - n_giants)));
    for (size_t i = 0; i < n; ++i) {
      if (n_giants > static_cast<size_t>(giant[i])) any[i] = 1;  // another giant exists
      if (giant[i] && n > 1) any[i] = 1;
    }
    if (per_pair) {
      for (int a = 0; a < K; ++a)
        for (int b = a; b < K; ++b) {
          const double na = static_cast<double>(counts[a]), nb = static_cast<double>(counts[b]);
          const double ma = na - giants_of[a], mb = nb - giants_of[b];
          pairs[a * KP + b] += static_cast<size_t>(a == b ? c2(na) - c2(ma) : na * nb - ma * mb);
        }
      for (size_t i = 0; i < n; ++i) {
        const int c = ps.cls(i);
        for (int o = 0; o < K; ++o) {
          const size_t others_in_o = counts[o] - (o == c ? 1 : 0);
          const size_t giant_others_in_o = giants_of[o] - (o == c && giant[i] ? 1 : 0);
          if (giant_others_in_o > 0 || (giant[i] && others_in_o > 0)) hit[i * KP + o] = 1;
        }
      }
    }
  }

  std::vector<OverlapCount> out;
  OverlapCount all;
  all.pairs = total;
  all.pair_fraction = n > 1 ? total / (0.5 * n * (n - 1)) : 0;
  size_t n_any = 0;
  for (char c : any) n_any += c;
  all.point_fraction = n ? static_cast<double>(n_any) / n : 0;
  out.push_back(all);
  if (!per_pair) return out;
  // hits[c * K + o]: points of class c overlapping a disk of class o.
  std::vector<size_t> hits(static_cast<size_t>(K) * K, 0);
  for (size_t i = 0; i < n; ++i)
    for (int o = 0; o < K; ++o) hits[ps.cls(i) * K + o] += hit[i * KP + o];
  for (int a = 0; a < K; ++a)
    for (int b = a; b < K; ++b) {
      OverlapCount oc;
      oc.ci = a;
      oc.cj = b;
      oc.pairs = pairs[a * KP + b];
      const double cand = a == b ? 0.5 * counts[a] * (counts[a] - (counts[a] > 0 ? 1.0 : 0.0))
                                 : static_cast<double>(counts[a]) * counts[b];
      oc.pair_fraction = cand > 0 ? oc.pairs / cand : 0;
      const size_t pts = a == b ? counts[a] : counts[a] + counts[b];
      const size_t h = a == b ? hits[a * K + a] : hits[a * K + b] + hits[b * K + a];
      oc.point_fraction = pts ? static_cast<double>(h) / pts : 0;
      out.push_back(oc);
    }
  return out;
}

}  // namespace ppsynth
