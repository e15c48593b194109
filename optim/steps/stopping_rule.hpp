#pragma once
// StoppingRule: when a sigma stage has converged (besides its iteration cap), by registered
// name under "method.convergence": {"type": name, ...params}.
//
//   "loss"     the paper's rule as the published code checks it (§5: the loss fell by less
//              than 1 % of the stage's whole decrease over the last 100 iterations);
//              the default (optim/steps/loss_stopping_rule.cpp).
//   "pattern"  watches the pattern instead of the loss: the PCFs of the stage's points
//              against the exemplar's stop improving (optim/steps/pattern_stopping_rule.cpp;
//              the loss keeps falling slowly after the points have stopped
//              changing what any metric sees).
//
// A rule is asked after every iteration. What it remembers of the stage goes into `record`,
// which the engine keeps in the checkpoint (optim/gabor/stages/synthesis_state.hpp), so a resumed stage
// stops at the same iteration as one never interrupted. A rule that measures the pattern may
// also mark an iterate as the stage's best so far: the engine then keeps a copy of those
// positions (also checkpointed) and ends the stage on them rather than on its last iterate.
#include <functional>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "core/registry.hpp"

namespace ppsynth {

// The stage as a rule sees it after one iteration.
struct StageView {
  const std::vector<double>& losses;  // the stage's losses so far; losses.back() is this iteration's
  int iteration = 0;                  // 0-based index of this iteration in the stage; -1: the stage's start
  // The stage's points in play now (moving and frozen points of its classes, with their
  // classes) on the stage's domain; built only when called (a copy of the positions).
  std::function<PointSet()> points;
  bool periodic = false;  // the domain is a torus (the paper's unit square)
  double zoom = 1;        // the points' units per exemplar unit (1/u on the paper's square)
};

// A rule's verdict after one iteration.
struct StopVerdict {
  bool stop = false;  // the stage has converged
  bool best = false;  // this iterate is the stage's best so far and the stage should end on it
};

class StoppingRule {
 public:
  virtual ~StoppingRule() = default;
  // A stage starts (or resumes): the exemplar's points of the stage's classes, and the class
  // whose points move (-1: none named; the stage's points as one pattern).
  virtual void begin_stage(const PointSet& exemplar_in_play, int moving_class) {
    (void)exemplar_in_play;
    (void)moving_class;
  }
  // After each iteration, and once at the stage's start (iteration -1: no loss yet, the
  // points where the previous stage left them; a stop there is ignored), so that a rule
  // keeping the best iterate can keep the start when the stage only worsens the pattern.
  // `record` is this rule's memory of the stage so far (empty at the stage's start;
  // checkpointed).
  virtual StopVerdict judge(const StageView& view, std::vector<double>& record) = 0;
  // What the rule saw of a finished stage, from its `record`, for the stage's line of
  // run.json (empty: nothing to add). Why: whether a stage ended on its start, or where its
  // best came, says what a cheaper rule would have cut; the record alone can say it.
  virtual nlohmann::json summary(const std::vector<double>& record) const {
    (void)record;
    return nlohmann::json::object();
  }
};

using StoppingRuleRegistry = Registry<StoppingRule>;

}  // namespace ppsynth
