#include "optim/gabor/stages/class_own_term.hpp"

#include <algorithm>

#include "models/point_tensor.hpp"

namespace ppsynth {

void ClassOwnMapTerm::begin_run(const MapTermRun& run) {
  exemplar_ = &run.exemplar;
  settings_ = run.settings;
  seed_ = run.seed;
  fresh_net_ = run.settings.options.fresh_net_per_class;
  if (run.exemplar.num_classes() > 1) pipe_ = std::make_unique<GaborPipeline>(run.settings, run.seed, run.device);
}

void ClassOwnMapTerm::begin_group(const MapTermGroup& g) {
  const Stage& stage = g.stage;
  if (!active(stage)) return;
  if (fresh_net_)  // as the joint pipeline's (window plans: a multiple of K groups per window)
    pipe_->redraw_network(class_network_seed(seed_, stage.group % exemplar_->num_classes()));
  const size_t own = exemplar_->subset_class(stage.own_class).size();
  pipe_->set_neighbors(settings_.options.k_per_stage ? static_cast<int>(std::min<size_t>(settings_.k, own)) : settings_.k);
  std::vector<int64_t> own_rows;  // rows of the frozen points of the moving class (a window's context)
  std::vector<size_t> weighted;   // their output indices, then the moving ones: evaluate()'s order
  for (size_t r = 0; r < g.frozen.size(); ++r)
    if (g.output.cls(g.frozen[r]) == stage.own_class) {
      own_rows.push_back(static_cast<int64_t>(r));
      weighted.push_back(g.frozen[r]);
    }
  own_frozen_ = own_rows.empty() ? torch::Tensor()
                                 : g.frozen_local.index_select(0, torch::tensor(own_rows).to(g.frozen_local.device()));
  weighted.insert(weighted.end(), g.moving.begin(), g.moving.end());
  // Weights as the joint maps' (GaborEngine::map_weights): each column over the class's every
  // output point, so a window sees the same scale as the whole output.
  out_weights_ = torch::Tensor();
  if (!settings_.attr_cols.empty()) {
    std::vector<size_t> all_own;
    for (size_t i = 0; i < g.output.size(); ++i)
      if (g.output.cls(i) == stage.own_class) all_own.push_back(i);
    const auto w = normalized_attributes(g.output.subset(all_own), settings_.attr_cols);
    std::vector<int64_t> rows;
    for (size_t i : weighted) rows.push_back(std::lower_bound(all_own.begin(), all_own.end(), i) - all_own.begin());
    out_weights_ = w.index_select(0, torch::tensor(rows)).to(pipe_->device());
  }
  measured_ = g.measured;
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
  const auto pts = own_frozen_.defined() ? torch::cat({own_frozen_, moving}) : moving;
  return pipe_->loss(measured_part(pipe_->features(pipe_->output_maps(pts, out_weights_, stage.sigma, jitter)), measured_));
}

}  // namespace ppsynth

// On by default (weight 1): on the joint maps alone a later class fills the holes the earlier
// ones left, whatever its own spacing (docs/explanation/method.md, "Beyond the paper").
namespace ppsynth {
namespace {
struct ClassOwnOptions {
  double weight = 1;
  static const ParamTable<ClassOwnOptions>& params() {
    static const ParamTable<ClassOwnOptions> t(
        "method.map_terms.class_own",
        {param("weight", &ClassOwnOptions::weight, "[0, inf)", "the loss on the moving class's own maps, against the joint maps' (0: off)")});
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::MapTermRegistry, "map_term", "class_own", ppsynth::ClassOwnOptions::params(),
                        "from the second class on, the loss on the moving class's own maps vs the exemplar class's own",
                        [](const ppsynth::ClassOwnOptions&, const std::string&) -> std::unique_ptr<ppsynth::MapTerm> {
                          return std::make_unique<ppsynth::ClassOwnMapTerm>();
                        })
