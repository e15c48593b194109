#pragma once
// MapTerm: a loss beside the paper's that the Gabor engine evaluates from maps of its own
// (map space), for example the maps of the moving class alone. None is in the paper and none
// runs unless configured, so every published run stays the paper's method. The engine adds,
// at every evaluation of a stage,
//
//   weight x term(wrapped moving positions, the evaluation's jitter, stage)
//
// A new term is one class registered under its name (PPSYNTH_REGISTER(MapTermRegistry, "name",
// {{"weight", 0.0}, ...}, ...)) and is switched on by `method.map_terms: {"name": {"weight": w}}`;
// nothing else changes (tests/optim/gabor/test_map_terms.cpp registers one in the test file).
// A term runs on the paper's u x u torus; one that also knows a window of a rectangle output
// (its frozen context, the grid part the losses measure) says so with in_windows(), and the
// others are refused there when the settings resolve (method.map_terms.<name>).
// Registered: "class_own" (optim/gabor/stages/class_own_term.hpp; torus and windows). Point terms, on
// positions rather than maps, are optim/terms/point_term.hpp.
#include <torch/torch.h>

#include <cstdint>

#include "core/point_set.hpp"
#include "core/registry.hpp"
#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/stages/stage_plan.hpp"
#include "optim/terms/weighted_terms.hpp"

namespace ppsynth {

// What a term may build its maps from: the method's parameters and resolved settings (grid,
// k, attributes), the exemplar, the run's seed.
struct MapTermRun {
  const GaborSettings& settings;
  const PointSet& exemplar;
  uint64_t seed;
  torch::Device device = torch::kCPU;  // where the run's tensors live (runtime.device)
};

// A group of stages as it begins (a class of the paper's plan; a class in one window).
struct MapTermGroup {
  const Stage& stage;
  const PointSet& output;              // as the group starts
  const std::vector<size_t>& moving;   // output indices, in the order of evaluate()'s rows
  const std::vector<size_t>& frozen;   // output indices, in the order of frozen_local's rows
  const torch::Tensor& frozen_local;   // their positions in the maps' coordinates, on the device
  // The grid's part the paper's losses measure ({x0, y0, x1, y1} fractions; empty: all of it;
  // method.window.statistics "output").
  const std::vector<double>& measured;
};

class MapTerm {
 public:
  virtual ~MapTerm() = default;
  // Once, before the first stage (also when a run is resumed).
  virtual void begin_run(const MapTermRun& run) = 0;
  // When a group of stages begins, and at every stage of it (a sigma): targets are set here.
  virtual void begin_group(const MapTermGroup& group) = 0;
  virtual void begin_stage(const Stage& stage) = 0;
  // The term at the wrapped moving positions (n x 2, requires grad), with the jitter of the
  // paper's maps at this evaluation. An undefined tensor: the term is off in this stage.
  virtual torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage& stage) = 0;
  // Whether the term knows a window (frozen context, measured part).
  virtual bool in_windows() const { return false; }
  // Whether the term acts on an exemplar of `classes` classes at all. One that does not (a
  // per-class term on one class) leaves the run as if it were not configured: the border
  // relax and the measures that refuse map terms see none.
  virtual bool acts_on(int classes) const {
    (void)classes;
    return true;
  }
};

using MapTermRegistry = Registry<MapTerm>;
using WeightedMapTerm = WeightedTerm<MapTerm>;

// The terms `method.map_terms` switches on (weight > 0), in name order.
inline std::vector<WeightedMapTerm> create_map_terms(const nlohmann::json& terms) {
  return create_weighted_terms<MapTerm>(terms, "method.map_terms");
}

// Whether any term `method.map_terms` switches on acts on an exemplar of `classes` classes.
inline bool map_terms_act(const nlohmann::json& terms, int classes) {
  for (const auto& t : create_map_terms(terms))
    if (t.term->acts_on(classes)) return true;
  return false;
}

// The windows of a rectangle output: every term switched on must know them; config_error
// naming method.map_terms.<name> otherwise.
inline void check_map_terms_in_windows(const nlohmann::json& terms) {
  check_terms_in_windows<MapTerm>(terms, "method.map_terms", "\"class_own\"");
}

}  // namespace ppsynth
