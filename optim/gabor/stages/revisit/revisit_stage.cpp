#include "optim/gabor/stages/revisit/revisit_stage.hpp"

#include <algorithm>

#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/stages/stage.hpp"

namespace ppsynth {

const ParamTable<RevisitOptions>& RevisitOptions::params() {
  using R = RevisitOptions;
  static const ParamTable<R> t("method.revisit", {
      param("iterations", &R::iterations, "int [0, 1000000000]",
            "after every class's sigma stages, each class moves again beside all the others, up to this many iterations (0: off, the paper's)"),
      param("lr", &R::lr, "(0, inf)", "Adam's rate in the revisit stages; null: the finest sigma's"),
  });
  return t;
}

int RevisitStage::iteration_cap(const GaborSettings& settings) const {
  // --quick caps every stage at the sigma stages' count, as it does the border relax.
  return settings.quick ? std::min(iterations_, settings.max_iterations) : iterations_;
}

nlohmann::json RevisitStage::optimizer(nlohmann::json spec, const GaborSettings&) const {
  if (lr_ > 0) spec["lr"] = nlohmann::json::array({lr_});  // else the finest sigma's
  return spec;
}

StageStart RevisitStage::start(const StageStartView&) const {
  StageStart st;
  st.note = "every point of the class moves again, beside every other class";
  return st;
}

PPSYNTH_REGISTER_STAGE_KIND("revisit", RevisitOptions::params(),
                            "method.revisit: after every class's sigma stages, each class moves again beside all the others",
                            [](const RevisitOptions& o, const std::string&, const GaborSettings&) -> std::unique_ptr<StageKind> {
                              if (o.iterations <= 0) return nullptr;
                              return std::make_unique<RevisitStage>(o.iterations, o.lr ? *o.lr : 0.0);
                            })

}  // namespace ppsynth
