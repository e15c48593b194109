#pragma once
// Roveri2015Stats: what the "roveri2015" method records of a run (run.json's method_stats),
// one field per key, read back with roveri2015_stats_from_json, which refuses a missing,
// wrong-typed or unknown key by its path (optim/method/method_stats.hpp).
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "optim/baselines/roveri2015/solver.hpp"
#include "optim/method/method_stats.hpp"

namespace ppsynth::roveri2015 {

struct Roveri2015Stats {
  double d_nn = 0;    // the exemplar's mean nearest-neighbor distance
  double sigma = 0;   // sigma_factor d_nn
  double delta0 = 0;  // window_factor d_nn
  size_t quadrature_points = 0, initial_points = 0;
  size_t points = 0;  // of the output (after a rectangle's crop)
  // The paper's path: u^2 M, a count (written as one); a rectangle: the density's expectation.
  double target_points = 0;
  std::optional<RectangleStats> rectangle;  // a rectangle output's
  std::vector<ScaleReport> scales;          // one per scale, in order (solver.hpp)
  double seconds = 0;                       // of the synthesis
};

nlohmann::json to_json(const Roveri2015Stats& s);
// Back from to_json's form; std::invalid_argument naming the key's path.
Roveri2015Stats roveri2015_stats_from_json(const nlohmann::json& j);

}  // namespace ppsynth::roveri2015
