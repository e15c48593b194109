// The "pattern" stopping rule (issue 21): stop a sigma stage when its pattern stops getting
// closer to the exemplar's, whatever the loss still does. Every `check_every` iterations it
// measures the PCF MSE between the stage's points in play and the exemplar's points of the
// same classes (core/metrics/pcf.hpp: radii in each set's own r_max units, so a u x u output
// and its exemplar line up; the output on its torus, the exemplar and a window's grid as
// rectangles with the translation edge correction). It stops once `min_iterations` have run
// and the best value of the last `window` iterations is not `threshold` (relative) below the
// best before them: the pattern, as the evaluation sees it, has stopped improving.
//
// Why: the loss of a stage keeps falling for hundreds of iterations while the points only
// jitter around their places (the grid jitter of every iteration feeds Adam fresh noise);
// the loss rule waits for that tail (docs/performance.md, "Time to quality").
#include <algorithm>

#include "core/metrics/pcf.hpp"
#include "optim/stopping_rule.hpp"

namespace ppsynth {
namespace {

class PatternStoppingRule : public StoppingRule {
 public:
  PatternStoppingRule(int window, int check_every, double threshold, int min_iterations)
      : window_(window), check_every_(check_every), threshold_(threshold), min_iterations_(min_iterations) {}

  void begin_stage(const PointSet& exemplar_in_play) override { target_ = pcf(exemplar_in_play); }

  bool converged(const StageView& v, std::vector<double>& record) override {
    if ((v.iteration + 1) % check_every_ != 0) return false;
    PcfOptions o;
    o.periodic = v.periodic;
    record.push_back(curve_mse(pcf(v.points(), o), target_));
    const size_t recent = static_cast<size_t>(std::max(1, window_ / check_every_));
    if (v.iteration + 1 < min_iterations_ || record.size() <= recent) return false;
    const auto split = record.end() - static_cast<std::ptrdiff_t>(recent);
    const double before = *std::min_element(record.begin(), split), last = *std::min_element(split, record.end());
    return last > (1 - threshold_) * before;
  }

 private:
  int window_, check_every_;
  double threshold_;
  int min_iterations_;
  Curve target_;
};

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::StoppingRuleRegistry, "pattern",
                 (ppsynth::json{{"window", 50}, {"check_every", 10}, {"threshold", 0.02}, {"min_iterations", 30}}),
                 (ppsynth::json{{"window", "int [1, 1000000000]"}, {"check_every", "int [1, 1000000000]"},
                                {"threshold", "[0, 1]"}, {"min_iterations", "int [0, 1000000000]"}}),
                 "stop when the PCF MSE of the stage's points to the exemplar's has not improved by `threshold` (relative) in `window` iterations",
                 [](const ppsynth::json& p) -> std::unique_ptr<ppsynth::StoppingRule> {
                   return std::make_unique<ppsynth::PatternStoppingRule>(p["window"].get<int>(), p["check_every"].get<int>(),
                                                                         p["threshold"].get<double>(),
                                                                         p["min_iterations"].get<int>());
                 })
