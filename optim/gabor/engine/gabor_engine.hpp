#pragma once
// GaborEngine: runs a SynthesisPlan (optim/gabor/stages/stage_plan.hpp) over explicit state
// (optim/gabor/stages/synthesis_state.hpp), one stage after another:
//
//   stage:  targets <- exemplar classes -> Rasterizer -> FeatureNet -> CompositeLoss target
//           repeat: wrap(moving) + frozen -> Rasterizer(u) -> FeatureNet -> CompositeLoss
//                   (method.measure "tiles": cut into exemplar-sized tiles at a random
//                   offset, each -> Rasterizer -> FeatureNet -> CompositeLoss, averaged;
//                   optim/gabor/stages/random_tiles.hpp)
//                   (windows: confine(moving) + frozen, in the window's coordinates)
//                   [+ map terms on maps of their own (optim/gabor/stages/map_term.hpp); not in the paper]
//                   [+ point terms on the positions (optim/terms/point_term.hpp); not in the paper]
//                   -> backward -> PositionOptimizer step        (until the StoppingRule)
//
// What a stage does with its points (which move, for how long, rolled or not, at which rate,
// with which terms of its own) is its kind's (optim/gabor/stages/stage_kind.hpp): the paper's sigma
// stage, or the border relax after a class's (optim/gabor/stages/border_relax/border_relax_stage.hpp).
//
// Everything that changes while it runs lives in the state, so the state can be saved at any
// iteration (SynthesisContext::save_checkpoint) and a run restored from it takes the very
// same steps. Everything else (targets, networks, rasterizers) is a function of the config,
// the exemplar, the seed and the stage, and is rebuilt on entering a stage.
//
// Two plans: the paper's u x u unit square read as a torus (optim/gabor/stages/stage_plan.hpp), and a
// rectangle in exemplar units synthesized on one grid over a canvas padded for clean borders
// (window by window past the memory budget), then cropped, or with the pad held by the
// exemplar's own points, frozen (optim/gabor/windows/window_plan.hpp; core/output_shape.hpp).
#include <chrono>
#include <memory>
#include <random>

#include "optim/gabor/engine/gabor_stats.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/stages/map_term.hpp"
#include "optim/method/method.hpp"
#include "optim/terms/point_term.hpp"
#include "optim/steps/position_optimizer.hpp"
#include "optim/gabor/stages/stage_plan.hpp"
#include "optim/steps/stopping_rule.hpp"
#include "optim/gabor/stages/synthesis_state.hpp"
#include "optim/gabor/windows/window_plan.hpp"

namespace ppsynth {

class GaborEngine {
 public:
  GaborEngine(const GaborParams& params, const PointSet& exemplar, const SynthesisContext& ctx);
  // Runs the plan from the state (fresh, or restored from ctx.resume_state) to the end.
  PointSet run();
  const GaborStats& stats() const { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;

  void restore(const std::string& bytes);
  // Every index, count and flag of the restored state against the plan and the output;
  // InputError naming `source` otherwise.
  void check_restored(const std::string& source) const;
  void enter_group(const Stage& stage);   // networks, neighbors, point terms of a new group
  torch::Tensor map_weights(const std::vector<size_t>& rows, const std::vector<int>& classes) const;
  void enter_stage(const Stage& stage);   // targets and a fresh (or restored) optimizer
  void run_stage(const Stage& stage);
  torch::Tensor evaluate(const Stage& stage);  // the loss at the current positions, after backward
  // The paper's loss of one raster: the output's grid, or a tile of it on the exemplar's grid.
  torch::Tensor measure(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& jitter,
                        const Stage& stage, bool tile);
  void finish_stage(const Stage& stage);
  void save_checkpoint();
  PointSet points_in_play() const;  // the stage's moving and frozen points on its domain
  GaborRuntime runtime_record() const;  // device, precision, determinism, maps path (run.json's "runtime")
  PointSet synthesized() const;     // out_ without a frozen exemplar pad, on the area where points move
  ProgressEvent event(const Stage& stage) const;
  int iteration_cap(const Stage& stage) const;  // its kind's

  const PointSet& exemplar_;
  OutputShape shape_;
  WindowLayout layout_;  // rectangles only
  const SynthesisContext& ctx_;
  // Every tensor of the synthesis lives here (runtime.device); the output PointSet stays on the
  // CPU, and positions cross at group and stage boundaries only (and when the stopping rule
  // reads the pattern).
  torch::Device device_;
  GaborSettings s_;
  std::unique_ptr<GaborPipeline> pipe_;
  std::vector<WeightedMapTerm> map_terms_;
  std::vector<WeightedPointTerm> terms_;
  std::unique_ptr<StoppingRule> rule_;
  SynthesisPlan plan_;
  std::vector<std::shared_ptr<StageKind>> kinds_;  // the plan's stage kinds, each once, in plan order
  PointSet out_;
  size_t pad_begin_ = 0;  // out_[pad_begin_..] is the frozen exemplar pad ("border": "context")
  SynthesisState state_;
  std::mt19937_64 jitter_rng_;
  GaborPhaseSeconds phases_;  // wall time per phase, accumulated over the run
  GaborStats stats_;

  // The current group and stage (rebuilt from the plan and the state).
  int group_ = -1;
  std::shared_ptr<const StageGeometry> geometry_;  // the group's: the unit torus, or a window
  std::vector<size_t> moving_idx_, frozen_idx_;
  torch::Tensor frozen_, out_weights_;
  // method.window.statistics = "output": the grid's part inside the output rectangle, as
  // fractions of the grid {x0, y0, x1, y1}; empty: the losses measure the whole grid.
  std::vector<double> measured_;
  // What the stage's kind decided as it started; its mask on the device: the moving points
  // without it get no gradient, so a fresh Adam leaves them where they are.
  StageStart start_;
  std::unique_ptr<PositionOptimizer> optimizer_;
  Clock::time_point stage_start_, last_checkpoint_, run_start_;
  double seconds_before_ = 0;  // wall time of the processes before a resume (from the checkpoint)
  double cpu_before_ = 0;      // their CPU time (from the checkpoint; -1: unknown, a checkpoint without it)
  double cpu_at_start_ = 0;    // this process's CPU time when the run began
};

}  // namespace ppsynth
