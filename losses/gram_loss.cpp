// "gram": L = sum over layers of sum_{t1,t2} (G_out - G_exemplar)^2, G = F F^T / (C H W)
// (paper §3.1; the published code's normalisation). Captures local structure.
#include "losses/gram_loss.hpp"

namespace ppsynth {

torch::Tensor gram_matrix(const torch::Tensor& F) {
  auto f = F.reshape({F.size(1), -1});
  return torch::mm(f, f.t()) / static_cast<double>(F.numel());
}

GramLoss::GramLoss(std::vector<int> layers) : layers_(std::move(layers)) {}

void GramLoss::set_target(const Features& ex, const LossContext&) {
  targets_.clear();
  for (int l : layers_) targets_.push_back(gram_matrix(layer_of(ex, l, "gram")).detach());
}

torch::Tensor GramLoss::forward(const Features& out) {
  torch::Tensor loss;
  for (size_t i = 0; i < layers_.size(); ++i) {
    auto d = (gram_matrix(layer_of(out, layers_[i], "gram")) - targets_[i]).pow(2).sum();
    loss = loss.defined() ? loss + d : d;
  }
  return loss;
}

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::LossRegistry, "gram", (ppsynth::json{{"layers", {0, 1, 2}}, {"weight", 0.08}}),
                 "Gram-matrix loss over the listed layers (local structure)",
                 [](const ppsynth::json& p) -> std::unique_ptr<ppsynth::FeatureLoss> {
                   return std::make_unique<ppsynth::GramLoss>(ppsynth::loss_layers(p, "gram"));
                 })
