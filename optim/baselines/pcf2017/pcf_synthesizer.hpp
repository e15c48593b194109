#pragma once
// The synthesis algorithm of thesis Sec. 4.3.1: gradient descent on the PCF energy (Eq. 4.3,
// pcf_energy.hpp) with a line search at every iteration, on a torus.
//
//   x <- wrap(x - delta * D / max_i ||D_i||),   D_i = sum_k dE_k/dx_i
//
// delta (largest displacement, in units of the output's r_max) is the line-search variable:
// halved until E decreases (at most `line_search_halvings` times; none decreases = converged),
// grown by `grow` after an accepted step, capped at `max_step`.
//
// Two front ends:
//   - synthesize_stationary: one whole-torus neighborhood, one target PCF (e.g. an exemplar's
//     pattern_pcf), density n / A;
//   - synthesize_adaptive: a density map and per-position weights of dictionary PCFs (basis
//     g_l). Neighborhoods are disks on a regular grid of spacing T = min_k R_k / 2 with
//     R_k = sqrt(m / (pi lambda_k)) (m = expected points per neighborhood; the chapter's
//     |N_k| = alpha n / lambda_k), target t_k = sum_l w_l(c_k) g_l, lambda scaled so that it
//     integrates to n. Initialization: density-proportional rejection sampling.
#include <functional>
#include <cstdint>
#include <vector>

#include "core/point_set.hpp"
#include "optim/baselines/pcf2017/pcf_energy.hpp"
#include "optim/baselines/pcf2017/pcf_params.hpp"

namespace ppsynth::pcf2017 {

struct DescentOptions {
  int iterations = 300;
  double step = 0.1;            // initial delta, units of r_max
  double max_step = 0.5;        // cap of delta, units of r_max
  double grow = 1.2;
  int line_search_halvings = 12;
};

// Called after every accepted iteration: (iteration, energy).
using DescentCallback = std::function<void(int, double)>;

struct DescentResult {
  std::vector<Vec2> points;
  std::vector<double> energy;  // E before the first step, then after every accepted step
  bool converged = false;      // stopped because no step decreased E
};

// Gradient descent with line search on `energy`, starting from `x` (wrapped into the torus).
// `rmax` converts the step options to domain units.
DescentResult descend(const PcfEnergy& energy, std::vector<Vec2> x, double rmax,
                      const DescentOptions& opt = {}, const DescentCallback& cb = {});

// n uniform points on `domain` (seeded).
std::vector<Vec2> uniform_points(size_t n, const Domain& domain, uint64_t seed);

// Stationary synthesis: `init` (n points on the torus `domain`) descends to match `target`
// (samples at relative_radii(params)).
DescentResult synthesize_stationary(const std::vector<double>& target, std::vector<Vec2> init,
                                    const Domain& domain, const PcfParams& params = {},
                                    const DescentOptions& opt = {}, const DescentCallback& cb = {});

// A scalar field over the domain (density, weight).
using ScalarMap = std::function<double(Vec2)>;

struct AdaptiveTarget {
  ScalarMap density;                        // relative intensity (any positive scale)
  std::vector<ScalarMap> weights;           // w_l(x), one per basis PCF (normalized to sum 1)
  std::vector<std::vector<double>> basis;   // g_l at relative_radii(params)
  double neighborhood_points = 40;         // m
};

// The neighborhoods of an adaptive target for n points on `domain` (see above).
std::vector<Neighborhood> adaptive_neighborhoods(const AdaptiveTarget& t, size_t n, const Domain& domain);

// n points drawn with probability proportional to t.density (seeded rejection sampling).
std::vector<Vec2> density_points(const ScalarMap& density, size_t n, const Domain& domain, uint64_t seed);

DescentResult synthesize_adaptive(const AdaptiveTarget& target, size_t n, const Domain& domain,
                                  uint64_t seed, const PcfParams& params = {},
                                  const DescentOptions& opt = {}, const DescentCallback& cb = {});

}  // namespace ppsynth::pcf2017
