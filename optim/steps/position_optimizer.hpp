#pragma once
// PositionOptimizer: one step on the moving output positions given a closure that
// recomputes the loss and its gradient. "adam" (the paper's; fresh state per stage, a
// learning rate per sigma) and "lbfgs" (the paper: "similar results"). A new optimizer is a
// class plus a PPSYNTH_REGISTER line.
#include <torch/torch.h>

#include <functional>
#include <map>
#include <string>

#include "core/registry.hpp"

namespace ppsynth {

// An optimizer's state as named tensors (moments, step counts, history), as a checkpoint
// holds it (optim/gabor/stages/synthesis_state.hpp); empty before the first step.
using OptimizerState = std::map<std::string, torch::Tensor>;

class PositionOptimizer {
 public:
  virtual ~PositionOptimizer() = default;
  // closure: zero grads are handled here; it returns the loss after backward().
  virtual double step(const std::function<torch::Tensor()>& closure) = 0;
  // The optimizer's state, and back: checkpoints restore it so a resumed stage takes the very
  // steps it would have taken. load_state checks every tensor against the parameters (shape,
  // type, finite, in range) and throws InputError naming `source` for a state that is not
  // this optimizer's.
  virtual OptimizerState save_state() const = 0;
  virtual void load_state(const OptimizerState& state, const std::string& source) = 0;
};

// Created per stage with the parameter tensor and the stage (sigma) index, so a learning-rate
// list can give each sigma its own rate.
using OptimizerRegistry = Registry<PositionOptimizer, torch::Tensor /*params*/, int /*sigma index*/>;

// `lr`, a number or a list (one per sigma; the last repeats), at a sigma; key_path: the optimizer's.
double learning_rate_for(const json& lr, int sigma_index, const std::string& key_path);

}  // namespace ppsynth
