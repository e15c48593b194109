#pragma once
// Sampling control of thesis Sec. 3.4.1 (Eq. 3.7): after the local-global iterations, each
// quadrature point compares the number of output points in its window with the number of
// exemplar points in its matched window, P_s(q_k, m_k) (similarity.hpp, sampling_error),
// and proposes to fix the difference by one point:
//   P_s < -epsilon (output too sparse): ADD a point. Proposal: the exemplar point e_j of the
//     matched window whose image q_k + (e_j - m_k) has the largest density deficit
//     e(e_j) - f(q_k + e_j - m_k) (densities with a = 1), jittered by 0.05 sigma, with e_j's
//     channels. (The thesis adds "a new random point in vicinity of the quadrature point";
//     this proposal is a point in that vicinity chosen where the exemplar says one is missing.)
//     The new point's position is then optimized alone (candidate_iterations normalized
//     gradient steps on the energy change).
//   P_s > +epsilon (too dense): REMOVE the output point of the window with the largest
//     density surplus f(x_i) - e(m_k + x_i - q_k).
// Either change is kept only if it lowers T (thesis: "decide to keep the optimized point or
// not by checking whether the energy increases or decreases"); the change of T is exact and
// local: only the quadrature points whose window can contain the point are re-evaluated
// (energy.hpp, local_energy), matches held fixed.
// Quadrature points are visited by decreasing |P_s| (computed once per round), at most
// max_fraction of them per round; a point's P_s is re-evaluated just before its proposal.
//
// Note: the thesis's text states the sign rule both ways ("If P < 0 ... implying removal of
// points" and then "add a new point ... if P < -epsilon"); the second one follows from
// P = Int (f - e) w and is the one implemented.
#include <cstdint>

#include "optim/baselines/roveri2015/synthesis_state.hpp"

namespace ppsynth::roveri2015 {

struct SamplingOptions {
  double epsilon = 1e-6;
  int candidate_iterations = 5;
  double max_fraction = 0.5;
};

struct SamplingResult {
  int tried_add = 0, added = 0;
  int tried_remove = 0, removed = 0;
};

// Tries to add one point near quadrature point k; returns true when it was kept.
bool try_add_point(SynthesisState& st, size_t k, const SamplingOptions& opt, uint64_t seed);
// Tries to remove one point near quadrature point k; returns true when it was removed.
bool try_remove_point(SynthesisState& st, size_t k, const SamplingOptions& opt);

SamplingResult sampling_control(SynthesisState& st, const SamplingOptions& opt, uint64_t seed);

}  // namespace ppsynth::roveri2015
