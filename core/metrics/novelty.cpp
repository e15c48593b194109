#include "core/metrics/novelty.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// A pattern's points in offset units (coordinates over the spacing), with their classes; a
// periodic one as its 9 images (the point set shifted by -W, 0, +W and -H, 0, +H), the
// original first, so that a plane query from an original point sees the torus around it with
// true offsets.
struct Scaled {
  std::vector<Vec2> pos;
  std::vector<int> cls;
  size_t n = 0;  // original points: indices 0..n-1
  Domain window;
};

Scaled scaled(const PointSet& ps, double spacing, bool periodic) {
  Scaled s;
  s.n = ps.size();
  const Domain& d = ps.domain();
  s.window = {0, 0, d.width() / spacing, d.height() / spacing};
  const int images = periodic ? 9 : 1;
  const int sx[9] = {0, -1, 1, 0, 0, -1, -1, 1, 1};
  const int sy[9] = {0, 0, 0, -1, 1, -1, 1, -1, 1};
  s.pos.reserve(images * s.n);
  s.cls.reserve(images * s.n);
  for (int b = 0; b < images; ++b)
    for (size_t i = 0; i < s.n; ++i) {
      s.pos.push_back({(ps[i].x - d.x0) / spacing + sx[b] * s.window.x1, (ps[i].y - d.y0) / spacing + sy[b] * s.window.y1});
      s.cls.push_back(ps.cls(i));
    }
  return s;
}

struct Neighbour {
  Vec2 offset;
  double dist;
  int cls;
};

// The neighbours of point i of `s` within r (itself left out), as offsets.
std::vector<Neighbour> around(const Scaled& s, const NeighborIndex& index, size_t i, double r) {
  std::vector<double> d;
  const std::vector<size_t> idx = index.radius(s.pos[i], r, &d);
  std::vector<Neighbour> out;
  out.reserve(idx.size());
  for (size_t t = 0; t < idx.size(); ++t)
    if (idx[t] != i) out.push_back({{s.pos[idx[t]].x - s.pos[i].x, s.pos[idx[t]].y - s.pos[i].y}, d[t], s.cls[idx[t]]});
  return out;
}

// A run of neighbours, sorted by distance.
struct Span {
  const Neighbour* begin;
  const Neighbour* end;
};
Span span(const std::vector<Neighbour>& v) { return {v.data(), v.data() + v.size()}; }

// The largest distance from a neighbour of `from` no farther than `reach` to the nearest one
// of its class in `to`; stops (returning +inf) once it exceeds `limit`.
double directed(Span from, double reach, Span to, double limit) {
  double worst = 0;
  const double limit2 = limit * limit;
  for (const Neighbour* a = from.begin; a != from.end && a->dist <= reach; ++a) {
    double best = kInf;
    for (const Neighbour* b = to.begin; b != to.end; ++b)
      if (b->cls == a->cls) {
        const double dx = a->offset.x - b->offset.x, dy = a->offset.y - b->offset.y;
        best = std::min(best, dx * dx + dy * dy);
      }
    if (best > limit2) return kInf;
    worst = std::max(worst, best);
  }
  return std::sqrt(worst);
}

}  // namespace

void check_novelty_options(const NoveltyOptions& opt) {
  if (opt.k < 1 || opt.k > 64) throw InputError("novelty k (--novelty-k) must be in 1..64 (got " + std::to_string(opt.k) + ")");
  if (!(opt.tolerance > 0) || opt.tolerance > 1)
    throw InputError("novelty tolerance (--novelty-tolerance) must be in (0, 1] exemplar mean nearest-neighbour distances");
  if (!(opt.copy_share > 0) || opt.copy_share > 1)
    throw InputError("novelty copy share (--novelty-copy-share) must be in (0, 1]");
}

double NeighbourhoodMatch::share() const {
  return scored ? static_cast<double>(matched) / static_cast<double>(scored) : std::nan("");
}

