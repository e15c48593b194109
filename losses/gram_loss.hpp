#pragma once
// Gram-matrix loss (paper §3.1): sum over layers of the squared Frobenius distance between
// output and exemplar Gram matrices G = F F^T / (C H W).
#include "losses/loss.hpp"

namespace ppsynth {

torch::Tensor gram_matrix(const torch::Tensor& F);  // 1 x C x H x W -> C x C

class GramLoss : public FeatureLoss {
 public:
  explicit GramLoss(std::vector<int> layers);
  void set_target(const Features& exemplar, const LossContext& ctx) override;
  torch::Tensor forward(const Features& output) override;

 private:
  std::vector<int> layers_;
  std::vector<torch::Tensor> targets_;
};

}  // namespace ppsynth
