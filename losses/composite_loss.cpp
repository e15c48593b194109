#include "losses/composite_loss.hpp"

namespace ppsynth {

CompositeLoss::CompositeLoss(const json& specs, const std::string& key_path) {
  if (!specs.is_array() || specs.empty()) throw config_error(key_path, "expected a non-empty array of losses");
  for (size_t i = 0; i < specs.size(); ++i) {
    const std::string kp = key_path + "[" + std::to_string(i) + "]";
    json resolved;
    auto loss = LossRegistry::instance().create(specs[i], kp, &resolved);
    const double w = get_number(resolved, "weight", kp);
    terms_.push_back(Term{resolved["type"], w, std::move(loss), {}});
    resolved_.push_back(resolved);
  }
}

void CompositeLoss::set_target(const Features& ex, const LossContext& ctx) {
  for (auto& t : terms_) t.loss->set_target(ex, ctx);
}

torch::Tensor CompositeLoss::forward(const Features& out) {
  torch::Tensor total;
  for (auto& t : terms_) {
    auto v = t.loss->forward(out);
    t.last = v.detach();
    auto wv = v * t.weight;
    total = total.defined() ? total + wv : wv;
  }
  return total;
}

}  // namespace ppsynth
