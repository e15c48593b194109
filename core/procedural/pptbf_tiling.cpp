#include "core/procedural/pptbf_tiling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/procedural/pptbf_random.hpp"

namespace ppsynth::pptbf_impl {

std::uint64_t CellKey::hash() const {
  return hash_keys(0x1234, static_cast<std::uint64_t>(part * 64 + sub), i, j);
}

TilingSpec tiling_spec(int t) {
  TilingSpec s;
  switch (t) {
    case 0: s.name = "regular"; break;
    case 1: s.name = "regular+sub"; s.subdiv_prob = 0.5; break;
    case 2: s.name = "regular+allsub+relax"; s.subdiv_prob = 1.0; s.relax_iters = 5; break;
    case 3: s.name = "regular+sub+relax"; s.subdiv_prob = 0.5; s.relax_iters = 5; break;
    case 4: s.name = "brick"; s.row_shift_div = 2; break;
    case 5: s.name = "third-shift"; s.row_shift_div = 3; break;
    case 6: s.name = "irregular"; s.randx = 0.8; s.randy = 0.8; break;
    case 7: s.name = "irregular+sub"; s.randx = 0.8; s.randy = 0.8; s.subdiv_prob = 0.5; break;
    case 8: s.name = "irregular-x"; s.randx = 0.8; break;
    case 9: s.name = "irregular-x+sub"; s.randx = 0.8; s.subdiv_prob = 0.5; break;
    case 10: s.name = "herringbone2"; s.pavement = Pavement::Herringbone; s.herringbone_len = 2; break;
    case 11: s.name = "herringbone2+sub"; s.pavement = Pavement::Herringbone; s.herringbone_len = 2; s.subdiv_prob = 0.5; break;
    case 12: s.name = "herringbone3"; s.pavement = Pavement::Herringbone; s.herringbone_len = 3; break;
    case 13: s.name = "herringbone3+sub"; s.pavement = Pavement::Herringbone; s.herringbone_len = 3; s.subdiv_prob = 0.5; break;
    case 14: s.name = "bisquare"; s.pavement = Pavement::Pythagorean; break;
    case 15: s.name = "bisquare+sub"; s.pavement = Pavement::Pythagorean; s.subdiv_prob = 0.5; break;
    case 16: s.name = "apavement"; s.pavement = Pavement::APavement; break;
    case 17: s.name = "apavement+sub"; s.pavement = Pavement::APavement; s.subdiv_prob = 0.5; break;
    default: throw InputError("tile_type " + std::to_string(t) + " is not in 0..17");
  }
  return s;
}

namespace {
Rect unit_rect(double x, double y, double w, double h, double s) {
  return Rect{{x * s, y * s}, {(x + w) * s, (y + h) * s}};
}
}  // namespace

PointProcess::PointProcess(int tile_type, double jitter, std::uint64_t seed)
    : tile_type_(tile_type), spec_(tiling_spec(tile_type)), jitter_(jitter), seed_(seed) {
  switch (spec_.pavement) {
    case Pavement::Grid: break;
    case Pavement::Herringbone: {
      // Staircase of L x 1 horizontal and 1 x L vertical bricks: period (1,1) and (0,2L).
      const int L = spec_.herringbone_len;
      const double s = 1.0 / (2 * L);
      lat_a_ = {s, s};
      lat_b_ = {0, 2 * L * s};
      layout_ = {unit_rect(0, 0, L, 1, s), unit_rect(0, 1, 1, L, s)};
      break;
    }
    case Pavement::Pythagorean: {
      // Squares of side 2 and 1 (in fifths): period (2,1) and (-1,2).
      const double s = 1.0 / 5.0;
      lat_a_ = {2 * s, 1 * s};
      lat_b_ = {-1 * s, 2 * s};
      layout_ = {unit_rect(0, 0, 2, 2, s), unit_rect(2, 0, 1, 1, s)};
      break;
    }
    case Pavement::APavement: {
      // A 4x4 block of mixed rectangles (our own layout); blocks stacked with a shift of 1.
      const double s = 1.0 / 4.0;
      lat_a_ = {4 * s, 0};
      lat_b_ = {1 * s, 4 * s};
      layout_ = {unit_rect(0, 0, 2, 2, s), unit_rect(2, 0, 1, 1, s), unit_rect(3, 0, 1, 2, s),
                 unit_rect(2, 1, 1, 1, s), unit_rect(0, 2, 1, 2, s), unit_rect(1, 2, 2, 1, s),
                 unit_rect(3, 2, 1, 1, s), unit_rect(1, 3, 1, 1, s), unit_rect(2, 3, 2, 1, s)};
      break;
    }
  }
}

void PointProcess::grid_cells(const Rect& box, std::vector<BaseCell>& out) const {
  const int div = spec_.row_shift_div;
  auto cut_y = [&](std::int64_t j) {
    return spec_.randy == 0 ? 0.0 : 0.5 * spec_.randy * CellRng(seed_, kStreamTileCutY, j).rand();
  };
  auto cut_x = [&](std::int64_t i, std::int64_t j) {
    return spec_.randx == 0 ? 0.0 : 0.5 * spec_.randx * CellRng(seed_, kStreamTileCutX, i, j).rand();
  };
  const auto j0 = static_cast<std::int64_t>(std::floor(box.lo.y)) - 1;
  const auto j1 = static_cast<std::int64_t>(std::floor(box.hi.y)) + 1;
  for (std::int64_t j = j0; j <= j1; ++j) {
    const double ylo = j + cut_y(j), yhi = j + 1 + cut_y(j + 1);
    if (yhi <= box.lo.y || ylo >= box.hi.y) continue;
    const double shift = static_cast<double>(((j % div) + div) % div) / div;
    const auto i0 = static_cast<std::int64_t>(std::floor(box.lo.x - shift)) - 1;
    const auto i1 = static_cast<std::int64_t>(std::floor(box.hi.x - shift)) + 1;
    for (std::int64_t i = i0; i <= i1; ++i) {
      BaseCell c;
      c.rect = Rect{{i + shift + cut_x(i, j), ylo}, {i + 1 + shift + cut_x(i + 1, j), yhi}};
      c.key = CellKey{i, j, 0, 0};
      if (c.rect.intersects(box)) out.push_back(c);
    }
  }
}

void PointProcess::periodic_cells(const Rect& box, std::vector<BaseCell>& out) const {
  // lattice coordinates (u, v) with x = u a + v b
  const double det = lat_a_.x * lat_b_.y - lat_a_.y * lat_b_.x;
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (Vec2 q : {box.lo, box.hi, Vec2{box.lo.x, box.hi.y}, Vec2{box.hi.x, box.lo.y}}) {
    const double u = (q.x * lat_b_.y - q.y * lat_b_.x) / det;
    const double v = (lat_a_.x * q.y - lat_a_.y * q.x) / det;
    umin = std::min(umin, u); umax = std::max(umax, u);
    vmin = std::min(vmin, v); vmax = std::max(vmax, v);
  }
  const int margin = 3;  // rectangles reach beyond their period's parallelogram
  for (auto n = static_cast<std::int64_t>(std::floor(vmin)) - margin; n <= std::ceil(vmax) + margin; ++n)
    for (auto m = static_cast<std::int64_t>(std::floor(umin)) - margin; m <= std::ceil(umax) + margin; ++m) {
      const Vec2 t{m * lat_a_.x + n * lat_b_.x, m * lat_a_.y + n * lat_b_.y};
      for (size_t r = 0; r < layout_.size(); ++r) {
        BaseCell c;
        c.rect = Rect{{layout_[r].lo.x + t.x, layout_[r].lo.y + t.y}, {layout_[r].hi.x + t.x, layout_[r].hi.y + t.y}};
        c.key = CellKey{m, n, static_cast<int>(r), 0};
        if (c.rect.intersects(box)) out.push_back(c);
      }
    }
}

void PointProcess::base_cells_in_box(const Rect& box, std::vector<BaseCell>& out) const {
  if (spec_.pavement == Pavement::Grid) grid_cells(box, out);
  else periodic_cells(box, out);
}

std::vector<FeaturePoint> PointProcess::unrelaxed_points_of(const BaseCell& cell) const {
  const CellKey& k = cell.key;
  std::vector<Rect> parts{cell.rect};
  if (spec_.subdiv_prob > 0) {
    CellRng rng(seed_, kStreamSubdivide, k.i, k.j, k.part);
    if (rng.rand01() < spec_.subdiv_prob) {
      const Rect r = cell.rect;
      const Vec2 s = r.size();
      if (std::abs(s.x - s.y) < 0.2 * std::max(s.x, s.y)) {  // squarish: 4-way split
        const double cx = r.lo.x + s.x * (0.5 + 0.18 * rng.rand());
        const double cy = r.lo.y + s.y * (0.5 + 0.18 * rng.rand());
        parts = {Rect{r.lo, {cx, cy}}, Rect{{cx, r.lo.y}, {r.hi.x, cy}},
                 Rect{{r.lo.x, cy}, {cx, r.hi.y}}, Rect{{cx, cy}, r.hi}};
      } else if (s.x > s.y) {  // 2-way along x
        const double cx = r.lo.x + s.x * (0.4 + 0.2 * rng.rand01());
        parts = {Rect{r.lo, {cx, r.hi.y}}, Rect{{cx, r.lo.y}, r.hi}};
      } else {
        const double cy = r.lo.y + s.y * (0.4 + 0.2 * rng.rand01());
        parts = {Rect{r.lo, {r.hi.x, cy}}, Rect{{r.lo.x, cy}, r.hi}};
      }
    }
  }
  std::vector<FeaturePoint> pts;
  pts.reserve(parts.size());
  for (size_t s = 0; s < parts.size(); ++s) {
    FeaturePoint fp;
    fp.key = CellKey{k.i, k.j, k.part, static_cast<int>(s)};
    fp.c = parts[s].lo;
    fp.d = parts[s].size();
    CellRng rng(seed_, kStreamJitter, k.i, k.j, k.part * 8 + static_cast<int>(s));
    const Vec2 ctr = parts[s].center();
    const double rx = rng.rand(), ry = rng.rand();
    fp.p = {ctr.x + jitter_ * 0.9 * rx * fp.d.x / 2, ctr.y + jitter_ * 0.9 * ry * fp.d.y / 2};
    pts.push_back(fp);
  }
  return pts;
}

std::vector<FeaturePoint> PointProcess::points_of(const BaseCell& cell) {
  if (spec_.relax_iters == 0) return unrelaxed_points_of(cell);
  auto it = relaxed_cache_.find(cell.key);
  if (it != relaxed_cache_.end()) return it->second;
  std::vector<FeaturePoint> own = unrelaxed_points_of(cell);
  // fixed neighbors: unrelaxed points of the cells around this one
  std::vector<BaseCell> around;
  const Vec2 c = cell.rect.center();
  base_cells_in_box(Rect{{c.x - 1.5, c.y - 1.5}, {c.x + 1.5, c.y + 1.5}}, around);
  std::vector<Vec2> fixed;
  for (const BaseCell& b : around) {
    if (b.key == cell.key) continue;
    for (const FeaturePoint& q : unrelaxed_points_of(b)) fixed.push_back(q.p);
  }
  for (int it_r = 0; it_r < spec_.relax_iters; ++it_r) {
    std::vector<Vec2> moved(own.size());
    for (size_t k = 0; k < own.size(); ++k) {
      const Vec2 q = own[k].p;
      // three nearest neighbors among fixed + other own points
      double best[3] = {1e300, 1e300, 1e300};
      Vec2 bp[3] = {q, q, q};
      auto consider = [&](Vec2 n) {
        const double d = std::hypot(n.x - q.x, n.y - q.y);
        if (d < best[0]) { best[2] = best[1]; bp[2] = bp[1]; best[1] = best[0]; bp[1] = bp[0]; best[0] = d; bp[0] = n; }
        else if (d < best[1]) { best[2] = best[1]; bp[2] = bp[1]; best[1] = d; bp[1] = n; }
        else if (d < best[2]) { best[2] = d; bp[2] = n; }
      };
      for (Vec2 n : fixed) consider(n);
      for (size_t o = 0; o < own.size(); ++o) if (o != k) consider(own[o].p);
      Vec2 dir{0, 0};
      for (int m = 0; m < 3; ++m) {
        if (best[m] >= 1e299 || best[m] == 0) continue;
        dir.x += (bp[m].x - q.x) / (best[m] * best[m]);
        dir.y += (bp[m].y - q.y) / (best[m] * best[m]);
      }
      const double no = std::hypot(dir.x, dir.y);
      Vec2 nq = q;
      if (no > 0) { nq.x -= 0.05 * dir.x / no; nq.y -= 0.05 * dir.y / no; }
      const FeaturePoint& f = own[k];
      const double mx = std::min(0.05, 0.25 * f.d.x), my = std::min(0.05, 0.25 * f.d.y);
      nq.x = std::clamp(nq.x, f.c.x + mx, f.c.x + f.d.x - mx);
      nq.y = std::clamp(nq.y, f.c.y + my, f.c.y + f.d.y - my);
      moved[k] = nq;
    }
    for (size_t k = 0; k < own.size(); ++k) own[k].p = moved[k];
  }
  relaxed_cache_.emplace(cell.key, own);
  return own;
}

void PointProcess::points_in_box(const Rect& box, std::vector<FeaturePoint>& out) {
  std::vector<BaseCell> cells;
  base_cells_in_box(box, cells);
  for (const BaseCell& c : cells) {
    std::vector<FeaturePoint> pts = points_of(c);
    out.insert(out.end(), pts.begin(), pts.end());
  }
}

void PointProcess::points_near(Vec2 x, double reach, std::vector<FeaturePoint>& out) {
  points_in_box(Rect{{x.x - reach, x.y - reach}, {x.x + reach, x.y + reach}}, out);
}

}  // namespace ppsynth::pptbf_impl
