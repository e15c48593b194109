#include "optim/gabor/settings/gabor_options.hpp"

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "models/gabor_feature_maps.hpp"

namespace ppsynth {

namespace {
constexpr const char* k_key = "method";
}  // namespace

nlohmann::json GaborOptions::defaults() {
  return {
      {"c1", 1.0},
      {"c2", 2.6},
      {"num_sigmas", 4},
      {"k", GaborMapsOptions{}.k},  // neighbors: min(M, k)
      // M = the exemplar points of the classes in play at a class stage (the published disk
      // and multi-attribute optimizers); false: M = all exemplar points (its point optimizer).
      {"k_per_stage", true},
      {"jitter", true},
      {"max_iterations", 500},
      {"class_order", nlohmann::json::array()},  // empty = file order
      {"fresh_net_per_class", false},
      // Where the losses measure the output of the paper's u x u square: "grid" (its whole
      // grid, as published: points park on its border), "tiles" (u x u tiles of the
      // exemplar's size cut at a random offset every iteration, each rasterized and measured
      // as the exemplar is) or "rolled" (the whole grid of the torus rolled by a random offset
      // every iteration: the grid's edge never stays where a point could park on it;
      // optim/gabor/stages/random_tiles.hpp).
      {"measure", "grid"},
  };
}

nlohmann::json GaborOptions::bounds() {
  return {{"c1", "(0, inf)"},
          {"c2", "(0, inf)"},
          {"num_sigmas", "int [1, 64]"},
          {"k", "int [1, 1000000]"},
          {"max_iterations", "int [1, 1000000000]"},
          {"class_order", "int [0, 1000000]"}};
}

GaborOptions GaborOptions::resolve(const nlohmann::json& p) {
  GaborOptions o;
  o.c1 = get_number(p, "c1", k_key);
  o.c2 = get_number(p, "c2", k_key);
  o.num_sigmas = get_int(p, "num_sigmas", k_key);
  o.k = get_int(p, "k", k_key);
  if (o.k < 1) throw config_error("method.k", "must be >= 1");
  o.k_per_stage = get_bool(p, "k_per_stage", k_key);
  o.jitter = get_bool(p, "jitter", k_key);
  o.max_iterations = get_int(p, "max_iterations", k_key);
  if (o.max_iterations < 1) throw config_error("method.max_iterations", "must be >= 1");
  for (const auto& c : p["class_order"]) {
    if (!c.is_number_integer() || c.get<int64_t>() < 0 || c.get<int64_t>() > 1000000)
      throw config_error("method.class_order", "expected class ids (whole numbers >= 0)");
    o.class_order.push_back(c.get<int>());
  }
  o.fresh_net_per_class = get_bool(p, "fresh_net_per_class", k_key);
  const nlohmann::json& measure = p["measure"];
  if (!measure.is_string() || (measure != "grid" && measure != "tiles" && measure != "rolled"))
    throw config_error("method.measure", "expected \"grid\", \"tiles\" or \"rolled\", got " + measure.dump());
  o.measure = measure == "tiles" ? Measure::tiles : measure == "rolled" ? Measure::rolled : Measure::grid;
  return o;
}

const char* measure_name(GaborOptions::Measure m) {
  switch (m) {
    case GaborOptions::Measure::tiles: return "tiles";
    case GaborOptions::Measure::rolled: return "rolled";
    default: return "grid";
  }
}

}  // namespace ppsynth
