#pragma once
// The state Algorithm 1 works on: the exemplar samples {(e_j, b_j)} (fixed), the output
// samples {(x_i, a_i)} (optimized), the quadrature points q_k on a regular grid over the output
// domain (Eq. 3.6) with their current matches m_k in the exemplar, and k-d trees for the
// neighborhood queries (core/neighbors.hpp). Every length is in exemplar units.
//
// Matches are restricted to `match_box`, the exemplar's window shrunk by match_margin * delta
// on every side, so a matched window lies (mostly) inside the exemplar: the exemplar is a
// finite sample and its outside would read as "no points".
//
// Masks (an addition: the chapter synthesizes on open domains and does not say how windows
// that cross a domain boundary are treated): a window pair (q_k, m_k) only compares the part
// of the plane that exists on both sides, approximated point-wise like the box window
// does: an output point counts in S_k only if its image in the exemplar is inside the
// exemplar's window, an exemplar point only if its image in the output is inside the output
// domain. Without the second mask, exemplar points that map outside a non-periodic output
// pull output points onto its border.
#include <memory>
#include <vector>

#include "core/neighbors.hpp"
#include "core/point_set.hpp"
#include "optim/baselines/roveri2015/functional.hpp"
#include "optim/baselines/roveri2015/params.hpp"
#include "optim/baselines/roveri2015/similarity.hpp"

namespace ppsynth::roveri2015 {

struct SynthesisState {
  KernelParams kp;
  // Exemplar (never periodic: it is a finite window of a larger pattern).
  FunctionalSet ex;
  Domain ex_domain;
  Domain match_box;
  // Output.
  FunctionalSet out;
  Domain out_domain;
  bool periodic = false;
  // Quadrature points, their matches, the exemplar neighborhood of each match and its
  // exemplar-exemplar term (constant while merging).
  std::vector<Vec2> quad;      // row-major grid, quad_nx x quad_ny
  int quad_nx = 0, quad_ny = 0;
  std::vector<Vec2> match;
  std::vector<Neighborhood> ex_nb;
  std::vector<double> ex_term;

  SynthesisState(FunctionalSet exemplar, const Domain& exemplar_domain, FunctionalSet output,
                 const Domain& output_domain, bool periodic_output);

  // Sets delta (window) and the derived match box; call before matching at a new scale.
  void set_window(const KernelParams& params, double match_margin);
  // Regular grid of quadrature points, spacing <= `spacing`, cell centers of the output domain.
  void set_quadrature(double spacing);
  // Rebuild the output k-d tree after the output points moved, were added or removed.
  void rebuild_output_index();

  // Output points within kp.radius() of q (relative to q; minimum image on a torus), except
  // `skip` (pass npos for none). With `m`: only points whose image m + (x_i - q) lies inside
  // the exemplar's window (mask, see below).
  void gather_output(Vec2 q, Neighborhood& nb, size_t skip = npos, const Vec2* m = nullptr) const;
  // Exemplar points within kp.radius() of m (relative to m). With `q` and a non-periodic
  // output: only points whose image q + (e_j - m) lies inside the output domain.
  void gather_exemplar(Vec2 m, Neighborhood& nb, const Vec2* q = nullptr) const;
  // Output and exemplar neighborhoods of quadrature point k at its current match (masked).
  void gather_pair(size_t k, Neighborhood& out_nb, size_t skip = npos) const { gather_output(quad[k], out_nb, skip, &match[k]); }
  // Grid neighbors of quadrature point k (left, right, below, above; wrapped on a torus).
  std::vector<size_t> quad_neighbors(size_t k) const;
  // Quadrature points whose window can contain a point at p (within kp.radius()).
  std::vector<size_t> quads_near(Vec2 p) const;
  // Wraps p into the output torus, or clamps it into the output rectangle.
  Vec2 confine(Vec2 p) const;
  // Clamps m into match_box.
  Vec2 confine_match(Vec2 m) const;

  static constexpr size_t npos = size_t(-1);

 private:
  std::unique_ptr<NeighborIndex> ex_index_, out_index_, quad_index_;
};

}  // namespace ppsynth::roveri2015
