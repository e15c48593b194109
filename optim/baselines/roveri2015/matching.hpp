#pragma once
// Local step of Algorithm 1 (thesis Sec. 3.4.1, "Matching"): for every quadrature point q_k
// find the exemplar location m_k minimizing S(f(q_k), e(m_k)). Each m_k is independent of
// the others (dT/dm_k = dS_k/dm_k), so they are solved one by one by gradient descent on
// m (similarity.hpp, dS/dm = -sum_j dS/dv_j) from several starts, keeping the best:
//   - `restarts` uniformly random starts in the match box (thesis: five),
//   - the current m_k (so a matching round never increases T; thesis: "each step is
//     guaranteed to decrease the similarity error"),
//   - (`aligned_starts`) the best few point-aligned offsets: the output point nearest q_k put
//     on each exemplar point in turn, ranked by S (an addition: random starts alone rarely
//     land in the right basin, whose area is ~sigma^2),
//   - optionally (`coherent`) the matches of the 4 grid neighbors of q_k shifted by the grid
//     offset (an addition in the spirit of k-coherence search; not in the chapter).
// Descent: normalized gradient steps of length `step` * sigma, doubled (up to the initial
// length) after a success and halved after a failure, `iterations` evaluations per start;
// m stays in the match box (clamped).
#include <cstdint>

#include "optim/baselines/roveri2015/synthesis_state.hpp"

namespace ppsynth::roveri2015 {

struct MatchOptions {
  int restarts = 5;
  int iterations = 20;
  double step = 0.5;  // initial move / sigma
  bool coherent = true;
  int aligned_starts = 2;
};

// S_k(m) for quadrature point k, given its unmasked output neighborhood `out_nb`; masks
// applied at m (synthesis_state.hpp). The output-output term is left out when `with_out_out`
// is false (constant in m as long as the mask does not change). `d_m` (optional) receives
// dS/dm (masks held fixed).
double match_energy(const SynthesisState& st, size_t k, const Neighborhood& out_nb, Vec2 m, Vec2* d_m = nullptr,
                    bool with_out_out = true);

// Finds the best m for quadrature point k (starting points from `rng`); updates st.match[k],
// st.ex_nb[k] and st.ex_term[k]; returns the best S_k.
double match_point(SynthesisState& st, size_t k, const MatchOptions& opt, uint64_t seed);

// match_point for every k (seeded per k from `seed`); returns sum_k of full S_k = T.
double match_all(SynthesisState& st, const MatchOptions& opt, uint64_t seed);

}  // namespace ppsynth::roveri2015
