#include "core/metrics/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

// The "radius" column, every value a disk's (>= 0; NaN is not).
const std::vector<double>& checked_radii(const PointSet& ps) {
  const auto ra = ps.attribute_index("radius");
  if (!ra) throw InputError("disk_overlaps: the point set has no \"radius\" attribute");
  const auto& rad = ps.attribute_column(*ra);
  for (size_t i = 0; i < rad.size(); ++i)
    if (!(rad[i] >= 0)) {
      std::ostringstream s;
      s << "disk_overlaps: point " << i << " has radius " << rad[i] << " (a disk radius must be >= 0)";
      throw InputError(s.str());
    }
  return rad;
}

// No two points are farther apart than the diagonal of their bounding box (on the torus: than
// the domain's diagonal): a disk with a larger radius overlaps every other disk. Such "giant"
// disks are counted, not searched (a radius of 1e300 made every query return all).
struct Giants {
  std::vector<char> is;            // per point
  std::vector<size_t> of_class;    // per class
  size_t count = 0;
};

Giants giant_disks(const PointSet& ps, const std::vector<double>& rad, bool periodic) {
  const size_t n = ps.size();
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
  Giants g;
  g.is.assign(n, 0);
  g.of_class.assign(ps.num_classes(), 0);
  for (size_t i = 0; i < n; ++i)
    if (rad[i] > giant_radius) g.is[i] = 1, ++g.of_class[ps.cls(i)], ++g.count;
  return g;
}

// What the counts gather: pairs[a * KP + b] (a <= b); hit[i * KP + c] = point i overlaps a
// disk of class c; any[i] = point i overlaps some disk. KP = 0 when no class-pair tables are
// wanted (too many classes).
struct Tally {
  int KP = 0;
  std::vector<size_t> pairs;
  std::vector<char> hit, any;
  size_t total = 0;

  Tally(size_t n, int kp) : KP(kp), pairs(static_cast<size_t>(kp) * kp, 0), hit(n * static_cast<size_t>(kp), 0), any(n, 0) {}
  void overlap(const PointSet& ps, size_t i, size_t j) {
    any[i] = any[j] = 1;
    ++total;
    if (KP == 0) return;
    const int ci = ps.cls(i), cj = ps.cls(j);
    hit[i * KP + cj] = 1;
    hit[j * KP + ci] = 1;
    ++pairs[std::min(ci, cj) * KP + std::max(ci, cj)];
  }
};

// Pairs of ordinary disks: each is searched from its endpoint with the larger radius (ties: the
// lower index), within 2 r_i >= r_i + r_j: O(N log N + pairs within that reach).
void count_ordinary_pairs(const PointSet& ps, const std::vector<double>& rad, const Giants& giants, bool periodic, Tally& t) {
  const size_t n = ps.size();
  NeighborIndex index(ps.positions(), ps.domain(), periodic);
  std::vector<double> dist;
  const bool report = n >= 200000;
  for (size_t i = 0; i < n; ++i) {
    if (report && i > 0 && i % (n / 10) == 0) spdlog::info("disk overlaps: {}% of {} disks", 100 * i / n, n);
    if (giants.is[i] || rad[i] == 0) continue;
    auto js = index.radius(ps[i], 2 * rad[i], &dist);
    for (size_t k = 0; k < js.size(); ++k) {
      const size_t j = js[k];
      if (j == i || giants.is[j]) continue;
      if (rad[j] > rad[i] || (rad[j] == rad[i] && j < i)) continue;  // searched from j
      if (dist[k] < rad[i] + rad[j]) t.overlap(ps, i, j);
    }
  }
}

// Pairs with a giant disk: all of them, counted by class.
void count_giant_pairs(const PointSet& ps, const Giants& giants, Tally& t) {
  if (giants.count == 0) return;
  const size_t n = ps.size();
  const int K = ps.num_classes();
  const auto counts = ps.class_counts();
  auto c2 = [](double m) { return m * (m - 1) / 2; };
  t.total += static_cast<size_t>(c2(static_cast<double>(n)) - c2(static_cast<double>(n - giants.count)));
  for (size_t i = 0; i < n; ++i) {
    if (giants.count > static_cast<size_t>(giants.is[i])) t.any[i] = 1;  // another giant exists
    if (giants.is[i] && n > 1) t.any[i] = 1;
  }
  if (t.KP == 0) return;
  for (int a = 0; a < K; ++a)
    for (int b = a; b < K; ++b) {
      const double na = static_cast<double>(counts[a]), nb = static_cast<double>(counts[b]);
      const double ma = na - giants.of_class[a], mb = nb - giants.of_class[b];
      t.pairs[a * t.KP + b] += static_cast<size_t>(a == b ? c2(na) - c2(ma) : na * nb - ma * mb);
    }
  for (size_t i = 0; i < n; ++i) {
    const int c = ps.cls(i);
    for (int o = 0; o < K; ++o) {
      const size_t others_in_o = counts[o] - (o == c ? 1 : 0);
      const size_t giant_others_in_o = giants.of_class[o] - (o == c && giants.is[i] ? 1 : 0);
      if (giant_others_in_o > 0 || (giants.is[i] && others_in_o > 0)) t.hit[i * t.KP + o] = 1;
    }
  }
}

// The rows: all classes together, then each class pair a <= b (when tallied).
std::vector<OverlapCount> overlap_rows(const PointSet& ps, const Tally& t) {
  const size_t n = ps.size();
  const int K = ps.num_classes();
  std::vector<OverlapCount> out;
  OverlapCount all;
  all.pairs = t.total;
  all.pair_fraction = n > 1 ? t.total / (0.5 * n * (n - 1)) : 0;
  size_t n_any = 0;
  for (char c : t.any) n_any += c;
  all.point_fraction = n ? static_cast<double>(n_any) / n : 0;
  out.push_back(all);
  if (t.KP == 0) return out;
  const auto counts = ps.class_counts();
  // hits[c * K + o]: points of class c overlapping a disk of class o.
  std::vector<size_t> hits(static_cast<size_t>(K) * K, 0);
  for (size_t i = 0; i < n; ++i)
    for (int o = 0; o < K; ++o) hits[ps.cls(i) * K + o] += t.hit[i * t.KP + o];
  for (int a = 0; a < K; ++a)
    for (int b = a; b < K; ++b) {
      OverlapCount oc;
      oc.ci = a;
      oc.cj = b;
      oc.pairs = t.pairs[a * t.KP + b];
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

}  // namespace

std::vector<OverlapCount> disk_overlaps(const PointSet& ps, bool periodic, int max_pair_classes) {
  const std::vector<double>& rad = checked_radii(ps);
  const int K = ps.num_classes();
  const Giants giants = giant_disks(ps, rad, periodic);
  Tally tally(ps.size(), K <= max_pair_classes ? K : 0);  // class-pair tables only when asked for
  count_ordinary_pairs(ps, rad, giants, periodic, tally);
  count_giant_pairs(ps, giants, tally);
  return overlap_rows(ps, tally);
}

}  // namespace ppsynth
