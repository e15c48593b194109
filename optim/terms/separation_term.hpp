#pragma once
// SeparationTerm: not in the paper (method.terms.separation, off by default; a point term,
// optim/terms/point_term.hpp; method.border_relax.separation switches it on in the relax stages
// only, optim/gabor/stages/border_relax/border_relax_stage.cpp). A soft minimum-distance
// penalty on the moving output points. The Gabor losses see two points closer than a grid
// cell as one blurred point, so outputs keep pairs closer than the exemplar ever has them:
// the small-r mass of their PCF and, for disks, the overlaps the paper names as the method's
// weakness (Fig. 15). This term asks for the exemplar's own spacing:
//
//   penalty = sum over pairs (moving-moving, moving-frozen) of relu(1 - d_ij / t_ij)^2
//   t_ij    = max(fraction * dmin_ex(c_i, c_j) / u,  r_i + r_j)    (r: output radii; disks only)
//
// d_ij on the unit torus (the positions are wrapped toroidally); dmin_ex(a, b) is the closest
// pair of exemplar points of classes a and b (no term where a class pair has no pair).
// In a window of a rectangle output (window_side s > 0) the same in the window's grid
// coordinates: d_ij in the plane, t_ij = max(fraction x dmin_ex / s, (r_i + r_j) / s).
// The synthesizer weights it by method.terms.separation.weight times the stage's first loss,
// so one weight serves every scene and sigma. Pairs are dense (n x n and n x m per
// evaluation): cheap beside the filter network at the paper's sizes (up to ~1,100 output
// points); a neighbor search would be the step for much larger outputs.
#include <torch/torch.h>

#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

class SeparationTerm {
 public:
  // Thresholds for one class stage: `moving` and `frozen` index `output` (radii, if any, are
  // the output's, i.e. already divided by u on the torus), kept on `device`, where the
  // positions will be. window_side: 0 on the unit torus, else the window grid's side
  // (point_term.hpp's ClassStage).
  SeparationTerm(const PointSet& exemplar, const PointSet& output, const std::vector<size_t>& moving,
                 const std::vector<size_t>& frozen, int upscale, double fraction, torch::Device device = torch::kCPU,
                 double window_side = 0);
  // moving: n x 2 wrapped (or window-local) positions (may require grad); frozen: m x 2 (m may be 0).
  torch::Tensor operator()(const torch::Tensor& moving, const torch::Tensor& frozen) const;

 private:
  torch::Tensor t_moving_;  // n x n, strictly upper triangle (each pair once); 0 = no term
  torch::Tensor t_frozen_;  // n x m
  bool periodic_ = true;    // torus distances; false: a window's plane
};

// Closest distance between two distinct exemplar points of classes a and b, per class pair
// (K x K, symmetric, in the square); 0 where the pair of classes has no two points.
std::vector<std::vector<double>> class_pair_min_distance(const PointSet& ps);

}  // namespace ppsynth
