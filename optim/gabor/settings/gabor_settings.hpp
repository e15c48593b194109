#pragma once
// GaborSettings: one run of the Gabor method, the type alone: the method's keys as read
// (GaborOptions), held rather than copied, and what they resolve to for one exemplar and
// output (grid, k, sigmas, attributes, windows, ...). resolve_gabor_settings
// (optim/gabor/resolution/gabor_resolution.hpp) fills it from the method's params; the
// pipeline, the stages, the windows and the engine read it.
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "optim/gabor/settings/gabor_options.hpp"
#include "optim/gabor/settings/window_size.hpp"

namespace ppsynth {

// Resolved from the method's params by resolve_gabor_settings: the defaults are gabor_defaults()'s
// and the run config's, declared once there; the zeros below are not values a run can get.
struct GaborSettings {
  // The method's own keys as read (its parts' specs among them): what needs no resolving is
  // read from here (options.jitter, options.measure, options.rasterizer, ...); the fields below
  // are what depends on the exemplar, the output or --quick.
  GaborOptions options;
  double mean_nn_distance = 0;  // d of the exemplar (all classes)
  int res = 0;                  // exemplar grid (positions per exemplar unit)
  // What the exemplar's raster covers, in exemplar coordinates: the unit square (the paper's
  // outputs), or the exemplar's whole domain (rectangle outputs, in exemplar units: a
  // 1.6 x 1 exemplar's grid is res x 1.6 columns by res rows, as the output's keeps its aspect).
  Domain exemplar_grid{};
  int upscale = 0;              // the paper's u (1 for rectangle outputs: exemplar units)
  // The output raster: `out_res` columns and `out_rows` rows at one spacing over a grid
  // `out_scale` exemplar units wide. The paper's: the unit square, u * res across u.
  // Rectangles: the canvas, or one of its windows past the budget (`window`,
  // optim/gabor/windows/window_plan.hpp), rows x columns in the exemplar's aspect.
  int out_res = 0, out_rows = 0;
  double out_scale = 0;
  WindowSize window;            // rectangles: the windows' size and count (one: the canvas)
  double window_margin = 0;     // rectangles: exemplar units reserved on each side of a window's interior
  bool statistics_in_output = false;  // rectangles: the losses measure the grid's part inside the output only
  // method.measure (options.measure; the paper's u x u torus only for all but "grid"): "grid"
  // measures the whole grid as published; "tiles" cuts the output at a random offset into u x u
  // exemplar-sized tiles, each on the exemplar's grid; "rolled" measures the whole grid of
  // the torus rolled by a random offset (optim/gabor/stages/random_tiles.hpp). Both offsets change with
  // every iteration.
  bool measure_tiles() const { return options.measure == GaborOptions::Measure::tiles; }
  // What the stage kinds see of the run besides the numbers above: a rectangle output, --quick.
  bool rectangle = false, quick = false;
  // Each class-end stage kind's block (method.<name>, its defaults merged and its ranges checked
  // as its StageKindRegistry entry declares them), by the kind's name: the kind reads it
  // (optim/gabor/stages/stage_kind.hpp); the settings do not.
  nlohmann::json stage_kinds = nlohmann::json::object();
  // The grid of each sigma stage (coarse -> fine): `res` and `out_res` at every stage, or with
  // method.grid.per_sigma coarser grids at the coarser sigmas, keeping the finest stage's
  // grid positions per sigma (the Gabor frequencies scale with 1/sigma, so each stage's
  // maps are sampled as finely as the finest stage's).
  std::vector<int> sigma_res, sigma_out_res, sigma_out_rows;
  int k = 0;                    // neighbors per grid position: min(M, k) (options.k_per_stage: M of the stage's classes)
  std::vector<double> sigmas;   // coarse -> fine
  std::vector<int> attr_cols;   // attribute columns weighting the maps
  std::vector<int> class_order;
  int max_iterations = 0;        // options.max_iterations, after --quick's cap
  nlohmann::json feature_net;             // the net spec after --quick shrinking
};

}  // namespace ppsynth
