// The "loss" stopping rule (the default): the paper's §5, "the decrease of loss during the
// most recent 100 iterations is smaller than 1%", as the published code checks it: every
// `check_every` iterations, once more than `window` have run, stop when
//     (L[n - window] - L[n - 1]) / (L[0] - L[n - 1]) < threshold
// with L the stage's per-iteration losses (n of them). With the defaults it can first fire
// at iteration 110.
#include "core/config/defaults_catalog.hpp"
#include "optim/steps/stopping_rule.hpp"

namespace ppsynth {
namespace {

struct LossRuleOptions {
  int window = 100;
  int check_every = 10;
  double threshold = 0.01;
  static const ParamTable<LossRuleOptions>& params() {
    using O = LossRuleOptions;
    // check_every 0 would divide by zero; a window of 0 compares a loss with itself
    static const ParamTable<O> t("method.convergence", {
        param("window", &O::window, "int [1, 1000000000]", "the iterations whose decrease is compared with the stage's"),
        param("check_every", &O::check_every, "int [1, 1000000000]", "iterations between two checks"),
        param("threshold", &O::threshold, "[0, inf)", "the fraction of the stage's decrease below which it stops"),
    });
    return t;
  }
};

class LossStoppingRule : public StoppingRule {
 public:
  LossStoppingRule(int window, int check_every, double threshold)
      : window_(window), check_every_(check_every), threshold_(threshold) {}

  StopVerdict judge(const StageView& v, std::vector<double>&) override {
    const auto& L = v.losses;
    const int n = static_cast<int>(L.size());
    if (v.iteration % check_every_ != 0 || n <= window_) return {};
    const double init = L.front(), pre = L[n - window_], now = L[n - 1];
    // A loss that rose over the whole stage gives a negative ratio: the published code then
    // stops too (the comparison is the same).
    const double denom = init - now;
    if (denom == 0) return {true, false};
    return {(pre - now) / denom < threshold_, false};
  }

 private:
  int window_, check_every_;
  double threshold_;
};

}  // namespace
}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("convergence", ppsynth::StoppingRuleRegistry)

PPSYNTH_REGISTER_PARAMS(ppsynth::StoppingRuleRegistry, "convergence", "loss", ppsynth::LossRuleOptions::params(),
                        "the paper's rule: the loss fell by less than `threshold` of the stage's decrease over the last `window` iterations",
                        [](const ppsynth::LossRuleOptions& o, const std::string&) -> std::unique_ptr<ppsynth::StoppingRule> {
                          return std::make_unique<ppsynth::LossStoppingRule>(o.window, o.check_every, o.threshold);
                        })
