#pragma once
// GaborStats: what the "gabor" method records of a run (run.json's method_stats, beside the
// run layer's stages), one field per key, filled by the engine (gabor_engine.hpp) and read back
// with gabor_stats_from_json, which refuses a missing or wrong-typed key by its path
// (optim/method/method_stats.hpp).
//
// Torch-free: a reader of run directories needs no LibTorch for it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optim/method/method_stats.hpp"

namespace ppsynth {

// method_stats.runtime: where and how the synthesis computed.
struct GaborRuntime {
  std::string device;         // "cpu", "cuda:0"
  std::string precision;      // the network's arithmetic: "float32", "tf32", "bfloat16"
  bool deterministic = true;  // always on the CPU; runtime.deterministic on CUDA
  // CUDA only (null elsewhere): what the device decided and why, the run layer's record
  // (optim/run/runtime.hpp's decide_device_settings), kept as it wrote it.
  nlohmann::json choices;
  std::optional<std::string> gabor_maps;  // the Gabor maps' path, for the rasterizers that have one
};

// method_stats.windows: the rectangle's windows (optim/gabor/windows/window_plan.hpp).
struct GaborWindows {
  int nx = 1, ny = 1;
  double width = 0, height = 0;  // of a window, exemplar units
  double margin = 0;             // reserved on each side of an interior
  int grid_columns = 0, grid_rows = 0;  // "grid": the output raster's [columns, rows]
};

// A rectangle output's fields.
struct GaborRectangle {
  RectangleStats shape;          // output, canvas, canvas_points
  size_t frozen_pad_points = 0;  // the exemplar's points frozen in the pad ("border": "context")
  GaborWindows windows;
};

// method_stats.phase_seconds: wall time per phase, summed over the run (a resumed run's included).
struct GaborPhaseSeconds {
  double targets = 0, maps_forward = 0, net_forward = 0, loss_forward = 0, backward = 0, optimizer_step = 0;
};

// method_stats.resolved: the pipeline's specs with every default filled in, as its parts
// resolved them (records of config shape, kept as JSON).
struct GaborResolved {
  nlohmann::json rasterizer = nlohmann::json::object();
  nlohmann::json feature_net = nlohmann::json::object();
  nlohmann::json losses = nlohmann::json::array();
};

struct GaborStats {
  int grid_res = 0, output_grid_res = 0, output_grid_rows = 0;  // GaborSettings' res, out_res, out_rows
  std::vector<int> grid_res_per_sigma, output_grid_res_per_sigma, output_grid_rows_per_sigma;
  int k = 0;
  std::vector<double> sigmas;    // coarse -> fine
  double mean_nn_distance = 0;   // d of the exemplar
  std::map<std::string, double> map_terms, terms;  // weight by name (method.map_terms, method.terms)
  GaborRuntime runtime;
  std::optional<GaborRectangle> rectangle;  // rectangle outputs only
  GaborPhaseSeconds phase_seconds;
  GaborResolved resolved;
  // What the plan's stage kinds add of their own (StageKind::describe: border_relax_terms; a
  // kind owns its record), flat beside the fields above; read back as every other key.
  nlohmann::json kinds = nlohmann::json::object();
};

nlohmann::json to_json(const GaborStats& s);
nlohmann::json to_json(const GaborPhaseSeconds& p);
// Back from to_json's form; std::invalid_argument naming the key's path.
GaborStats gabor_stats_from_json(const nlohmann::json& j);

}  // namespace ppsynth
