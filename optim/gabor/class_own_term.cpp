#include "optim/gabor/class_own_term.hpp"

#include <algorithm>

#include "models/point_tensor.hpp"

namespace ppsynth {

void ClassOwnMapTerm::begin_run(const MapTermRun& run) {
  exemplar_ = &run.exemplar;
  settings_ = run.settings;
  seed_ = run.seed;
  fresh_net_ = run.settings.fresh_net_per_class;
  if (run.exemplar.num_classes() > 1) pipe_ = std::make_unique<GaborPipeline>(run.params, run.settings, run.seed, run.device);
}

void ClassOwnMapTerm::begin_group(const Stage& stage, const PointSet& output) {
  if (!active(stage)) return;
  if (fresh_net_) pipe_->redraw_network(seed_ + 7919ull * stage.group);  // as the joint pipeline's
  const size_t own = exemplar_->subset_class(stage.own_class).size();
  pipe_->set_neighbors(settings_.k_per_stage ? static_cast<int>(std::min<size_t>(settings_.k, own)) : settings_.k);
  out_weights_ = settings_.attr_cols.empty()
                     ? torch::Tensor()
                     : normalized_attributes(output.subset(stage.moving), settings_.attr_cols).to(pipe_->device());
}

void ClassOwnMapTerm::begin_stage(const Stage& stage) {
  if (!active(stage)) return;
  pipe_->set_grid(stage.sigma_index);  // the joint pipeline's grid of this sigma (its jitter's size)
  const PointSet ex_own = exemplar_->subset_class(stage.own_class);
  pipe_->set_targets(positions_tensor(ex_own),
                     settings_.attr_cols.empty() ? torch::Tensor() : normalized_attributes(ex_own, settings_.attr_cols),
                     stage.sigma);
}

torch::Tensor ClassOwnMapTerm::evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage& stage) {
  if (!active(stage)) return {};
  return pipe_->loss(pipe_->features(pipe_->output_maps(moving, out_weights_, stage.sigma, jitter)));
}

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::MapTermRegistry, "class_own", (nlohmann::json{{"weight", 0.0}}),
                 (nlohmann::json{{"weight", "[0, inf)"}}),
                 "from the second class on, the loss on the moving class's own maps vs the exemplar class's own",
                 [](const nlohmann::json&, const std::string&) -> std::unique_ptr<ppsynth::MapTerm> {
                   return std::make_unique<ppsynth::ClassOwnMapTerm>();
                 })
