#pragma once
// "class_own" map term (not in the paper; docs/explanation/method.md "Beyond the paper"): from the second
// class on, the paper's loss on the maps of the moving class ALONE against the exemplar's class
// alone. The joint maps constrain a later class only through the joint pattern; this term also
// asks for the class's own spacing. It uses a second pipeline (rasters with the class's own k,
// targets of the class alone) whose network is drawn from the run's seed, so both losses see
// the same random filters.
//
// In a window of a rectangle output the class's own maps hold its moving points and its frozen
// ones in the window's context (final from earlier windows), and the loss measures the grid's
// part the paper's loss measures.
#include <memory>

#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/stages/map_term.hpp"

namespace ppsynth {

class ClassOwnMapTerm : public MapTerm {
 public:
  void begin_run(const MapTermRun& run) override;
  void begin_group(const MapTermGroup& group) override;
  void begin_stage(const Stage& stage) override;
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage& stage) override;
  bool in_windows() const override { return true; }
  bool acts_on(int classes) const override { return classes > 1; }  // one class: the joint maps are its own

 private:
  // Not for the first class of the order: its joint maps are its own.
  bool active(const Stage& stage) const { return pipe_ && stage.target_classes.size() > 1; }

  std::unique_ptr<GaborPipeline> pipe_;  // null for a one-class exemplar: the joint maps are the class's own
  const PointSet* exemplar_ = nullptr;
  GaborSettings settings_;
  uint64_t seed_ = 0;
  bool fresh_net_ = false;
  torch::Tensor own_frozen_;    // the class's frozen points in the maps' coordinates (a window's context); may be empty
  torch::Tensor out_weights_;   // [own frozen; moving] map weights; undefined without attributes
  std::vector<double> measured_;
};

}  // namespace ppsynth
