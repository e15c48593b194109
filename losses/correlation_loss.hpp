#pragma once
// Deep-correlation loss (paper Eq. 3-4, method.md §4): the mean over channels and kept lags
// of (C_out - C_exemplar)^2, where C is the normalized autocorrelation of each channel of
// the layer, cropped to the exemplar layer's q x q central lags for both. Captures the
// global (regular, long-range) structure. "gradient": "exact" (default) or "published".
#include "losses/autocorrelation.hpp"
#include "losses/loss.hpp"

namespace ppsynth {

class CorrelationLoss : public FeatureLoss {
 public:
  CorrelationLoss(std::vector<int> layers, CorrelationGradient mode);
  void set_target(const Features& exemplar, const LossContext& ctx) override;
  torch::Tensor forward(const Features& output) override;

 private:
  std::vector<int> layers_;
  CorrelationGradient mode_;
  std::vector<torch::Tensor> targets_;
  std::vector<std::pair<int, int>> crops_;
};

}  // namespace ppsynth
