#pragma once
// CompositeLoss: the weighted sum of the losses a config lists (paper Eq. 7:
// L = L_corr + 0.08 L_gram). Keeps each term's last value for progress and loss curves.
#include <memory>
#include <string>
#include <vector>

#include "losses/loss.hpp"

namespace ppsynth {

class CompositeLoss {
 public:
  // `specs`: array of {"type": ..., "weight": ..., "layers": [...], ...}; key_path names it.
  CompositeLoss(const json& specs, const std::string& key_path = "losses");
  void set_target(const Features& exemplar, const LossContext& ctx);
  torch::Tensor forward(const Features& output);

  struct Term {
    std::string type;
    double weight;
    std::unique_ptr<FeatureLoss> loss;
    // Unweighted, from the last forward; kept as a tensor so that a forward on a CUDA device
    // does not wait for the device (read it when needed).
    torch::Tensor last;
    double last_value() const { return last.defined() ? last.item<double>() : 0.0; }
  };
  const std::vector<Term>& terms() const { return terms_; }
  const json& resolved() const { return resolved_; }  // specs with defaults filled in

 private:
  std::vector<Term> terms_;
  json resolved_ = json::array();
};

}  // namespace ppsynth
