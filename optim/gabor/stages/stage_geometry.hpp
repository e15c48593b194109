#pragma once
// Where a stage's points live and how they are held there: a policy of the plan, as the
// stage's kind is (optim/gabor/stages/stage_kind.hpp). The engine asks its stage's geometry, never
// which one it is:
//
//   TorusGeometry   the paper's u x u output read as the unit torus: the plan names the
//                   group's points, positions wrap, the maps' grid is the output itself
//   WindowGeometry  a rectangle output's canvas, or one window of it (optim/gabor/windows/window_plan.hpp): its points are
//                   chosen by position as its group starts, held inside its movable rectangle,
//                   and final once inside its interior at the group's end
#include <torch/torch.h>

#include <functional>
#include <string>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct Stage;

// A window's rectangles in output coordinates. The maps' grid covers the rectangle `grid`;
// positions enter the maps in its local coordinates, (p - corner) / width along both axes (the
// grid's rows keep the columns' spacing, models/feature_grid.hpp). The group's moving
// points are the class's points inside `movable` not yet final; frozen are the other points
// of the stage's classes inside `context` (the grid and the reach of the maps beyond it).
// Moving points stay inside `movable`; the ones inside `interior` when the group ends are
// final (no later window moves them).
struct StageWindow {
  Domain grid{};
  Domain movable{}, interior{}, context{};
  int index = 0, count = 1;  // window i of n (0-based)
};

class StageGeometry {
 public:
  virtual ~StageGeometry() = default;
  virtual int index() const = 0;      // window i of count() (0-based): progress and snapshots
  virtual int count() const = 0;
  virtual Domain grid() const = 0;    // the maps' rectangle in output coordinates (its width: the local unit)
  virtual bool periodic() const = 0;  // the pattern the stopping rule judges is a torus
  // The group's moving and frozen points (output indices) as it starts.
  virtual void choose_points(const Stage& stage, const PointSet& out, const std::vector<uint8_t>& final_points,
                             const std::function<void()>& poll, std::vector<int64_t>& moving,
                             std::vector<int64_t>& frozen) const = 0;
  // A group restored from a checkpoint: "" when its points may be the group's, else what is wrong.
  virtual std::string restored_points_problem(const Stage& stage, const std::vector<int64_t>& moving,
                                              const std::vector<int64_t>& frozen) const = 0;
  virtual torch::Tensor to_local(const PointSet& points) const = 0;      // output -> grid coordinates, float32
  virtual torch::Tensor confine(const torch::Tensor& moving) const = 0;  // held in place, identity gradient
  // A moving point's grid-local position (u, v) in output coordinates. Local positions are
  // float: a point held at the movable edge in float maps back up to a few 1e-8 beyond it, and
  // an output point outside its domain is one the readers refuse.
  virtual Vec2 to_output(double u, double v) const = 0;
  // The grid's part inside `output` as fractions {x0, y0, x1, y1} of the grid; empty: all of it.
  virtual std::vector<double> part_inside(const Domain& output) const = 0;
  // The points in play as the stopping rule judges them, from local positions [frozen; moving]
  // (CPU, float64; the first `frozen` rows frozen) and each row's class; `moving_area`: where
  // points move.
  virtual PointSet pattern(const torch::Tensor& local, int64_t frozen, const std::vector<int>& classes,
                           const Domain& moving_area) const = 0;
  // The geometry's last stage ended (a window: its classes' stages and the after-all stages,
  // the revisit, that move them again): its points that no later stage moves get
  // final_points[i] = 1.
  virtual void stages_done(const PointSet& out, std::vector<uint8_t>& final_points) const = 0;
  // The window's last stage ended.
  virtual void window_done() const = 0;
};

class TorusGeometry : public StageGeometry {
 public:
  int index() const override { return 0; }
  int count() const override { return 1; }
  Domain grid() const override { return Domain{}; }
  bool periodic() const override { return true; }
  void choose_points(const Stage& stage, const PointSet& out, const std::vector<uint8_t>& final_points,
                     const std::function<void()>& poll, std::vector<int64_t>& moving, std::vector<int64_t>& frozen) const override;
  std::string restored_points_problem(const Stage& stage, const std::vector<int64_t>& moving,
                                      const std::vector<int64_t>& frozen) const override;
  torch::Tensor to_local(const PointSet& points) const override;
  torch::Tensor confine(const torch::Tensor& moving) const override;
  Vec2 to_output(double u, double v) const override { return {u, v}; }
  std::vector<double> part_inside(const Domain&) const override { return {}; }
  PointSet pattern(const torch::Tensor& local, int64_t frozen, const std::vector<int>& classes,
                   const Domain& moving_area) const override;
  void stages_done(const PointSet&, std::vector<uint8_t>&) const override {}
  void window_done() const override {}
};

class WindowGeometry : public StageGeometry {
 public:
  explicit WindowGeometry(const StageWindow& window) : w_(window) {}
  int index() const override { return w_.index; }
  int count() const override { return w_.count; }
  Domain grid() const override { return w_.grid; }
  bool periodic() const override { return false; }
  const StageWindow& window() const { return w_; }
  void choose_points(const Stage& stage, const PointSet& out, const std::vector<uint8_t>& final_points,
                     const std::function<void()>& poll, std::vector<int64_t>& moving, std::vector<int64_t>& frozen) const override;
  std::string restored_points_problem(const Stage&, const std::vector<int64_t>&, const std::vector<int64_t>&) const override {
    return "";  // chosen by position: the checkpoint's choice is the one to go on with
  }
  torch::Tensor to_local(const PointSet& points) const override;
  torch::Tensor confine(const torch::Tensor& moving) const override;
  Vec2 to_output(double u, double v) const override;
  std::vector<double> part_inside(const Domain& output) const override;
  PointSet pattern(const torch::Tensor& local, int64_t frozen, const std::vector<int>& classes,
                   const Domain& moving_area) const override;
  void stages_done(const PointSet& out, std::vector<uint8_t>& final_points) const override;
  void window_done() const override;  // its buffers go back to the kernel

 private:
  StageWindow w_;
};

}  // namespace ppsynth
