// NeighborIndex: nanoflann k-d tree, with 9 periodic images in toroidal mode.
#include "core/neighbors.hpp"

#include <algorithm>
#include <cmath>

#include <nanoflann.hpp>

#include "core/error.hpp"
#include "core/poll.hpp"

namespace ppsynth {

namespace {

struct Cloud {
  std::vector<Vec2> pts;
  size_t kdtree_get_point_count() const { return pts.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return dim == 0 ? pts[i].x : pts[i].y; }
  template <class BBOX>
  bool kdtree_get_bbox(BBOX&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                 Cloud, 2, size_t>;

double wrap_into(double v, double lo, double w) {
  double t = std::fmod(v - lo, w);
  if (t < 0) t += w;
  return lo + t;
}

// Periodic results: `idx` holds image indices (block * n + i) in increasing distance. Keeps
// the first (nearest) image of each point, in the original order, as point indices. Cost
// O(k log k) in the number of results: the former per-query table of n flags made every
// query O(n), so n queries (nearest neighbors of every point) were O(n^2).
void keep_nearest_images(std::vector<size_t>& idx, std::vector<double>& d2, size_t n) {
  std::vector<size_t> order(idx.size());
  for (size_t t = 0; t < idx.size(); ++t) {
    idx[t] %= n;
    order[t] = t;
  }
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return idx[a] != idx[b] ? idx[a] < idx[b] : a < b; });
  std::vector<char> keep(idx.size(), 0);
  for (size_t u = 0; u < order.size(); ++u)
    if (u == 0 || idx[order[u]] != idx[order[u - 1]]) keep[order[u]] = 1;
  size_t w = 0;
  for (size_t t = 0; t < idx.size(); ++t)
    if (keep[t]) idx[w] = idx[t], d2[w] = d2[t], ++w;
  idx.resize(w);
  d2.resize(w);
}

}  // namespace

struct NeighborIndex::Impl {
  Cloud cloud;
  size_t n = 0;
  bool periodic = false;
  Domain domain;
  std::unique_ptr<Tree> tree;

