#pragma once
// Algorithm 1 of thesis Chapter 3, the multi-scale local-global solver:
//
//   delta <- delta_0
//   repeat (scales)                              until delta < min_window_ratio * delta_0
//     repeat sampling_control_iterations times
//       repeat local_global_iterations times
//         matching:  m_k <- argmin_m S(f(q_k), e(m))      (matching.hpp)
//         merging:   x_i, a_i <- argmin T                  (merging.hpp)
//       sampling control: add/remove points by P_s         (sampling_control.hpp)
//     delta <- scale_factor * delta                         (thesis: 0.9; stops at half)
//
// With the thesis's a = 0.9 and stop at half this is 7 scales (delta_0 ... 0.53 delta_0).
// Quadrature points: a regular grid of spacing quad_spacing * sigma over the output (fixed).
// Deterministic from `seed`.
#include <cstdint>
#include <functional>
#include <vector>

#include "optim/baselines/roveri2015/functional.hpp"
#include "optim/baselines/roveri2015/params.hpp"
#include "optim/baselines/roveri2015/synthesis_state.hpp"

namespace ppsynth::roveri2015 {

struct ScaleReport {
  double delta = 0;
  double energy_start = 0;  // T after the first matching of the scale
  double energy_end = 0;    // T after the last merging of the scale
  size_t points = 0;        // output points at the end of the scale
  int added = 0, removed = 0;
  int merge_iterations = 0;
  double seconds = 0;
};

struct SolverCallbacks {
  std::function<void(int scale, int scales, double delta)> scale_begin;
  // After every merging: `iteration` counts local-global rounds within the scale.
  std::function<void(int scale, int iteration, int iterations, double T)> iteration;
  std::function<void(int scale, const SynthesisState& st, const ScaleReport& r)> scale_end;
};

// The window sizes of the schedule: delta_0 a^s while >= ratio * delta_0 (at least one).
std::vector<double> window_schedule(double delta0, double scale_factor, double min_window_ratio);

// Runs Algorithm 1 on `st` (output already initialized). sigma and delta_0 in exemplar units.
std::vector<ScaleReport> solve(SynthesisState& st, const ChannelEncoder& enc, const RoveriParams& p, double sigma,
                               double delta0, uint64_t seed, const SolverCallbacks& cb = {});

}  // namespace ppsynth::roveri2015
