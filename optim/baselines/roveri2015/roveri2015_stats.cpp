#include "optim/baselines/roveri2015/roveri2015_stats.hpp"

#include <cmath>
#include <string>

namespace ppsynth::roveri2015 {

nlohmann::json to_json(const Roveri2015Stats& s) {
  nlohmann::json j = {{"d_nn", s.d_nn},
                      {"sigma", s.sigma},
                      {"delta0", s.delta0},
                      {"quadrature_points", s.quadrature_points},
                      {"initial_points", s.initial_points},
                      {"points", s.points},
                      {"scales", nlohmann::json::array()},
                      {"seconds", s.seconds}};
  if (s.rectangle) {
    j["target_points"] = s.target_points;
    add_to(j, *s.rectangle);
  } else {
    j["target_points"] = static_cast<size_t>(std::llround(s.target_points));
  }
  for (const ScaleReport& r : s.scales)
    j["scales"].push_back({{"delta", r.delta},
                           {"energy_start", r.energy_start},
                           {"energy_end", r.energy_end},
                           {"points", r.points},
                           {"added", r.added},
                           {"removed", r.removed},
                           {"merge_iterations", r.merge_iterations},
                           {"seconds", r.seconds}});
  return j;
}

Roveri2015Stats roveri2015_stats_from_json(const nlohmann::json& j) {
  const StatsFields f(j, "");
  std::vector<std::string> known = {"d_nn", "sigma", "delta0", "quadrature_points", "initial_points",
                                    "points", "target_points", "scales", "seconds"};
  const bool rect = f.has("output") || f.has("canvas") || f.has("canvas_points");
  if (rect) known.insert(known.end(), kRectangleStatsKeys.begin(), kRectangleStatsKeys.end());
  f.refuse_others(known);
  Roveri2015Stats s;
  s.d_nn = f.number("d_nn");
  s.sigma = f.number("sigma");
  s.delta0 = f.number("delta0");
  s.quadrature_points = f.count("quadrature_points");
  s.initial_points = f.count("initial_points");
  s.points = f.count("points");
  s.target_points = rect ? f.number("target_points") : static_cast<double>(f.count("target_points"));
  if (rect) s.rectangle = rectangle_stats_from(f);
  for (const StatsFields& r : f.objects("scales")) {
    r.refuse_others({"delta", "energy_start", "energy_end", "points", "added", "removed", "merge_iterations", "seconds"});
    s.scales.push_back({r.number("delta"), r.number("energy_start"), r.number("energy_end"), r.count("points"),
                        r.integer("added"), r.integer("removed"), r.integer("merge_iterations"), r.number("seconds")});
  }
  s.seconds = f.number("seconds");
  return s;
}

}  // namespace ppsynth::roveri2015
