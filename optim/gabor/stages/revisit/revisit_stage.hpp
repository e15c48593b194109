#pragma once
// method.revisit (not in the paper; alternating passes over the classes): the paper synthesizes
// classes one after another and never moves a class again, so class 0 is placed without the
// classes after it. A revisit stage follows every class's sigma stages (and any border relax):
// one stage per class, in the class order, at the finest sigma, where that class's points move
// beside every other class's (frozen) and the loss measures the targets of all classes, with
// the map terms of the moving class (class_own). The stopping rule judges it as a sigma stage
// and ends it on its best checked iterate. On by default (100 iterations a class at most;
// docs/lab/later_classes: on poisson_n64c2_point, Parterre10 and amacrine it brings the pair
// and the first class closer, and takes Parterre10's lattice class's PCF MSE from 0.084 to
// 0.057, for a sixth to a third more time); configs/methods/gabor_published.json turns it
// off for the paper's configs. It acts on several classes only: a one-class exemplar's plan
// holds no revisit stage.
// Its options, declared once in the table where it registers (revisit_stage.cpp):
//   iterations  the cap per class (0: off, the paper's)
//   lr          Adam's rate; null: the finest sigma's
#include <optional>

#include "core/config/params.hpp"
#include "optim/gabor/stages/stage_kind.hpp"

namespace ppsynth {

struct RevisitOptions {
  int iterations = 100;
  std::optional<double> lr;

  static const ParamTable<RevisitOptions>& params();
};

class RevisitStage : public StageKind {
 public:
  RevisitStage(int iterations, double lr) : iterations_(iterations), lr_(lr) {}
  std::string label() const override { return "revisit"; }
  int iteration_cap(const GaborSettings& settings) const override;
  bool judged() const override { return true; }
  bool rolls_grid() const override { return false; }
  bool after_all_classes() const override { return true; }
  bool acts_on(int classes) const override { return classes > 1; }  // one class: nothing placed beside it
  nlohmann::json optimizer(nlohmann::json spec, const GaborSettings& settings) const override;
  StageStart start(const StageStartView& view) const override;

 private:
  int iterations_;
  double lr_;  // 0: the finest sigma's
};

}  // namespace ppsynth
