#include "optim/position_optimizer.hpp"

#include <sstream>

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

double learning_rate_for(const json& p, int s, const std::string& kp) {
  const json& lr = p["lr"];
  double v = 0;
  if (lr.is_number()) v = lr.get<double>();
  else if (lr.is_array() && !lr.empty() && lr[0].is_number())
    v = lr[std::min<size_t>(static_cast<size_t>(s), lr.size() - 1)].get<double>();
  else throw config_error(kp + ".lr", "expected a number or a list of numbers");
  if (!(v > 0)) throw config_error(kp + ".lr", "must be > 0");
  return v;
}

namespace {

std::string save_optimizer(const torch::optim::Optimizer& o) {
  torch::serialize::OutputArchive a;
  o.save(a);
  std::ostringstream out;
  a.save_to(out);
  return out.str();
}

void load_optimizer(torch::optim::Optimizer& o, const std::string& bytes) {
  torch::serialize::InputArchive a;
  std::istringstream in(bytes);
  // The moments go where the positions are (a checkpoint is read on the CPU; runtime.device).
  a.load_from(in, o.param_groups().at(0).params().at(0).device());
  o.load(a);
}

class AdamPositions : public PositionOptimizer {
 public:
  AdamPositions(torch::Tensor p, double lr) : params_(p), adam_({p}, torch::optim::AdamOptions(lr)) {}
  double step(const std::function<torch::Tensor()>& closure) override {
    adam_.zero_grad();
    auto loss = closure();
    adam_.step();
    return loss.item<double>();
  }
  std::string save_state() const override { return save_optimizer(adam_); }
  void load_state(const std::string& bytes) override { load_optimizer(adam_, bytes); }

 private:
  torch::Tensor params_;
  torch::optim::Adam adam_;
};

class LbfgsPositions : public PositionOptimizer {
 public:
  LbfgsPositions(torch::Tensor p, double lr, int max_iter)
      : lbfgs_({p}, torch::optim::LBFGSOptions(lr).max_iter(max_iter)) {}
  double step(const std::function<torch::Tensor()>& closure) override {
    double first = 0;
    bool have = false;
    lbfgs_.step([&] {
      lbfgs_.zero_grad();
      auto l = closure();
      if (!have) first = l.item<double>(), have = true;
      return l;
    });
    return first;
  }
  std::string save_state() const override { return save_optimizer(lbfgs_); }
  void load_state(const std::string& bytes) override { load_optimizer(lbfgs_, bytes); }

 private:
  torch::optim::LBFGS lbfgs_;
};

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::OptimizerRegistry, "adam", (ppsynth::json{{"lr", {0.005, 0.002, 0.002, 0.002}}}),
                 (ppsynth::json{{"lr", "(0, inf)"}}),
                 "Adam, fresh state per stage; lr per sigma (published: 0.005, 0.002, 0.002, 0.002)",
                 [](const ppsynth::json& p, torch::Tensor params, int s) -> std::unique_ptr<ppsynth::PositionOptimizer> {
                   return std::make_unique<ppsynth::AdamPositions>(params, ppsynth::learning_rate_for(p, s, "optimizer"));
                 })
PPSYNTH_REGISTER(ppsynth::OptimizerRegistry, "lbfgs", (ppsynth::json{{"lr", {0.5, 0.2, 0.2, 0.2}}, {"max_iter", 20}}),
                 (ppsynth::json{{"lr", "(0, inf)"}, {"max_iter", "int [1, 10000]"}}),
                 "L-BFGS (published: lr 100x Adam's); one step = up to max_iter evaluations",
                 [](const ppsynth::json& p, torch::Tensor params, int s) -> std::unique_ptr<ppsynth::PositionOptimizer> {
                   return std::make_unique<ppsynth::LbfgsPositions>(params, ppsynth::learning_rate_for(p, s, "optimizer"),
                                                                   ppsynth::get_int(p, "max_iter", "optimizer"));
                 })
PPSYNTH_DEFAULTS_KIND("optimizer", ppsynth::OptimizerRegistry)
