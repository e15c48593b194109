#pragma once
// Total similarity error of thesis Eq. 3.6: T = sum_k S(f(q_k), e(m_k)), one similarity
// density (similarity.hpp) per quadrature point q_k against its match m_k, and its
// gradients dT/dx_i = sum_k dS_k/dx_i, dT/da_i = sum_k dS_k/da_i (Appendix A.1.2; each S_k only
// involves the x_i inside q_k's window, so only those receive a contribution).
//
// The exemplar-exemplar part of every S_k does not depend on the output; it is computed once
// per matching (SynthesisState::ex_term) and added back by total_energy.
#include <cstddef>
#include <vector>

#include "optim/baselines/roveri2015/synthesis_state.hpp"

namespace ppsynth::roveri2015 {

// sum_k [S_k minus its exemplar-exemplar term], with optional gradients (resized to the output).
double output_energy(const SynthesisState& st, std::vector<Vec2>* grad_x = nullptr,
                     std::vector<double>* grad_a = nullptr);
// T of Eq. 3.6 (output_energy + sum_k ex_term[k]).
double total_energy(const SynthesisState& st);

// A point that is not (yet) in the output: position and channel vector.
struct ExtraPoint {
  Vec2 x;
  const double* a;
};
// Part of output_energy restricted to the quadrature points `quads`, evaluated as if output
// point `skip` were absent (npos: none) and `extra` present (null: none). `d_extra` (optional)
// receives the gradient with respect to extra->x. For sampling control: the energy change of
// adding/removing one point only involves the quadrature points whose window contains it.
double local_energy(const SynthesisState& st, const std::vector<size_t>& quads, size_t skip = SynthesisState::npos,
                    const ExtraPoint* extra = nullptr, Vec2* d_extra = nullptr);

}  // namespace ppsynth::roveri2015
