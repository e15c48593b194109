#pragma once
// Initializer: where the output points of one class start. "best_candidate" (toroidal
// best-candidate Poisson disk in the domain inset by `margin`: the paper's; margin 0.01), "uniform"
// (supplement: random initialization works too), "file" (a given point file, e.g. the
// published code's own initialization in shared/data/reference, to reproduce its runs).
#include <cstdint>
#include <functional>
#include <string>

#include "core/point_set.hpp"
#include "core/registry.hpp"

namespace ppsynth {

class Initializer {
 public:
  virtual ~Initializer() = default;
  // n positions for class `cls` (0-based, in the exemplar's class numbering) on `domain`
  // (the paper's unit square, or a canvas in exemplar units; margins are fractions of it).
  virtual PointSet initialize(size_t n, int cls, uint64_t seed, const Domain& domain) const = 0;
  // Called often while it works (a run's stop check, SynthesisContext::poll; it may throw to
  // stop): a start of hundreds of thousands of points takes a while.
  void set_poll(std::function<void()> poll) { poll_ = std::move(poll); }

 protected:
  std::function<void()> poll_;
};

using InitializerRegistry = Registry<Initializer>;

// A synthesis's word before it initializes `points` positions on `canvas` (a large canvas
// takes a while, and the log says what the config asked for; check_synthesis_size,
// optim/run/synthesize.hpp, has refused a count beyond the memory before).
void log_initialization(size_t points, const Domain& canvas);

}  // namespace ppsynth
