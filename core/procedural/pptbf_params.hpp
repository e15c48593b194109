#pragma once
// PptbfParams: every parameter of the Point Process Texture Basis Function (Guehl et al.
// 2020, supplement #4, Table 1 and Appendix A), named as in the supplement's pseudo-code.
// Defaults are declared once (pptbf_default_params_json()); from_json() merges a user JSON
// object over them with apply_defaults(), so an unknown key is an InputError naming it, and
// validate() rejects impossible values naming the key.
//
// Units: x, y of pptbf() are image coordinates (the unit square is one rendered image);
// model coordinates m = zoom * R(rotation) * (x / rescalex, y) are in tile units (a base
// cell of tilings 0..9 is 1x1 model unit).
#include <array>
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

struct PptbfParams {
  // seed of every per-cell random number (tiling, jitter, window, feature, noise)
  long long seed = 0;

  // --- deformation and model transform (pseudo-code steps [1], [2]) --------------------
  double zoom = 10.0;        // model units per image unit (about zoom x zoom cells)
  double rotation = 0.0;     // rotation_angle, radians
  double rescalex = 1.0;     // horizontal stretch of the model (x is divided by it)
  std::array<double, 3> ampli{0.0, 1.0, 0.5};  // Brownian distortion: amplitude, frequency, falloff

  // --- point process (Table 1: nu_T, jit) ------------------------------------------------
  int tile_type = 0;         // 0..17, see pptbf_tiling.hpp
  double jitter = 0.5;       // 0 = cell centers, 1 = uniform in (90% of) the cell

  // --- window function (Table 1: omega, ||.||_c, lambda, nv, lc, sigma_j) ------------------
  double normblend = 0.5;    // omega: weight of the cellular window w1 (1-omega for w2)
  int arity = 6;             // nv: control points of the smoothed cell polygon (3..64)
  double larp = 0.0;         // lambda: anisotropy of the cellular distance (0..1)
  double wsmooth = 0.0;      // lc: 0 exact cell, 1 nv-gon, 2 Bezier-rounded nv-gon
  double norm = 2.0;         // ||.||_c Minkowski exponent (>= 1; >= 50 means L-infinity)
  double sigw1 = 1.0;        // sigma of the cellular window w1
  double sigw2 = 2.0;        // sigma of the clamped exponential window w2

  // --- feature function (Table 1: ft, J, correl, phi, tau, kappa, theta, eta, ||.||_f, sigma_f)
  int mixture = 2;           // 0 = constant feature 1; 1..5 = the five mixture models (Fig. 2)
  double winfeatcorrel = 0.0;  // correl: 0 kernels anywhere in the cell, 1 at the point
  double feataniso = 1.0;    // eta: kernel y axis divided by eta (> 0)
  int Jmin = 1, Jmax = 1;    // number of kernels per cell, uniform in [Jmin, Jmax]
  double freq = 0.0;         // phi: frequency of the stringed Gabor stripes
  double thickness = 1.0;    // tau: stripe thickness (ff^(1/tau))
  double curvature = 0.0;    // kappa: curvature of the stripes
  double deltaorient = 0.0;  // theta: kernel orientation uniform in [0, theta]
  double normfeat = 2.0;     // ||.||_f Minkowski exponent of the kernel distance
  double sigcos = 1.0;       // sigma_f: kernel sharpness (larger = smaller kernels)
  double sigcosvar = 0.0;    // sigma_f var: sigma_f * (1 + var * U[0,1])
};

// Every key with its default value (the only place defaults live).
nlohmann::json pptbf_default_params_json();
// Defaults overridden by `user` (a JSON object); unknown keys / wrong types / impossible
// values throw InputError naming `key_path` + the key.
PptbfParams pptbf_params_from_json(const nlohmann::json& user, const std::string& key_path = "");
nlohmann::json to_json(const PptbfParams& p);
// Range checks of Table 1 (e.g. jitter in [0,1], Jmin <= Jmax, mixture in 0..5).
void validate(const PptbfParams& p, const std::string& key_path = "");

}  // namespace ppsynth
