#include "core/generators/candidate_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/generators/sampling_util.hpp"

namespace ppsynth::gen_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Cells per point of the count the cells are cut for: finer cells see fewer points each but
// are more to update when a point is accepted.
constexpr double kCellsPerPoint = 4;
// The first cut's count; then every doubling.
constexpr size_t kFirstTarget = 16;
// Bounds are raised by this share so that rounding never cuts off a candidate that wins.
constexpr double kBoundSlack = 1e-9;

double squared_nearest(Vec2 q, const std::vector<Vec2>& sites) {
  double m = kInf;
  for (const Vec2& s : sites) m = std::min(m, (q.x - s.x) * (q.x - s.x) + (q.y - s.y) * (q.y - s.y));
  return m;
}

}  // namespace

double max_nearest_distance(const Domain& r, const std::vector<Vec2>& s) {
  if (s.empty()) return kInf;
  double best = 0;
  const auto consider = [&](Vec2 q) { best = std::max(best, squared_nearest(q, s)); };
  for (const Vec2 c : {Vec2{r.x0, r.y0}, Vec2{r.x1, r.y0}, Vec2{r.x0, r.y1}, Vec2{r.x1, r.y1}}) consider(c);
  for (size_t i = 0; i < s.size(); ++i)
    for (size_t j = i + 1; j < s.size(); ++j) {
      // The bisector of i and j: 2 q . (s_j - s_i) = |s_j|^2 - |s_i|^2, met with the four edges.
      const double dx = s[j].x - s[i].x, dy = s[j].y - s[i].y;
      const double rhs = 0.5 * ((s[j].x * s[j].x + s[j].y * s[j].y) - (s[i].x * s[i].x + s[i].y * s[i].y));
      if (dy != 0)
        for (double x : {r.x0, r.x1}) {
          const double y = (rhs - x * dx) / dy;
          if (y >= r.y0 && y <= r.y1) consider({x, y});
        }
      if (dx != 0)
        for (double y : {r.y0, r.y1}) {
          const double x = (rhs - y * dy) / dx;
          if (x >= r.x0 && x <= r.x1) consider({x, y});
        }
      for (size_t k = j + 1; k < s.size(); ++k) {
        // The circumcenter of i, j, k (a Voronoi vertex when no site is nearer).
        const double ex = s[k].x - s[i].x, ey = s[k].y - s[i].y;
        const double det = 2 * (dx * ey - dy * ex);
        if (det == 0) continue;
        const double a2 = dx * dx + dy * dy, b2 = ex * ex + ey * ey;
        const Vec2 c{s[i].x + (ey * a2 - dy * b2) / det, s[i].y + (dx * b2 - ex * a2) / det};
        if (c.x >= r.x0 && c.x <= r.x1 && c.y >= r.y0 && c.y <= r.y1) consider(c);
      }
    }
  return std::sqrt(best);
}

CandidateCells::CandidateCells(const Domain& d, const Domain& window, size_t n)
    : d_(d), window_(window), n_(n), window_area_(window.area()), points_(d, std::sqrt(d.area()), true) {
  rebuild(std::min(n, kFirstTarget));
}

void CandidateCells::rebuild(size_t target) {
  target_ = std::max<size_t>(target, 1);
  const double t = static_cast<double>(target_);
  DynamicGrid grid(d_, std::sqrt(d_.area() / t), /*periodic=*/true);
  for (const Vec2& p : points_.points()) grid.insert(p);
  points_ = std::move(grid);
  const double side = std::sqrt(d_.area() / (kCellsPerPoint * t));
  // At most about kCellsPerPoint * target cells, also for a strip far narrower than a cell.
  const double cap = 4 * kCellsPerPoint * t + 4;
  nx_ = static_cast<size_t>(std::clamp(std::ceil(d_.width() / side), 1.0, cap));
  ny_ = static_cast<size_t>(std::clamp(std::ceil(d_.height() / side), 1.0, std::max(1.0, cap / static_cast<double>(nx_))));
  cw_ = d_.width() / static_cast<double>(nx_);
  ch_ = d_.height() / static_cast<double>(ny_);
  const size_t cells = nx_ * ny_;
  largest_.assign(cells, kInf);
  area_.assign(cells, 0.0);
  slot_.assign(cells, -1);
  heap_.clear();
  for (size_t c = 0; c < cells; ++c) {
    const Domain r = rect(c);
    if (!(r.width() > 0) || !(r.height() > 0)) continue;
    area_[c] = r.area();
    heap_.push_back(static_cast<uint32_t>(c));
    measure(c);
  }
  const auto less = [&](uint32_t a, uint32_t b) { return largest_[a] < largest_[b]; };
  std::make_heap(heap_.begin(), heap_.end(), less);
  for (size_t t2 = 0; t2 < heap_.size(); ++t2) slot_[heap_[t2]] = static_cast<int64_t>(t2);
}

Domain CandidateCells::rect(size_t cell) const {
  const double x0 = d_.x0 + static_cast<double>(cell % nx_) * cw_, y0 = d_.y0 + static_cast<double>(cell / nx_) * ch_;
  return Domain{std::max(x0, window_.x0), std::max(y0, window_.y0), std::min(x0 + cw_, window_.x1),
                std::min(y0 + ch_, window_.y1)};
}

double CandidateCells::exact_nearest(Vec2 q, double guess) const {
  const double diag = std::hypot(d_.width(), d_.height());
  double lim = guess * (1 + kBoundSlack) + std::numeric_limits<double>::min(), dn;
  while ((dn = points_.nearest_within(q, lim)) >= lim && lim < diag) lim *= 2;
  return dn;
}

