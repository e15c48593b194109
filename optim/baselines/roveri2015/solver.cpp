#include "optim/baselines/roveri2015/solver.hpp"

#include <chrono>
#include <cmath>
#include <random>

#include "optim/baselines/roveri2015/energy.hpp"
#include "optim/baselines/roveri2015/matching.hpp"
#include "optim/baselines/roveri2015/merging.hpp"
#include "optim/baselines/roveri2015/sampling_control.hpp"

namespace ppsynth::roveri2015 {

std::vector<double> window_schedule(double delta0, double scale_factor, double min_window_ratio) {
  std::vector<double> d{delta0};
  if (!(scale_factor > 0 && scale_factor < 1)) return d;
  for (double x = delta0 * scale_factor; x >= min_window_ratio * delta0 * (1 - 1e-12) && d.size() < 1000;
       x *= scale_factor)
    d.push_back(x);
  return d;
}

std::vector<ScaleReport> solve(SynthesisState& st, const ChannelEncoder& enc, const RoveriParams& p, double sigma,
                               double delta0, uint64_t seed, const SolverCallbacks& cb) {
  const std::vector<double> deltas = window_schedule(delta0, p.scale_factor, p.min_window_ratio);
  st.set_quadrature(p.quad_spacing * sigma);
  MatchOptions mo{p.match_restarts, p.match_iterations, p.match_step, true, p.aligned_starts};
  MergeOptions go{p.merge_iterations, p.merge_step, p.merge_tolerance, p.attribute_iterations};
  SamplingOptions so{p.sampling_epsilon, p.candidate_iterations, p.max_candidate_fraction};
  std::mt19937_64 seeder(seed);
  std::vector<ScaleReport> reports;
  const int rounds = p.local_global_iterations * p.sampling_control_iterations;
  for (size_t s = 0; s < deltas.size(); ++s) {
    const auto t0 = std::chrono::steady_clock::now();
    KernelParams kp;
    kp.sigma = sigma;
    kp.delta = deltas[s];
    kp.window = p.window;
    kp.window_cutoff = p.window_cutoff;
    kp.pair_cutoff = p.pair_cutoff;
    st.set_window(kp, p.match_margin);
    if (cb.scale_begin) cb.scale_begin(int(s), int(deltas.size()), kp.delta);
    ScaleReport r;
    r.delta = kp.delta;
    int round = 0;
    for (int sc = 0; sc < p.sampling_control_iterations; ++sc) {
      for (int lg = 0; lg < p.local_global_iterations; ++lg) {
        const double Tm = match_all(st, mo, seeder());
        if (round == 0) r.energy_start = Tm;
        const MergeResult mr = merge(st, enc, go);
        r.merge_iterations += mr.iterations;
        double B = 0;
        for (double b : st.ex_term) B += b;
        r.energy_end = mr.energy + B;
        ++round;
        if (cb.iteration) cb.iteration(int(s), round, rounds, r.energy_end);
      }
      const SamplingResult sr = sampling_control(st, so, seeder());
      r.added += sr.added;
      r.removed += sr.removed;
    }
    if (p.sampling_control_iterations > 0 && p.local_global_iterations > 0) r.energy_end = total_energy(st);
    r.points = st.out.size();
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    reports.push_back(r);
    if (cb.scale_end) cb.scale_end(int(s), st, r);
  }
  return reports;
}

}  // namespace ppsynth::roveri2015
