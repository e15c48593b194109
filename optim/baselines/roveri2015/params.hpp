#pragma once
// Parameters of Roveri et al. 2015 (thesis Chapter 3, "Example Based Repetitive Structure
// Synthesis"), all lengths given relative to the exemplar so one set of defaults fits every
// exemplar. The members' initializers are the defaults; the method's config keys are declared
// once, in roveri2015_options.cpp's table.
//
// Units: every length below is in units of d_nn, the exemplar's mean nearest-neighbor
// distance (plane, exemplar units). Section 3.6.1: "sigma is set to the average spacing
// between the points e_i", so sigma_factor = 1 is the thesis's choice; the window size delta
// "is provided by the user based on the expected scale of repetitions".
#include <cstdint>

namespace ppsynth::roveri2015 {

// Window function w of Eq. 3.2. Box: the thesis's practical choice (Eq. 3.5, radius delta,
// only points closer than delta count). Gaussian: w(s) = exp(-|s|^2 / delta^2), Eq. A.6
// (smooth in every variable; truncated at window_cutoff * delta).
enum class WindowKind { Box, Gaussian };

struct KernelParams {
  double sigma = 1;         // Gaussian g(x, sigma) = exp(-|x|^2 / sigma^2) of Eq. 3.4 [length]
  double delta = 2;         // window size [length]
  WindowKind window = WindowKind::Gaussian;
  double window_cutoff = 2.5;  // Gaussian window: points farther than cutoff*delta are ignored
  double pair_cutoff = 4.5;    // pairs farther apart than pair_cutoff*sigma are skipped
                               // (their term is exp(-pair_cutoff^2 / 2) < 4e-5 of a coincident pair)
  // Radius of the point neighborhood around a quadrature / matching point.
  double radius() const { return window == WindowKind::Box ? delta : window_cutoff * delta; }
};

struct RoveriParams {
  // --- representation (Eq. 3.4) and window ---------------------------------------------
  double sigma_factor = 1.0;       // sigma / d_nn
  double window_factor = 2.0;      // initial delta / d_nn
  WindowKind window = WindowKind::Gaussian;
  double window_cutoff = 2.5;
  double pair_cutoff = 4.5;
  double attribute_weight = 0.5;   // weight of a standardized attribute channel (class channels: 1)
  // --- quadrature (Eq. 3.6) -----------------------------------------------------------
  double quad_spacing = 1.0;       // grid spacing of the quadrature points q_k / sigma
  // --- matching (local step) ----------------------------------------------------------
  int match_restarts = 5;          // random starts per q_k (thesis: five), plus the previous m_k
  int aligned_starts = 2;          // best point-aligned offsets added as starts (not in the thesis; matching.hpp)
  int match_iterations = 20;       // normalized gradient-descent steps per start
  double match_step = 0.5;         // initial matching move / sigma (halved on failure)
  double match_margin = 1.0;       // m_k kept >= margin*delta inside the exemplar's window
  // --- merging (global step) ----------------------------------------------------------
  int merge_iterations = 30;       // thesis: 30 gradient-descent iterations at most
  double merge_step = 0.1;         // initial largest point move / sigma (adapted by backtracking)
  double merge_tolerance = 1e-6;   // stop when the mean move / sigma falls below this (thesis 1e-6)
  int attribute_iterations = 10;   // gradient steps on the attributes (Gauss-Seidel after positions)
  // --- Algorithm 1 loops --------------------------------------------------------------
  int local_global_iterations = 3;     // matching + merging rounds per sampling-control round
  int sampling_control_iterations = 2; // sampling-control rounds per scale
  double scale_factor = 0.9;           // delta <- a * delta (thesis a = 0.9)
  double min_window_ratio = 0.5;       // stop once delta < ratio * initial delta (thesis: half)
  // --- sampling control (Eq. 3.7) -----------------------------------------------------
  double sampling_epsilon = 1e-6;      // |P| threshold (thesis 1e-6)
  int candidate_iterations = 5;        // gradient steps on a newly added point
  double max_candidate_fraction = 0.5; // at most this fraction of quadrature points tried per round
  // --- initialization ------------------------------------------------------------------
  double patch_size = 0.5;         // random-patch-copy square side / min(exemplar W, H)
  bool periodic_output = false;    // synthesize on a torus (default: plain rectangle)
};

}  // namespace ppsynth::roveri2015
