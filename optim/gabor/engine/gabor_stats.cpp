#include "optim/gabor/engine/gabor_stats.hpp"

#include <stdexcept>

namespace ppsynth {

namespace {

// Every key of the stats but the stage kinds'.
const std::vector<std::string> kKeys = {"grid_res", "output_grid_res", "output_grid_rows", "grid_res_per_sigma",
                                        "output_grid_res_per_sigma", "output_grid_rows_per_sigma", "k", "sigmas",
                                        "mean_nn_distance", "map_terms", "terms", "runtime", "phase_seconds",
                                        "resolved", "output", "canvas", "canvas_points", "frozen_pad_points", "windows"};

nlohmann::json to_json(const GaborRuntime& r) {
  nlohmann::json j = {{"device", r.device}, {"precision", r.precision}, {"deterministic", r.deterministic}};
  if (!r.choices.is_null()) j["choices"] = r.choices;
  if (r.gabor_maps) j["gabor_maps"] = *r.gabor_maps;
  return j;
}

GaborRuntime runtime_from(const StatsFields& f) {
  f.refuse_others({"device", "precision", "deterministic", "choices", "gabor_maps"});
  GaborRuntime r{f.text("device"), f.text("precision"), f.flag("deterministic"), nullptr, std::nullopt};
  if (f.has("choices")) {
    f.object("choices");  // refuses anything but an object
    r.choices = f.value("choices");
  }
  if (f.has("gabor_maps")) r.gabor_maps = f.text("gabor_maps");
  return r;
}

nlohmann::json to_json(const GaborWindows& w) {
  return {{"nx", w.nx}, {"ny", w.ny}, {"width", w.width}, {"height", w.height}, {"margin", w.margin},
          {"grid", {w.grid_columns, w.grid_rows}}};
}

GaborWindows windows_from(const StatsFields& f) {
  f.refuse_others({"nx", "ny", "width", "height", "margin", "grid"});
  const std::vector<int> grid = f.integers("grid");
  if (grid.size() != 2) throw std::invalid_argument("'windows.grid' is not [columns, rows]");
  return {f.integer("nx"), f.integer("ny"), f.number("width"), f.number("height"), f.number("margin"), grid[0], grid[1]};
}

GaborPhaseSeconds phases_from(const StatsFields& f) {
  f.refuse_others({"targets", "maps_forward", "net_forward", "loss_forward", "backward", "optimizer_step"});
  return {f.number("targets"), f.number("maps_forward"), f.number("net_forward"),
          f.number("loss_forward"), f.number("backward"), f.number("optimizer_step")};
}

GaborResolved resolved_from(const StatsFields& f) {
  f.refuse_others({"rasterizer", "feature_net", "losses"});
  f.object("rasterizer");
  f.object("feature_net");
  f.objects("losses");
  return {f.value("rasterizer"), f.value("feature_net"), f.value("losses")};
}

}  // namespace

nlohmann::json to_json(const GaborPhaseSeconds& p) {
  return {{"targets", p.targets}, {"maps_forward", p.maps_forward}, {"net_forward", p.net_forward},
          {"loss_forward", p.loss_forward}, {"backward", p.backward}, {"optimizer_step", p.optimizer_step}};
}

nlohmann::json to_json(const GaborStats& s) {
  nlohmann::json j = s.kinds.is_object() ? s.kinds : nlohmann::json::object();
  j["grid_res"] = s.grid_res;
  j["output_grid_res"] = s.output_grid_res;
  j["output_grid_rows"] = s.output_grid_rows;
  j["grid_res_per_sigma"] = s.grid_res_per_sigma;
  j["output_grid_res_per_sigma"] = s.output_grid_res_per_sigma;
  j["output_grid_rows_per_sigma"] = s.output_grid_rows_per_sigma;
  j["k"] = s.k;
  j["sigmas"] = s.sigmas;
  j["mean_nn_distance"] = s.mean_nn_distance;
  j["map_terms"] = nlohmann::json::object();
  for (const auto& [name, w] : s.map_terms) j["map_terms"][name] = w;
  j["terms"] = nlohmann::json::object();
  for (const auto& [name, w] : s.terms) j["terms"][name] = w;
  j["runtime"] = to_json(s.runtime);
  if (s.rectangle) {
    add_to(j, s.rectangle->shape);
    j["frozen_pad_points"] = s.rectangle->frozen_pad_points;
    j["windows"] = to_json(s.rectangle->windows);
  }
  j["phase_seconds"] = to_json(s.phase_seconds);
  j["resolved"] = {{"rasterizer", s.resolved.rasterizer}, {"feature_net", s.resolved.feature_net}, {"losses", s.resolved.losses}};
  return j;
}

GaborStats gabor_stats_from_json(const nlohmann::json& j) {
  const StatsFields f(j, "");
  GaborStats s;
  s.grid_res = f.integer("grid_res");
  s.output_grid_res = f.integer("output_grid_res");
  s.output_grid_rows = f.integer("output_grid_rows");
  s.grid_res_per_sigma = f.integers("grid_res_per_sigma");
  s.output_grid_res_per_sigma = f.integers("output_grid_res_per_sigma");
  s.output_grid_rows_per_sigma = f.integers("output_grid_rows_per_sigma");
  s.k = f.integer("k");
  s.sigmas = f.numbers("sigmas");
  s.mean_nn_distance = f.number("mean_nn_distance");
  s.map_terms = f.weights("map_terms");
  s.terms = f.weights("terms");
  s.runtime = runtime_from(f.object("runtime"));
  // A rectangle's keys come together: any of them asks for all.
  if (f.has("output") || f.has("canvas") || f.has("canvas_points") || f.has("frozen_pad_points") || f.has("windows"))
    s.rectangle = GaborRectangle{rectangle_stats_from(f), f.count("frozen_pad_points"), windows_from(f.object("windows"))};
  s.phase_seconds = phases_from(f.object("phase_seconds"));
  s.resolved = resolved_from(f.object("resolved"));
  for (const std::string& key : f.others(kKeys)) s.kinds[key] = j[key];
  return s;
}

}  // namespace ppsynth
