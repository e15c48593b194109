#pragma once
// Global step of Algorithm 1 (thesis Sec. 3.4.1, "Merging"): with the matches m_k fixed,
// minimize T (energy.hpp) over the output positions x_i, then over the channels a_i (Gauss-
// Seidel: positions first, "prevents points from clustering to compensate for the
// difference in attributes"), by gradient descent.
//
// Positions: x <- x - eta dT/dx for at most `iterations` steps (thesis: 30), stopping when the
// mean move falls below tolerance * sigma (thesis: 1e-6). The thesis's fixed step (0.03) is
// unit-dependent; here eta starts so that the largest move is step * sigma, is multiplied by
// 1.2 after a step that lowered T and halved (step retried, up to 20 times) otherwise, so every
// accepted step lowers T. Points stay in the output domain (clamped; wrapped on a torus).
// Channels: the same backtracking descent for attribute_iterations steps, then the class
// channels are snapped to one-hot (functional.hpp); the update is kept only if T decreased.
// Skipped when there is nothing to optimize (one class, no varying attribute).
#include "optim/baselines/roveri2015/functional.hpp"
#include "optim/baselines/roveri2015/synthesis_state.hpp"

namespace ppsynth::roveri2015 {

struct MergeOptions {
  int iterations = 30;
  double step = 0.1;
  double tolerance = 1e-6;
  int attribute_iterations = 10;
};

struct MergeResult {
  double energy_before = 0;  // output_energy at entry
  double energy = 0;         // output_energy at exit (<= energy_before)
  int iterations = 0;        // accepted position steps
  int class_changes = 0;     // points whose class changed in the attribute step
};

MergeResult merge(SynthesisState& st, const ChannelEncoder& enc, const MergeOptions& opt);

}  // namespace ppsynth::roveri2015
