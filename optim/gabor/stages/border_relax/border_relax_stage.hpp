#pragma once
// method.border_relax (not in the paper): after a class's sigma stages on the u x u torus,
// measured as one grid, points park along the grid's edge (the maps see no neighbors beyond
// it). The relax stage moves only the class's points within `band` of the edge, on the grid
// rolled by a new offset every iteration (so no edge stays where they are), for a fixed count
// (the pattern is the finished stage's, judged already), at its own rate, with a separation
// term. A class is relaxed when its share of points within 1 % of the edge exceeds `parked` x
// uniform points' share, or when an earlier class was relaxed (its pairs with the relaxed
// classes across the seam were never measured). Its options, each declared once: its block
// method.border_relax (border_relax_options.hpp), resolved where it registers; its record:
// parked_over_uniform and relaxed.
#include "optim/gabor/stages/border_relax/border_relax_options.hpp"
#include "optim/gabor/stages/stage_kind.hpp"

namespace ppsynth {

class BorderRelaxStage : public StageKind {
 public:
  explicit BorderRelaxStage(const BorderRelaxSettings& settings);
  std::string label() const override { return "border relax"; }
  int iteration_cap(const GaborSettings& settings) const override;
  bool judged() const override { return false; }
  bool rolls_grid() const override { return true; }
  bool after_all_classes() const override { return o_.after_all; }
  nlohmann::json optimizer(nlohmann::json spec, const GaborSettings& settings) const override;
  // The band's mask, from the positions the stage starts from; its record: the share that
  // decided ("parked_over_uniform") and whether it moved anything ("relaxed").
  StageStart start(const StageStartView& view) const override;
  void describe(nlohmann::json& stats) const override;
  std::string record_problem(const nlohmann::json& details) const override;
  const BorderRelaxSettings& options() const { return o_; }

 private:
  BorderRelaxSettings o_;
};

}  // namespace ppsynth
