#include "optim/baselines/pcf2017/pcf2017_stats.hpp"

#include <stdexcept>

namespace ppsynth::pcf2017 {

namespace {

const std::vector<std::string> kDescentKeys = {"iterations", "energy_initial", "energy_final", "converged", "target_r_max"};

void add_to(nlohmann::json& j, const Pcf2017Descent& d) {
  j["iterations"] = d.iterations;
  j["energy_initial"] = d.energy_initial;
  j["energy_final"] = d.energy_final;
  j["converged"] = d.converged;
  j["target_r_max"] = d.target_r_max;
}

Pcf2017Descent descent_from(const StatsFields& f) {
  return {f.integer("iterations"), f.number("energy_initial"), f.number("energy_final"), f.flag("converged"),
          f.number("target_r_max")};
}

// Its keys are all there or none is.
bool has_descent(const StatsFields& f) {
  for (const std::string& k : kDescentKeys)
    if (f.has(k)) return true;
  return false;
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

nlohmann::json to_json(const Pcf2017Stats& s) {
  nlohmann::json j = {{"points", s.points}, {"seconds", s.seconds}};
  if (s.descent) add_to(j, *s.descent);
  if (s.rectangle) {
    ppsynth::add_to(j, *s.rectangle);
    j["classes"] = nlohmann::json::array();
    for (const Pcf2017Class& c : s.classes) {
      nlohmann::json cj = {{"class", c.class_index}, {"torus", c.torus}, {"torus_points", c.torus_points}};
      if (c.descent) add_to(cj, *c.descent);
      j["classes"].push_back(cj);
    }
  }
  return j;
}

Pcf2017Stats pcf2017_stats_from_json(const nlohmann::json& j) {
  const StatsFields f(j, "");
  Pcf2017Stats s;
  s.points = f.count("points");
  s.seconds = f.number("seconds");
  if (f.has("classes") || f.has("output") || f.has("canvas") || f.has("canvas_points")) {
    f.refuse_others(with({"points", "seconds", "classes"}, kRectangleStatsKeys));
    s.rectangle = rectangle_stats_from(f);
    for (const StatsFields& c : f.objects("classes")) {
      c.refuse_others(with({"class", "torus", "torus_points"}, kDescentKeys));
      s.classes.push_back({c.integer("class"), c.box("torus"), c.count("torus_points"),
                           has_descent(c) ? std::optional(descent_from(c)) : std::nullopt});
    }
  } else {
    f.refuse_others(with({"points", "seconds"}, kDescentKeys));
    s.descent = descent_from(f);
  }
  return s;
}

}  // namespace ppsynth::pcf2017
