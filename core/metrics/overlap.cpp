#include "core/metrics/overlap.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

std::vector<OverlapCount> disk_overlaps(const PointSet& ps, bool periodic) {
  auto ra = ps.attribute_index("radius");
  if (!ra) throw InputError("disk_overlaps: the point set has no \"radius\" attribute");
  const auto& rad = ps.attribute_column(*ra);
  const int K = ps.num_classes();
  const auto counts = ps.class_counts();
  const size_t n = ps.size();
  double r_big = 0;
  for (double r : rad) r_big = std::max(r_big, r);
  NeighborIndex index(ps.positions(), ps.domain(), periodic);

  // pairs[ci][cj] (ci <= cj); hit[i][cj] = point i overlaps a disk of class cj.
  std::vector<std::vector<size_t>> pairs(K, std::vector<size_t>(K, 0));
  std::vector<std::vector<char>> hit(n, std::vector<char>(K, 0));
  std::vector<char> any(n, 0);
  size_t total = 0;
  std::vector<double> dist;
  for (size_t i = 0; i < n; ++i) {
    auto js = index.radius(ps[i], rad[i] + r_big, &dist);
    for (size_t t = 0; t < js.size(); ++t) {
      const size_t j = js[t];
      if (j == i || dist[t] >= rad[i] + rad[j]) continue;
      hit[i][ps.cls(j)] = 1;
      any[i] = 1;
      if (j < i) continue;  // count each unordered pair once
      const int a = std::min(ps.cls(i), ps.cls(j)), b = std::max(ps.cls(i), ps.cls(j));
      ++pairs[a][b];
      ++total;
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
  for (int a = 0; a < K; ++a)
    for (int b = a; b < K; ++b) {
      OverlapCount oc;
      oc.ci = a;
      oc.cj = b;
      oc.pairs = pairs[a][b];
      const double cand = a == b ? 0.5 * counts[a] * (counts[a] - (counts[a] > 0 ? 1.0 : 0.0))
                                 : static_cast<double>(counts[a]) * counts[b];
      oc.pair_fraction = cand > 0 ? oc.pairs / cand : 0;
      size_t pts = 0, hits = 0;
      for (size_t i = 0; i < n; ++i) {
        const int c = ps.cls(i);
        if (c != a && c != b) continue;
        ++pts;
        const int other = c == a ? b : a;
        hits += hit[i][other];
      }
      oc.point_fraction = pts ? static_cast<double>(hits) / pts : 0;
      out.push_back(oc);
    }
  return out;
}

}  // namespace ppsynth