NeighbourhoodMatch match_neighbourhoods(const PointSet& output, const PointSet& reference, bool reference_periodic,
                                        double spacing, const NoveltyOptions& opt) {
  check_novelty_options(opt);
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("novelty: the spacing must be a number > 0");
  NeighbourhoodMatch m;
  m.points = output.size();
  m.closest = kInf;
  const size_t k = static_cast<size_t>(opt.k);
  if (output.size() < k + 1 || reference.size() < 2) return m;
  const double tol = opt.tolerance;
  const Scaled out = scaled(output, spacing, false);
  const Scaled ref = scaled(reference, spacing, reference_periodic);
  const NeighborIndex out_index(out.pos), ref_index(ref.pos);

  // The output points scored: their k-th neighbour's distance, and their window's room.
  std::vector<double> rk(out.n, -1), scored_rk;
  std::vector<size_t> nearest(out.n);
  std::vector<double> d;
  for (size_t p = 0; p < out.n; ++p) {
    const std::vector<size_t> near = out_index.knn(out.pos[p], k + 1, &d);
    size_t seen = 0;  // the k nearest others (p is among the k + 1 unless duplicates crowd it out)
    for (size_t t = 0; t < near.size() && seen < k; ++t) {
      if (near[t] == p) continue;
      if (seen++ == 0) nearest[p] = near[t];
      rk[p] = d[t];
    }
    const Vec2 at = out.pos[p];
    const double room = std::min({at.x, out.window.x1 - at.x, at.y, out.window.y1 - at.y});
    if (seen < k || !(rk[p] + tol < room)) rk[p] = -1;  // its neighbourhood is cut by the window
    else scored_rk.push_back(rk[p]);
  }
  if (scored_rk.empty()) return m;
  // Each reference point's neighbours, sorted by distance, as far as most output
  // neighbourhoods reach (a farther one is asked of the tree), and at least its nearest plus
  // twice the tolerance: the pairs by offset below.
  std::sort(scored_rk.begin(), scored_rk.end());
  const double reach = scored_rk[(scored_rk.size() - 1) * 99 / 100] + tol;
  std::vector<std::vector<Neighbour>> lists(ref.n);
  std::vector<double> list_reach(ref.n);
  // Pairs (e, q) of the reference with q no farther from e than e's nearest neighbour plus
  // twice the tolerance, by offset. A reference point e that matches an output point p within
  // the tolerance holds such a pair within the tolerance of p's nearest neighbour's offset a1:
  // e's nearest neighbour lies within the tolerance of one of p's (the backward half of the
  // match), so |a1| <= nn(e) + tol, and a1's counterpart lies within |a1| + tol.
  std::vector<Vec2> pair_offset;
  std::vector<size_t> pair_point;
  std::vector<int> pair_class;
  for (size_t e = 0; e < ref.n; ++e) {
    const std::vector<size_t> two = ref_index.knn(ref.pos[e], 2, &d);
    double nn = kInf;
    for (size_t t = 0; t < two.size(); ++t)
      if (two[t] != e) nn = std::min(nn, d[t]);
    if (!std::isfinite(nn)) continue;
    list_reach[e] = std::max(reach, nn + 2 * tol);
    lists[e] = around(ref, ref_index, e, list_reach[e]);
    for (const Neighbour& q : lists[e]) {
      if (q.dist > nn + 2 * tol) break;
      pair_offset.push_back(q.offset);
      pair_point.push_back(e);
      pair_class.push_back(q.cls);
    }
  }
  if (pair_offset.empty()) return m;
  const NeighborIndex pair_index(pair_offset);

  std::vector<size_t> candidates;
  std::vector<Neighbour> theirs;
  for (size_t p = 0; p < out.n; ++p) {
    if (rk[p] < 0) continue;
    ++m.scored;
    const double core = rk[p] * (1 + 1e-12);  // the k nearest, ties and rounding included
    const std::vector<Neighbour> mine = around(out, out_index, p, rk[p] + tol);
    const size_t a = nearest[p];
    const Vec2 a1 = {out.pos[a].x - out.pos[p].x, out.pos[a].y - out.pos[p].y};
    candidates.clear();
    for (size_t t : pair_index.radius(a1, tol))
      if (pair_class[t] == out.cls[a] && ref.cls[pair_point[t]] == out.cls[p]) candidates.push_back(pair_point[t]);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    double best = kInf;
    for (size_t e : candidates) {
      const double limit = std::min(best, tol);
      Span their = span(lists[e]);
      if (rk[p] + tol <= list_reach[e]) {
        while (their.end != their.begin && (their.end - 1)->dist > rk[p] + tol) --their.end;
      } else {
        theirs = around(ref, ref_index, e, rk[p] + tol);
        their = span(theirs);
      }
      const double forward = directed(span(mine), core, their, limit);
      if (!std::isfinite(forward)) continue;
      best = std::min(best, std::max(forward, directed(their, core, span(mine), limit)));
    }
    if (best <= tol) {
      ++m.matched;
      m.closest = std::min(m.closest, best);
    }
  }
  return m;
}

namespace {

json report(const NeighbourhoodMatch& m, const NoveltyOptions& opt, double spacing, const char* measures) {
  const double share = m.share();
  return {{"measures", measures},
          {"k", opt.k},
          {"tolerance", opt.tolerance},
          {"unit", "the exemplar's mean nearest-neighbour distance (toroidal)"},
          {"spacing", num(spacing)},
          {"points", m.points},
          {"scored", m.scored},
          {"matched", m.matched},
          {"share", num(share)},
          {"closest", num(m.closest)},
          {"copy_share", opt.copy_share},
          {"copy", std::isfinite(share) ? json(share >= opt.copy_share) : json(nullptr)}};
}

// The exemplar's mean NN distance on its torus (exemplar units); NaN below 2 points.
double exemplar_spacing(const PointSet& exemplar) {
  return exemplar.size() >= 2 ? nn_stats(exemplar, true).mean : std::nan("");
}

PointSet in_exemplar_units(const PointSet& output, double zoom) {
  if (!(zoom > 0) || !std::isfinite(zoom)) throw InputError("novelty: the zoom must be a number > 0");
  const Domain& d = output.domain();
  return output.mapped_to(Domain{d.x0 / zoom, d.y0 / zoom, d.x1 / zoom, d.y1 / zoom});
}

}  // namespace

json novelty_report(const PointSet& exemplar, const PointSet& output, double zoom, const NoveltyOptions& opt) {
  const double s = exemplar_spacing(exemplar);
  NeighbourhoodMatch m;
  m.points = output.size();
  m.closest = kInf;
  if (s > 0) m = match_neighbourhoods(in_exemplar_units(output, zoom), exemplar, true, s, opt);
  return report(m, opt, s,
                "share of the output's points whose k-neighbourhood is a translated copy of one of the periodic "
                "exemplar's (within the tolerance); a copy flag when the share reaches copy_share");
}

json diversity_report(const PointSet& exemplar, const PointSet& output, const PointSet& other, double zoom,
                      const NoveltyOptions& opt) {
  const double s = exemplar_spacing(exemplar);
  NeighbourhoodMatch m;
  m.points = output.size();
  m.closest = kInf;
  if (s > 0) m = match_neighbourhoods(in_exemplar_units(output, zoom), in_exemplar_units(other, zoom), false, s, opt);
  return report(m, opt, s,
                "share of the output's points whose k-neighbourhood is a translated copy of one of the other output's "
                "(within the tolerance); flagged when the share reaches copy_share: the two are translates");
}

}  // namespace ppsynth
