#pragma once
// "class_own" map term (not in the paper; docs/explanation/method.md "Beyond the paper"): from the second
// class on, the paper's loss on the maps of the moving class ALONE against the exemplar's class
// alone. The joint maps constrain a later class only through the joint pattern; this term also
// asks for the class's own spacing. It uses a second pipeline (rasters with the class's own k,
// targets of the class alone) whose network is drawn from the run's seed, so both losses see
// the same random filters.
#include <memory>

#include "optim/gabor/map_term.hpp"

namespace ppsynth {

class ClassOwnMapTerm : public MapTerm {
 public:
  void begin_run(const MapTermRun& run) override;
  void begin_group(const Stage& stage, const PointSet& output) override;
  void begin_stage(const Stage& stage) override;
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage& stage) override;

 private:
  bool active(const Stage& stage) const { return pipe_ && stage.group > 0; }

  std::unique_ptr<GaborPipeline> pipe_;  // null for a one-class exemplar: the joint maps are the class's own
  const PointSet* exemplar_ = nullptr;
  GaborSettings settings_;
  uint64_t seed_ = 0;
  bool fresh_net_ = false;
  torch::Tensor out_weights_;
};

}  // namespace ppsynth
