#pragma once
// SynthesisMethod: "exemplar in, larger pattern out". The paper's Gabor method and the
// baselines (thesis Chapter 3 and Chapter 4) are all methods, registered by config name and
// chosen with `ppsynth synthesize --method NAME` or the config's "method" object, so every
// runner and report handles a new method with no code change.
//
// This header is torch-free on purpose: baselines in optim/baselines/ build without LibTorch.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "core/registry.hpp"

namespace ppsynth {

// What a method reports while it runs. Apps attach observers (progress line, snapshot
// writer, loss-curve recorder); methods never print or write files themselves.
struct ProgressEvent {
  std::string stage;        // e.g. "class 1/2, sigma 3/4" or "scale 2"
  int stage_index = 0;      // 0-based over the whole run
  int stage_count = 1;
  int iteration = 0;        // within the stage
  int max_iterations = 0;   // cap within the stage (0 = unknown)
  double loss = 0;
  double seconds = 0;       // wall time since the stage began
};

class SynthesisObserver {
 public:
  virtual ~SynthesisObserver() = default;
  // The output before optimisation (the initialisation), once.
  virtual void on_start(const PointSet& initial) {}
  virtual void on_stage_begin(const ProgressEvent&) {}
  virtual void on_iteration(const ProgressEvent&) {}
  // `current` is the whole output so far (frozen and moving points, with classes/attrs).
  virtual void on_stage_end(const ProgressEvent&, const PointSet& current) {}
};

// Everything a method gets besides its own parameters.
struct SynthesisContext {
  uint64_t seed = 95;
  int upscale = 2;  // u: output has u*u times the exemplar's points, features 1/u as wide
  std::vector<SynthesisObserver*> observers;
  // Optional explicit initialisation (else the method's own initialiser runs).
  const PointSet* initialization = nullptr;
  bool quick = false;  // tiny grids and few iterations (tests, --quick)
  // Optional: the method records what it measured here (iterations and final loss per
  // stage, wall time per phase, resolved settings such as the grid and sigmas).
  nlohmann::json* stats = nullptr;

  void start(const PointSet& p) const { for (auto* o : observers) o->on_start(p); }
  void stage_begin(const ProgressEvent& e) const { for (auto* o : observers) o->on_stage_begin(e); }
  void iteration(const ProgressEvent& e) const { for (auto* o : observers) o->on_iteration(e); }
  void stage_end(const ProgressEvent& e, const PointSet& p) const { for (auto* o : observers) o->on_stage_end(e, p); }
};

class SynthesisMethod {
 public:
  virtual ~SynthesisMethod() = default;
  // Returns the output pattern in the unit square; every point keeps its class and attributes.
  virtual PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) = 0;
};

// {"type": "gabor" | "roveri2015" | "pcf2017" | ..., params...}
using MethodRegistry = Registry<SynthesisMethod>;

}  // namespace ppsynth
