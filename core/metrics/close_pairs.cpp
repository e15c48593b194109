#include "core/metrics/close_pairs.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/patches.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();
// A pair as close as the exemplar's own (a copy's, up to rounding) is not below it.
constexpr double kBelow = 1 - 1e-9;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

struct RowPairs {
  double min = kInf;
  size_t pairs_below = 0, points_below = 0, points = 0;
};

// The closest pair within a (b null) or between a and b, and the pairs closer than
// `threshold` (none counted when it is not finite).
RowPairs measure(const PointSet& a, const PointSet* b, double threshold) {
  RowPairs r;
  r.points = a.size() + (b ? b->size() : 0);
  const PointSet& other = b ? *b : a;
  if (a.empty() || other.size() < (b ? 1u : 2u)) return r;
  const NeighborIndex index(other.positions());
  std::vector<char> flagged(other.size(), 0);
  const double below = threshold * kBelow;
  std::vector<double> d;
  for (size_t i = 0; i < a.size(); ++i) {
    const std::vector<size_t> two = index.knn(a[i], b ? 1 : 2, &d);
    for (size_t t = 0; t < two.size(); ++t)
      if (b || two[t] != i) r.min = std::min(r.min, d[t]);
    if (!std::isfinite(threshold)) continue;
    bool mine = false;
    const std::vector<size_t> near = index.radius(a[i], below, &d);
    for (size_t t = 0; t < near.size(); ++t) {
      if ((!b && near[t] == i) || !(d[t] < below)) continue;
      mine = true;
      flagged[near[t]] = 1;
      ++r.pairs_below;
    }
    if (b && mine) ++r.points_below;
  }
  if (!b) r.pairs_below /= 2;  // each pair seen from both ends
  for (char f : flagged) r.points_below += f;
  return r;
}

}  // namespace

json close_pairs_report(const PointSet& exemplar, const PointSet& output, double zoom) {
  if (!(zoom > 0) || !std::isfinite(zoom)) throw InputError("close pairs: the zoom must be a number > 0");
  const Domain& od = output.domain();
  const PointSet out = output.mapped_to(Domain{od.x0 / zoom, od.y0 / zoom, od.x1 / zoom, od.y1 / zoom});
  const double ex_area = exemplar.domain().area(), out_area = out.domain().area();
  json rows = json::array();
  auto add = [&](json row, const PointSet& ea, const PointSet* eb, const PointSet& oa, const PointSet* ob) {
    const RowPairs e = measure(ea, eb, kInf);
    const RowPairs o = measure(oa, ob, e.min);
    row["exemplar_min"] = num(e.min);
    row["output_min"] = num(o.min);
    row["exemplar_normalized"] = num(e.min / (2 * packing_radius(e.points, ex_area)));
    row["output_normalized"] = num(o.min / (2 * packing_radius(o.points, out_area)));
    const bool judged = std::isfinite(e.min);
    row["pairs_below"] = judged ? json(o.pairs_below) : json(nullptr);
    row["share_below"] = judged && o.points ? json(static_cast<double>(o.points_below) / o.points) : json(nullptr);
    rows.push_back(row);
  };
  add({{"row", "all"}}, exemplar, nullptr, out, nullptr);
  const int K = exemplar.num_classes();
  if (K > 1) {
    const auto ek = split_classes(exemplar, K);
    const auto ok = split_classes(out, std::max(K, out.num_classes()));
    for (int c = 0; c < K; ++c) add({{"row", "class"}, {"class", c}}, ek[c], nullptr, ok[c], nullptr);
    if (K <= kMaxPairClasses)
      for (int i = 0; i < K; ++i)
        for (int j = i + 1; j < K; ++j) add({{"row", "pair"}, {"ci", i}, {"cj", j}}, ek[i], &ek[j], ok[i], &ok[j]);
  }
  return {{"measures",
           "the output's closest pairs against the exemplar's, per row (plane, exemplar units): pairs closer than the "
           "exemplar's closest pair of the row, the share of the row's points in one, and the closest pair over the "
           "largest possible for the row's density (the paper's normalized minimum distance)"},
          {"rows", rows}};
}

}  // namespace ppsynth
