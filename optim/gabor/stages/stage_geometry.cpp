#include "optim/gabor/stages/stage_geometry.hpp"

#include <algorithm>

#include "core/memory_budget.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/stages/stage.hpp"

namespace ppsynth {

namespace {

bool inside(const Domain& d, const Vec2& p) { return p.x >= d.x0 && p.x <= d.x1 && p.y >= d.y0 && p.y <= d.y1; }

Domain intersection(const Domain& a, const Domain& b) {
  return Domain{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

}  // namespace

// --- the paper's unit torus

void TorusGeometry::choose_points(const Stage& stage, const PointSet&, const std::vector<uint8_t>&,
                                  const std::function<void()>&, std::vector<int64_t>& moving,
                                  std::vector<int64_t>& frozen) const {
  moving.assign(stage.moving.begin(), stage.moving.end());
  frozen.assign(stage.frozen.begin(), stage.frozen.end());
}

std::string TorusGeometry::restored_points_problem(const Stage& stage, const std::vector<int64_t>& moving,
                                                   const std::vector<int64_t>& frozen) const {
  auto same = [](const std::vector<int64_t>& a, const std::vector<size_t>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](int64_t x, size_t y) { return static_cast<size_t>(x) == y; });
  };
  return same(moving, stage.moving) && same(frozen, stage.frozen) ? "" : "points other than those of " + stage.label;
}

torch::Tensor TorusGeometry::to_local(const PointSet& points) const { return positions_tensor(points); }  // its own grid

torch::Tensor TorusGeometry::confine(const torch::Tensor& moving) const { return wrap_unit(moving); }

PointSet TorusGeometry::pattern(const torch::Tensor& local, int64_t, const std::vector<int>& classes, const Domain&) const {
  const auto a = local.accessor<double, 2>();
  PointSet ps(Domain{});
  for (int64_t i = 0; i < local.size(0); ++i) {
    const Vec2 p{a[i][0], a[i][1]};
    if (inside(ps.domain(), p)) ps.add(p, classes[static_cast<size_t>(i)]);
  }
  return ps;
}

// --- a window of a large canvas

void WindowGeometry::choose_points(const Stage& stage, const PointSet& out, const std::vector<uint8_t>& final_points,
                                   const std::function<void()>& poll, std::vector<int64_t>& moving,
                                   std::vector<int64_t>& frozen) const {
  int classes = 0;
  for (int c : stage.target_classes) classes = std::max(classes, c + 1);
  std::vector<char> in_play(static_cast<size_t>(classes), 0);
  for (int c : stage.target_classes) in_play[c] = 1;
  moving.clear();
  frozen.clear();
  for (size_t i = 0; i < out.size(); ++i) {
    if (i % 65536 == 0) poll();
    const int c = out.cls(i);
    if (c < 0 || c >= classes || !in_play[c]) continue;
    if (c == stage.own_class && !final_points[i] && inside(w_.movable, out[i]))
      moving.push_back(static_cast<int64_t>(i));
    else if (inside(w_.context, out[i]))
      frozen.push_back(static_cast<int64_t>(i));
  }
}

torch::Tensor WindowGeometry::to_local(const PointSet& points) const {
  auto xy = positions_tensor(points, torch::kFloat64);
  const Domain& g = w_.grid;
  xy = (xy - torch::tensor({{g.x0, g.y0}}, torch::kFloat64)) / g.width();
  return xy.to(torch::kFloat32);
}

torch::Tensor WindowGeometry::confine(const torch::Tensor& moving) const {
  // Kept inside the movable rectangle with an identity gradient (as wrap_unit's): a point
  // pushed past the edge sits on it, and the loss can still pull it back.
  // The bounds as scalars: nothing is made or copied to the device per iteration.
  const Domain& g = w_.grid;
  const Domain& m = w_.movable;
  const double unit = g.width();  // of both axes (to_local)
  const auto x = moving.select(1, 0).clamp((m.x0 - g.x0) / unit, (m.x1 - g.x0) / unit);
  const auto y = moving.select(1, 1).clamp((m.y0 - g.y0) / unit, (m.y1 - g.y0) / unit);
  return moving + (torch::stack({x, y}, 1) - moving).detach();
}

Vec2 WindowGeometry::to_output(double u, double v) const {
  const Domain& g = w_.grid;
  const Domain& m = w_.movable;
  return {std::clamp(g.x0 + g.width() * u, m.x0, m.x1), std::clamp(g.y0 + g.width() * v, m.y0, m.y1)};
}

std::vector<double> WindowGeometry::part_inside(const Domain& output) const {
  const Domain& g = w_.grid;
  const Domain o = intersection(g, output);
  return {(o.x0 - g.x0) / g.width(), (o.y0 - g.y0) / g.height(), (o.x1 - g.x0) / g.width(), (o.y1 - g.y0) / g.height()};
}

PointSet WindowGeometry::pattern(const torch::Tensor& local, int64_t frozen, const std::vector<int>& classes,
                                 const Domain& moving_area) const {
  const auto a = local.accessor<double, 2>();
  const Domain& g = w_.grid;
  // A window's pattern is its grid's part of where points move: a frozen exemplar pad
  // ("context") is the exemplar's, and counting it would hide how the moving points change.
  PointSet ps(intersection(g, moving_area));
  for (int64_t i = 0; i < local.size(0); ++i) {
    // Moving points as the stage's end writes them (held inside the movable part); frozen ones
    // where they are, which may be past the grid: those are the window's context, not its
    // pattern, and the filter leaves them out.
    const Vec2 p = i < frozen ? Vec2{g.x0 + g.width() * a[i][0], g.y0 + g.width() * a[i][1]} : to_output(a[i][0], a[i][1]);
    if (inside(ps.domain(), p)) ps.add(p, classes[static_cast<size_t>(i)]);
  }
  return ps;
}

void WindowGeometry::stages_done(const PointSet& out, std::vector<uint8_t>& final_points) const {
  // The window's own part is done: no later window moves it. Marked when the window's last
  // stage ends, not its class's: a revisit stage moves a class again after the other classes
  // (every point not final inside the interior was moved by one of the window's groups: its
  // movable part holds the interior, and frozen pad points are final from the start).
  for (size_t i = 0; i < out.size(); ++i)
    if (!final_points[i] && inside(w_.interior, out[i])) final_points[i] = 1;
}

// The heap kept for speed within a window (optim/run/runtime.hpp) must not grow window after window.
void WindowGeometry::window_done() const { release_freed_memory(); }

}  // namespace ppsynth