void CandidateCells::measure(size_t cell) {
  if (points_.size() == 0) {
    largest_[cell] = kInf;
    return;
  }
  const Domain r = rect(cell);
  const Vec2 c{0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1)};
  const double half_diagonal = 0.5 * std::hypot(r.width(), r.height());
  // A point nearest to some spot q of the cell is within f(q) <= f(c) + half_diagonal of q.
  const double spacing = std::sqrt(d_.area() / static_cast<double>(points_.size()));
  const double reach = exact_nearest(c, spacing) + 2 * half_diagonal;
  std::vector<Vec2> sites;
  points_.for_each_within(c, reach * (1 + kBoundSlack), [&](Vec2 v) { sites.push_back(v); });
  const Domain local{r.x0 - c.x, r.y0 - c.y, r.x1 - c.x, r.y1 - c.y};
  largest_[cell] = max_nearest_distance(local, sites) * (1 + kBoundSlack);
}

void CandidateCells::sift_down(size_t t) {
  const size_t n = heap_.size();
  const uint32_t cell = heap_[t];
  for (;;) {
    size_t child = 2 * t + 1;
    if (child >= n) break;
    if (child + 1 < n && largest_[heap_[child + 1]] > largest_[heap_[child]]) ++child;
    if (!(largest_[heap_[child]] > largest_[cell])) break;
    heap_[t] = heap_[child];
    slot_[heap_[t]] = static_cast<int64_t>(t);
    t = child;
  }
  heap_[t] = cell;
  slot_[cell] = static_cast<int64_t>(t);
}

void CandidateCells::accept(Vec2 p) {
  points_.insert(p);
  if (points_.size() >= target_ && target_ < n_) return rebuild(std::min(n_, 2 * target_));
  if (heap_.empty()) return;
  // p lowers the distances of a cell only if it is nearer to a spot q of it than f(q), at most
  // the cell's largest: within that plus the half-diagonal of its center, and the heap's top
  // bounds them all.
  const double half_diagonal = 0.5 * std::hypot(cw_, ch_);
  const double reach = largest_[heap_[0]] + half_diagonal;
  const double rx = std::isfinite(reach) ? std::ceil(reach / cw_) + 1 : static_cast<double>(nx_);
  const double ry = std::isfinite(reach) ? std::ceil(reach / ch_) + 1 : static_cast<double>(ny_);
  const bool all_x = 2 * rx + 1 >= static_cast<double>(nx_), all_y = 2 * ry + 1 >= static_cast<double>(ny_);
  const long NX = static_cast<long>(nx_), NY = static_cast<long>(ny_);
  const long cx = std::clamp(static_cast<long>(std::floor((p.x - d_.x0) / cw_)), 0L, NX - 1);
  const long cy = std::clamp(static_cast<long>(std::floor((p.y - d_.y0) / ch_)), 0L, NY - 1);
  const long x_lo = all_x ? 0 : cx - static_cast<long>(rx), x_hi = all_x ? NX - 1 : cx + static_cast<long>(rx);
  const long y_lo = all_y ? 0 : cy - static_cast<long>(ry), y_hi = all_y ? NY - 1 : cy + static_cast<long>(ry);
  for (long gy = y_lo; gy <= y_hi; ++gy)
    for (long gx = x_lo; gx <= x_hi; ++gx) {
      const size_t cell = static_cast<size_t>(((gy % NY) + NY) % NY) * nx_ + static_cast<size_t>(((gx % NX) + NX) % NX);
      if (slot_[cell] < 0) continue;
      const Domain r = rect(cell);
      const Vec2 v = torus_delta(Vec2{0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1)}, p, d_);
      if (std::hypot(v.x, v.y) >= largest_[cell] + 0.5 * std::hypot(r.width(), r.height())) continue;
      measure(cell);
      sift_down(static_cast<size_t>(slot_[cell]));
    }
}

Vec2 CandidateCells::best_of(size_t candidates, std::mt19937_64& rng) const {
  // The heap's nodes in decreasing order of bound: a node's children never exceed it.
  using Node = std::pair<double, size_t>;  // (largest distance, index in heap_)
  std::priority_queue<Node> frontier;
  if (!heap_.empty()) frontier.push({largest_[heap_[0]], 0});
  Vec2 best{};
  double best_d = -1, area_left = window_area_;
  size_t left = candidates, visited = 0;
  while (!frontier.empty() && left > 0) {
    const auto [bound, t] = frontier.top();
    frontier.pop();
    if (bound <= best_d) break;  // no candidate of this cell or a later one can be farther
    const uint32_t cell = heap_[t];
    size_t here = left;
    if (++visited < heap_.size()) {
      std::binomial_distribution<size_t> share(left, std::clamp(area_[cell] / area_left, 0.0, 1.0));
      here = share(rng);
    }
    left -= here;
    area_left -= area_[cell];
    const Domain r = rect(cell);
    for (size_t k = 0; k < here; ++k) {
      const Vec2 q = uniform_in(rng, r);
      const double dn = exact_nearest(q, bound);
      if (dn > best_d) {
        best_d = dn;
        best = q;
      }
    }
    for (size_t child : {2 * t + 1, 2 * t + 2})
      if (child < heap_.size()) frontier.push({largest_[heap_[child]], child});
  }
  if (best_d < 0) best = uniform_in(rng, window_);  // no cell meets the window (a degenerate window)
  return best;
}

}  // namespace ppsynth::gen_detail
