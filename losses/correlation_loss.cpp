#include "losses/correlation_loss.hpp"

namespace ppsynth {

CorrelationLoss::CorrelationLoss(std::vector<int> layers, CorrelationGradient mode)
    : layers_(std::move(layers)), mode_(mode) {}

void CorrelationLoss::set_target(const Features& ex, const LossContext&) {
  targets_.clear();
  crops_.clear();
  for (int l : layers_) {
    const auto& F = layer_of(ex, l, "correlation");
    const int qh = static_cast<int>(F.size(2)), qw = static_cast<int>(F.size(3));
    crops_.emplace_back(qh, qw);
    targets_.push_back(deep_correlation(F.detach(), qh, qw).detach());
  }
}

torch::Tensor CorrelationLoss::forward(const Features& out) {
  torch::Tensor loss;
  for (size_t i = 0; i < layers_.size(); ++i) {
    auto c = deep_correlation(layer_of(out, layers_[i], "correlation"), crops_[i].first, crops_[i].second, mode_);
    auto d = (c - targets_[i]).pow(2).mean();
    loss = loss.defined() ? loss + d : d;
  }
  return loss;
}

}  // namespace ppsynth

namespace ppsynth {
namespace {
struct CorrelationOptions {
  std::vector<int> layers{2};
  double weight = 1.0;
  CorrelationGradient gradient = CorrelationGradient::Exact;
  static const ParamTable<CorrelationOptions>& params() {
    using O = CorrelationOptions;
    static const ParamTable<O> t("loss", [] {
      std::vector<Param<O>> keys = layer_loss_params<O>();
      keys.push_back(choice("gradient", &O::gradient, {{"exact", CorrelationGradient::Exact}, {"published", CorrelationGradient::Published}},
                            "the correlation's gradient: exact, or the published code's"));
      return keys;
    }());
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::LossRegistry, "loss", "correlation", ppsynth::CorrelationOptions::params(),
                        "deep-correlation loss (global structure); gradient: exact | published",
                        [](const ppsynth::CorrelationOptions& o, const std::string& key) -> std::unique_ptr<ppsynth::FeatureLoss> {
                          return std::make_unique<ppsynth::CorrelationLoss>(ppsynth::given_layers(o.layers, key), o.gradient);
                        })
