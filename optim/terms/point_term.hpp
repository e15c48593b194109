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
// A term runs on the paper's u x u torus; one that also knows a window of a rectangle output
// (optim/gabor/windows/window_plan.hpp: plane distances, no wrap) says so with in_windows(), and the
// others are refused there when the settings resolve (method.terms.<name>), before any output.
// Registered: "separation" (optim/terms/separation_term.hpp; torus and windows), "pcf_match"
// (optim/terms/pcf_match_term.hpp; torus only).
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
  // Where evaluate()'s positions live. 0: the unit torus (an output length as it is, an
  // exemplar length / upscale). > 0: a window's grid, this side in exemplar units (output
  // coordinates are exemplar units; positions are (p - corner) / side, and do not wrap).
  double window_side = 0;
};

class PointTerm {
 public:
  virtual ~PointTerm() = default;
  // Before a class stage's first sigma.
  virtual void begin_class(const ClassStage& stage) = 0;
  // The term at the wrapped moving positions (n x 2, may require grad) and the frozen ones
  // (m x 2 in `frozen`'s order; m may be 0). A scalar.
  virtual torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& frozen) = 0;
  // Whether the term knows a window (ClassStage::window_side > 0).
  virtual bool in_windows() const { return false; }
};

using PointTermRegistry = Registry<PointTerm>;

using WeightedPointTerm = WeightedTerm<PointTerm>;

// The terms `method.terms` switches on (weight > 0), in name order (optim/terms/weighted_terms.hpp).
inline std::vector<WeightedPointTerm> create_point_terms(const nlohmann::json& terms) {
  return create_weighted_terms<PointTerm>(terms, "method.terms");
}

// The windows of a rectangle output: every term switched on must know them; config_error
// naming method.terms.<name> otherwise.
inline void check_point_terms_in_windows(const nlohmann::json& terms) {
  check_terms_in_windows<PointTerm>(terms, "method.terms", "\"separation\"");
}

}  // namespace ppsynth
