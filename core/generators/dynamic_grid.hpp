#pragma once
// DynamicGrid: a uniform bucket grid over a domain that accepts insertions, for generators
// that add points one by one and need "nearest accepted point" queries (dart throwing, best
// candidate), where a static k-d tree would have to be rebuilt. Internal helper.
#include <cmath>
#include <limits>
#include <vector>

#include "core/generators/sampling_util.hpp"
#include "core/point_set.hpp"

namespace ppsynth::gen_detail {

class DynamicGrid {
 public:
  // `cell` is the target cell size (domain units); `periodic` wraps queries.
  DynamicGrid(const Domain& d, double cell, bool periodic) : d_(d), periodic_(periodic) {
    nx_ = std::max(1, std::min(4096, static_cast<int>(std::floor(d.width() / cell))));
    ny_ = std::max(1, std::min(4096, static_cast<int>(std::floor(d.height() / cell))));
    cw_ = d.width() / nx_;
    ch_ = d.height() / ny_;
    cells_.resize(static_cast<size_t>(nx_) * ny_);
  }
  void insert(Vec2 p) {
    pts_.push_back(p);
    cells_[cell_of(p)].push_back(pts_.size() - 1);
  }
  size_t size() const { return pts_.size(); }
  const std::vector<Vec2>& points() const { return pts_; }

  // Distance to the nearest inserted point if it is below `limit`, else `limit`.
  double nearest_within(Vec2 q, double limit) const {
    double best2 = limit * limit;
    const int rx = static_cast<int>(std::ceil(limit / cw_)), ry = static_cast<int>(std::ceil(limit / ch_));
    const int cx = cx_of(q.x), cy = cy_of(q.y);
    const bool all_x = 2 * rx + 1 >= nx_, all_y = 2 * ry + 1 >= ny_;
    const int x_lo = all_x ? 0 : cx - rx, x_hi = all_x ? nx_ - 1 : cx + rx;
    const int y_lo = all_y ? 0 : cy - ry, y_hi = all_y ? ny_ - 1 : cy + ry;
    for (int gy = y_lo; gy <= y_hi; ++gy) {
      int yy = gy;
      if (yy < 0 || yy >= ny_) {
        if (!periodic_) continue;
        yy = ((yy % ny_) + ny_) % ny_;
      }
      for (int gx = x_lo; gx <= x_hi; ++gx) {
        int xx = gx;
        if (xx < 0 || xx >= nx_) {
          if (!periodic_) continue;
          xx = ((xx % nx_) + nx_) % nx_;
        }
        for (size_t i : cells_[static_cast<size_t>(yy) * nx_ + xx]) {
          Vec2 dv = periodic_ ? torus_delta(q, pts_[i], d_) : Vec2{pts_[i].x - q.x, pts_[i].y - q.y};
          best2 = std::min(best2, dv.x * dv.x + dv.y * dv.y);
        }
      }
    }
    return std::sqrt(best2);
  }

  // Calls f(offset) for every inserted point within `r` of q, as its offset from q: on a
  // periodic domain every image of it within r (a radius beyond half the domain meets several).
  template <class F>
  void for_each_within(Vec2 q, double r, F&& f) const {
    const long rx = static_cast<long>(std::ceil(r / cw_)), ry = static_cast<long>(std::ceil(r / ch_));
    const long cx = cx_of(q.x), cy = cy_of(q.y), NX = nx_, NY = ny_;
    for (long gy = cy - ry; gy <= cy + ry; ++gy) {
      const long sy = floor_div(gy, NY);  // which copy of the domain, in y
      if (sy != 0 && !periodic_) continue;
      for (long gx = cx - rx; gx <= cx + rx; ++gx) {
        const long sx = floor_div(gx, NX);
        if (sx != 0 && !periodic_) continue;
        for (size_t i : cells_[static_cast<size_t>((gy - sy * NY) * NX + (gx - sx * NX))]) {
          const Vec2 v{pts_[i].x + static_cast<double>(sx) * d_.width() - q.x, pts_[i].y + static_cast<double>(sy) * d_.height() - q.y};
          if (v.x * v.x + v.y * v.y <= r * r) f(v);
        }
      }
    }
  }

 private:
  static long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  int cx_of(double x) const { return std::min(nx_ - 1, std::max(0, static_cast<int>((x - d_.x0) / cw_))); }
  int cy_of(double y) const { return std::min(ny_ - 1, std::max(0, static_cast<int>((y - d_.y0) / ch_))); }
  size_t cell_of(Vec2 p) const { return static_cast<size_t>(cy_of(p.y)) * nx_ + cx_of(p.x); }

  Domain d_;
  bool periodic_;
  int nx_, ny_;
  double cw_, ch_;
  std::vector<Vec2> pts_;
  std::vector<std::vector<size_t>> cells_;
};

}  // namespace ppsynth::gen_detail
