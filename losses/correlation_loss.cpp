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

PPSYNTH_REGISTER(ppsynth::LossRegistry, "correlation",
                 (ppsynth::json{{"layers", {2}}, {"weight", 1.0}, {"gradient", "exact"}}),
                 (ppsynth::json{{"layers", "int [0, 15]"}, {"weight", "[0, inf)"}}),
                 "deep-correlation loss (global structure); gradient: exact | published",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::FeatureLoss> {
                   const std::string g = p["gradient"].get<std::string>();
                   ppsynth::CorrelationGradient mode;
                   if (g == "exact") mode = ppsynth::CorrelationGradient::Exact;
                   else if (g == "published") mode = ppsynth::CorrelationGradient::Published;
                   else throw ppsynth::config_error(key + ".gradient", "expected \"exact\" or \"published\", got \"" + g + "\"");
                   return std::make_unique<ppsynth::CorrelationLoss>(ppsynth::loss_layers(p, key), mode);
                 })
