#include "optim/gabor/stages/border_relax/border_relax_stage.hpp"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "core/metrics/border.hpp"
#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/stages/stage_plan.hpp"
#include "optim/terms/weighted_terms.hpp"

namespace ppsynth {

namespace {

// The moving points' share within 1 % of the unit square's edge, over uniform points' share.
double parked_over_uniform(const PointSet& output, const std::vector<size_t>& moving) {
  PointSet own;  // the u x u torus's unit square
  for (size_t i : moving) own.add(output[i]);
  return moving.empty() ? 0.0 : border_fraction(own) / uniform_border_fraction(own.domain());
}

// [moving x 1]: the moving points within `band` of the unit square's edge.
torch::Tensor border_band(const PointSet& output, const std::vector<size_t>& moving, double band) {
  auto mask = torch::zeros({static_cast<int64_t>(moving.size()), 1}, torch::kBool);
  auto m = mask.accessor<bool, 2>();
  for (size_t i = 0; i < moving.size(); ++i) {
    const Vec2 p = output[moving[i]];
    m[static_cast<int64_t>(i)][0] = p.x < band || p.x > 1 - band || p.y < band || p.y > 1 - band;
  }
  return mask;
}

}  // namespace

BorderRelaxStage::BorderRelaxStage(const BorderRelaxSettings& o) : o_(o) {
  terms_ = create_weighted_terms<PointTerm>(json{{"separation", {{"weight", o_.separation}}}}, "method.border_relax");
}

int BorderRelaxStage::iteration_cap(const GaborSettings&) const { return o_.iterations; }

nlohmann::json BorderRelaxStage::optimizer(nlohmann::json spec, const GaborSettings&) const {
  if (o_.lr > 0) spec["lr"] = json::array({o_.lr});  // else the finest sigma's
  return spec;
}

StageStart BorderRelaxStage::start(const StageStartView& v) const {
  const double parked = parked_over_uniform(v.output, v.moving);
  // Relaxed when it parks, or when an earlier class was relaxed, parked or not: its sigma
  // stages measured the unrolled grid, where its pairs with the relaxed classes across the
  // seam were never seen (lemon_4c_v2's later classes: docs/lab/large_outputs.md). The
  // records are the checkpoint's, so a resumed run decides as the uninterrupted one.
  const bool relax = o_.parked <= 0 || parked > o_.parked ||
                     std::any_of(v.finished_stages.begin(), v.finished_stages.end(),
                                 [](const StageRecord& r) { return r.details.value("relaxed", false); });
  StageStart st;
  st.moving_mask = relax ? border_band(v.output, v.moving, o_.band)
                         : torch::zeros({static_cast<int64_t>(v.moving.size()), 1}, torch::kBool);
  const bool moves = st.moving_mask.any().item<bool>();
  st.note = fmt::format("{:.2f} x uniform points' share within 1 % of the edge (method.border_relax.parked {:g}): {}",
                        parked, o_.parked, moves ? "relaxing its band" : "nothing to move");
  st.record = {{"parked_over_uniform", parked}, {"relaxed", moves}};
  return st;
}

void BorderRelaxStage::describe(nlohmann::json& stats) const {
  for (const auto& t : terms_) stats["border_relax_terms"][t.name] = t.weight;
}

std::string BorderRelaxStage::record_problem(const nlohmann::json& d) const {
  if (d.contains("relaxed") && !d["relaxed"].is_boolean()) return "'relaxed' is not true or false";
  if (d.contains("parked_over_uniform") && !d["parked_over_uniform"].is_number()) return "'parked_over_uniform' is not a number";
  return "";
}

PPSYNTH_REGISTER_STAGE_KIND("border_relax", BorderRelaxOptions::params(),
                            "method.border_relax: after each class's sigma stages, its points near the torus's grid edge move",
                            [](const BorderRelaxOptions& block, const std::string&, const GaborSettings& s) -> std::unique_ptr<StageKind> {
                              // What the rest of the settings say about where a relax can run.
                              BorderRelaxContext where;
                              where.rectangle = s.rectangle;
                              where.measured_whole = s.options.measure == GaborOptions::Measure::grid;
                              where.quick = s.quick;
                              where.max_iterations = s.max_iterations;
                              where.mean_nn_distance = s.mean_nn_distance;
                              where.upscale = s.upscale;
                              const BorderRelaxSettings o = BorderRelaxSettings::resolve(block, where);
                              if (o.iterations <= 0) return nullptr;
                              return std::make_unique<BorderRelaxStage>(o);
                            })

}  // namespace ppsynth
