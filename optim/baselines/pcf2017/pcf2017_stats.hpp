#pragma once
// Pcf2017Stats: what the "pcf2017" method records of a run (run.json's method_stats), one
// field per key, read back with pcf2017_stats_from_json, which refuses a missing,
// wrong-typed or unknown key by its path (optim/method/method_stats.hpp).
#include <array>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "optim/method/method_stats.hpp"

namespace ppsynth::pcf2017 {

// One gradient descent on Eq. 4.3 (pcf_synthesizer.hpp): the unit torus's, or a rectangle class's.
struct Pcf2017Descent {
  int iterations = 0;          // accepted steps
  double energy_initial = 0, energy_final = 0;
  bool converged = false;      // stopped because no step decreased E
  double target_r_max = 0;     // of the exemplar's (class's) PCF
};

// A rectangle's class, synthesized on its own torus.
struct Pcf2017Class {
  int class_index = 0;                  // "class"
  std::array<double, 4> torus{};        // {x0, y0, x1, y1}: the canvas, or grown past its far edges
  size_t torus_points = 0;
  std::optional<Pcf2017Descent> descent;  // none: too few points for a PCF (they stay uniform)
};

struct Pcf2017Stats {
  size_t points = 0;   // of the output
  double seconds = 0;  // of the synthesis
  std::optional<Pcf2017Descent> descent;    // the paper's path: the unit torus
  std::optional<RectangleStats> rectangle;  // a rectangle output, with its classes:
  std::vector<Pcf2017Class> classes;
};

nlohmann::json to_json(const Pcf2017Stats& s);
// Back from to_json's form; std::invalid_argument naming the key's path.
Pcf2017Stats pcf2017_stats_from_json(const nlohmann::json& j);

}  // namespace ppsynth::pcf2017