  Vec2 wrap(Vec2 q) const {
    if (!periodic) return q;
    return {wrap_into(q.x, domain.x0, domain.width()), wrap_into(q.y, domain.y0, domain.height())};
  }
};

NeighborIndex::NeighborIndex(const std::vector<Vec2>& pts, Domain domain, bool periodic)
    : impl_(std::make_unique<Impl>()) {
  impl_->n = pts.size();
  impl_->periodic = periodic || domain.periodic;
  impl_->domain = domain;
  if (impl_->periodic) {
    if (!(domain.width() > 0) || !(domain.height() > 0))
      throw InputError("NeighborIndex: toroidal domain must have a positive size");
    // Image block b = 0..8 holds point i at index b*n + i; block 0 is the identity.
    const double W = domain.width(), H = domain.height();
    const int sx[9] = {0, -1, 1, 0, 0, -1, -1, 1, 1};
    const int sy[9] = {0, 0, 0, -1, 1, -1, 1, -1, 1};
    impl_->cloud.pts.reserve(9 * pts.size());
    for (int b = 0; b < 9; ++b)
      for (const Vec2& p0 : pts) {
        Vec2 p = impl_->wrap(p0);
        impl_->cloud.pts.push_back({p.x + sx[b] * W, p.y + sy[b] * H});
      }
  } else {
    impl_->cloud.pts = pts;
  }
  impl_->tree = std::make_unique<Tree>(2, impl_->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  impl_->tree->buildIndex();
}

NeighborIndex::~NeighborIndex() = default;
NeighborIndex::NeighborIndex(NeighborIndex&&) noexcept = default;
NeighborIndex& NeighborIndex::operator=(NeighborIndex&&) noexcept = default;

size_t NeighborIndex::size() const { return impl_->n; }
bool NeighborIndex::periodic() const { return impl_->periodic; }

std::vector<size_t> NeighborIndex::knn(Vec2 q, size_t k, std::vector<double>* dist) const {
  poll();  // the metrics query once per point: a caller's stop check (core/poll.hpp) runs between
  const Impl& m = *impl_;
  k = std::min(k, m.n);
  std::vector<size_t> out;
  if (dist) dist->clear();
  if (k == 0) return out;
  q = m.wrap(q);
  const double qp[2] = {q.x, q.y};
  const size_t total = m.cloud.pts.size();
  // Periodic: ask for more images until k distinct points are found (at most 9k needed).
  std::vector<size_t> idx;
  std::vector<double> d2;
  for (size_t want = k;; want = std::min(total, want * 2)) {
    idx.resize(want);
    d2.resize(want);
    const size_t got = m.tree->knnSearch(qp, want, idx.data(), d2.data());
    idx.resize(got);
    d2.resize(got);
    if (m.periodic) keep_nearest_images(idx, d2, m.n);
    if (idx.size() >= k || want == total) {
      idx.resize(std::min(idx.size(), k));
      out.assign(idx.begin(), idx.end());
      if (dist) {
        dist->resize(out.size());
        for (size_t t = 0; t < out.size(); ++t) (*dist)[t] = std::sqrt(d2[t]);
      }
      return out;
    }
  }
}

size_t NeighborIndex::knn_into(Vec2 q, size_t k, size_t* idx, double* dist2) const {
  const Impl& m = *impl_;
  if (m.periodic) throw std::logic_error("NeighborIndex::knn_into: plane indices only");
  k = std::min(k, m.n);
  if (k == 0) return 0;
  const double qp[2] = {q.x, q.y};
  return m.tree->knnSearch(qp, k, idx, dist2);
}

std::vector<size_t> NeighborIndex::radius(Vec2 q, double r, std::vector<double>* dist) const {
  poll();
  const Impl& m = *impl_;
  std::vector<size_t> out;
  if (dist) dist->clear();
  if (m.n == 0 || !(r >= 0) || std::isnan(q.x) || std::isnan(q.y)) return out;
  q = m.wrap(q);
  const double qp[2] = {q.x, q.y};
  std::vector<std::pair<size_t, double>> found;
  // Squared radius; nudged so points at exactly r are included.
  m.tree->radiusSearch(qp, r * r * (1 + 1e-12), found, nanoflann::SearchParams(32, 0, true));
  std::vector<size_t> idx(found.size());
  std::vector<double> d2(found.size());
  for (size_t t = 0; t < found.size(); ++t) idx[t] = found[t].first, d2[t] = found[t].second;
  if (m.periodic) keep_nearest_images(idx, d2, m.n);
  if (dist) {
    dist->resize(d2.size());
    for (size_t t = 0; t < d2.size(); ++t) (*dist)[t] = std::sqrt(d2[t]);
  }
  return idx;
}

size_t NeighborIndex::nearest_other(size_t i, double* dist) const {
  const Impl& m = *impl_;
  if (m.n < 2) throw InputError("nearest_other: need at least 2 points");
  if (i >= m.n) throw InputError("nearest_other: index out of range");
  std::vector<double> d;
  auto idx = knn(m.cloud.pts[i], 2, &d);
  // Coincident points may come back in either order: take the first index that is not i.
  for (size_t t = 0; t < idx.size(); ++t)
    if (idx[t] != i) {
      if (dist) *dist = d[t];
      return idx[t];
    }
  throw InputError("nearest_other: no other point found");
}

double point_distance(Vec2 a, Vec2 b, const Domain& d, bool periodic) {
  double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  if (periodic || d.periodic) {
    const double W = d.width(), H = d.height();
    dx = std::fmod(dx, W);
    dy = std::fmod(dy, H);
    dx = std::min(dx, W - dx);
    dy = std::min(dy, H - dy);
  }
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace ppsynth
