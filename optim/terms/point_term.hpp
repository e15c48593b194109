#pragma once
// PointTerm: a loss on the output positions themselves, beside the paper's loss on the
// feature maps. None is in the paper and none runs unless configured, so every published run
// stays the paper's method. The synthesizer adds, at every evaluation of a class stage,
//
//   weight x (the paper's loss at the stage's first evaluation) x term(moving, frozen)
//
// so one weight serves every scene and sigma. A new term is one class registered under its
// name (PPSYNTH_REGISTER(PointTermRegistry, "name", {{"weight", 0.0}, ...}, ...)) and is
// switched on by `method.terms: {"name": {"weight": w, ...}}`; nothing else changes (the test
// "A point term registered in a test file acts in a synthesis" shows it).
// Registered: "separation" (optim/terms/separation_term.hpp), "pcf_match" (optim/terms/pcf_match_term.hpp).
#include <torch/torch.h>

#include <memory>
#include <string>
#include <vector>

#include "core/point_set.hpp"
#include "core/registry.hpp"
#include "optim/terms/weighted_terms.hpp"

namespace ppsynth {

// One class stage: which output points move (all of one class) and which are frozen.
struct ClassStage {
  const PointSet& exemplar;
  const PointSet& output;             // every point, positions as the stage starts
  const std::vector<size_t>& moving;  // indices into `output`
  const std::vector<size_t>& frozen;
  int upscale;
  torch::Device device = torch::kCPU;  // where evaluate() gets its positions (runtime.device)
};

class PointTerm {
 public:
  virtual ~PointTerm() = default;
  // Before a class stage's first sigma.
  virtual void begin_class(const ClassStage& stage) = 0;
  // The term at the wrapped moving positions (n x 2, may require grad) and the frozen ones
  // (m x 2 in `frozen`'s order; m may be 0). A scalar.
  virtual torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& frozen) = 0;
};

using PointTermRegistry = Registry<PointTerm>;

using WeightedPointTerm = WeightedTerm<PointTerm>;

// The terms `method.terms` switches on (weight > 0), in name order (optim/terms/weighted_terms.hpp).
inline std::vector<WeightedPointTerm> create_point_terms(const nlohmann::json& terms) {
  return create_weighted_terms<PointTerm>(terms, "method.terms");
}

}  // namespace ppsynth
