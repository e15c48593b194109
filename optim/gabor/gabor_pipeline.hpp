#pragma once
// GaborPipeline: the parts of the Gabor method for one evaluation, shared by the
// synthesizer (optim/gabor/gabor_synthesizer.hpp) and the benchmark (`ppsynth bench`):
//
//   points --Rasterizer(u)--> maps --FeatureNet--> [F1, F2, F3] --CompositeLoss--> loss
//
// GaborSettings are the resolved numbers of a run (grid, k, sigmas, attributes, ...).
#include <torch/torch.h>

#include <memory>
#include <random>
#include <vector>

#include "core/output_shape.hpp"
#include "core/point_set.hpp"
#include "losses/composite_loss.hpp"
#include "models/feature_net.hpp"
#include "models/rasterizer.hpp"
#include "optim/gabor/border_relax_options.hpp"
#include "optim/gabor/gabor_options.hpp"
#include "optim/gabor/window_plan.hpp"

namespace ppsynth {

// The "gabor" method's defaults (the published code's settings, method.md §2-5).
json gabor_defaults();
// The range of each numeric default (core/config/param_bounds.hpp), checked on creation.
json gabor_bounds();

// Resolved from the method's params by resolve_gabor_settings: the defaults are gabor_defaults()'s
// and the run config's, declared once there; the zeros below are not values a run can get.
struct GaborSettings {
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
  // optim/gabor/window_plan.hpp), rows x columns in the exemplar's aspect.
  int out_res = 0, out_rows = 0;
  double out_scale = 0;
  WindowSize window;            // rectangles: the windows' size and count (one: the canvas)
  double window_margin = 0;     // rectangles: exemplar units reserved on each side of a window's interior
  bool statistics_in_output = false;  // rectangles: the losses measure the grid's part inside the output only
  // method.measure (the paper's u x u torus only for all but "grid"): "grid" measures the
  // whole grid as published; "tiles" cuts the output at a random offset into u x u
  // exemplar-sized tiles, each on the exemplar's grid; "rolled" measures the whole grid of
  // the torus rolled by a random offset (optim/gabor/random_tiles.hpp). Both offsets change with
  // every iteration.
  GaborOptions::Measure measure = GaborOptions::Measure::grid;
  bool measure_tiles() const { return measure == GaborOptions::Measure::tiles; }
  BorderRelaxOptions border_relax;  // method.border_relax (optim/gabor/border_relax_options.hpp)
  // The grid of each sigma stage (coarse -> fine): `res` and `out_res` at every stage, or with
  // method.grid.per_sigma coarser grids at the coarser sigmas, keeping the finest stage's
  // grid positions per sigma (the Gabor frequencies scale with 1/sigma, so each stage's
  // maps are sampled as finely as the finest stage's).
  std::vector<int> sigma_res, sigma_out_res, sigma_out_rows;
  int k = 0;                    // neighbors per grid position: min(M, k)
  bool k_per_stage = true;      // k = min(k, exemplar points of the stage's classes)
  std::vector<double> sigmas;   // coarse -> fine
  std::vector<int> attr_cols;   // attribute columns weighting the maps
  std::vector<int> class_order;
  int max_iterations = 0;
  bool jitter = true;
  bool fresh_net_per_class = false;  // a new random network per class group (the published attribute scenes)
  json feature_net;             // the net spec after --quick shrinking
};

// Resolves settings from the method's (defaults-merged) params for an output of `shape`;
// errors name the key.
GaborSettings resolve_gabor_settings(const json& params, const PointSet& exemplar, const OutputShape& shape, bool quick);

class GaborPipeline {
 public:
  // Every module and tensor of the pipeline lives on `device` (runtime.device): the points
  // and weights given to it must be there too; set_targets moves the exemplar's itself.
  GaborPipeline(const json& params, const GaborSettings& s, uint64_t seed, torch::Device device = torch::kCPU);

  // Exemplar features -> loss targets; once per sigma (and per class stage). The exemplar's
  // points and weights may be on the CPU: they are moved to the pipeline's device.
  void set_targets(const torch::Tensor& ex_points, const torch::Tensor& ex_weights, double sigma);
  // The three stages of one output evaluation.
  torch::Tensor output_maps(const torch::Tensor& points, const torch::Tensor& weights, double sigma,
                            const torch::Tensor& jitter) { return out_rast_->forward(points, weights, sigma, jitter); }
  // A tile of the output the exemplar's size, rasterized as the exemplar is (method.measure = "tiles").
  torch::Tensor tile_maps(const torch::Tensor& points, const torch::Tensor& weights, double sigma,
                          const torch::Tensor& jitter) { return tile_rast_->forward(points, weights, sigma, jitter); }
  Features features(const torch::Tensor& maps) { return net_->forward(maps); }
  torch::Tensor loss(const Features& f) { return loss_.forward(f); }
  // Independent uniform offsets in [-1, 1] / (R + 1) per grid position and axis of the output
  // grid (R = out_res, rows x R positions) or of a tile (R = res, R x R), or an undefined tensor when jitter is off or
  // meaningless for the rasterizer. Drawn on the CPU from `rng` (the same offsets on every
  // device, and the generator's state is what a checkpoint keeps), then moved to the device.
  torch::Tensor draw_jitter(std::mt19937_64& rng, bool tile = false) const;
  // A new random network (the published code draws one per class for attribute scenes).
  void redraw_network(uint64_t seed);
  // Neighbors per grid position for the next stage (rebuilds the rasterizers if it changes).
  void set_neighbors(int k);
  // The grid of sigma stage `sigma_index` (GaborSettings::sigma_res; rebuilds if it changes).
  void set_grid(int sigma_index);
  const torch::Device& device() const { return device_; }

  const CompositeLoss& composite() const { return loss_; }
  json resolved() const;  // rasterizer, feature net and losses with every default filled in

 private:
  json p_;
  GaborSettings s_;
  uint64_t seed_;
  torch::Device device_;
  // tile_rast_ (method.measure "tiles"): the exemplar's raster, dividing by the exemplar's
  // neighbor count (tile_divisor_) even where a tile holds fewer points.
  std::unique_ptr<Rasterizer> ex_rast_, out_rast_, tile_rast_;
  int tile_divisor_ = 0;
  std::unique_ptr<FeatureNet> net_;
  CompositeLoss loss_;
  json resolved_rast_, resolved_net_;
  int in_channels_ = 10;
  int res_ = 0, out_res_ = 0, out_rows_ = 0;  // the current stage's grids (res_: per exemplar unit)
  void build_rasterizers();
};

// Every layer cut to the part {x0, y0, x1, y1} of the grid (fractions; x along columns, y
// along rows, as the maps lie): the losses then measure that part only (method.window.statistics
// "output"). Gram matrices average over the positions they get and the deep correlation
// normalizes by its overlap, so a part is measured as a smaller grid would be. Empty: all of it.
Features measured_part(const Features& f, const std::vector<double>& part);

// The network of a plan's class_step-th class when method.fresh_net_per_class draws one per
// class (as the published code does): the run's seed for the first.
inline uint64_t class_network_seed(uint64_t seed, int class_step) {
  return class_step == 0 ? seed : seed + 7919ull * static_cast<uint64_t>(class_step);
}

// Published toroidal wrap (x > 1 -> x - floor(x); x < 0 -> x + ceil(|x|)), identity gradient.
torch::Tensor wrap_unit(const torch::Tensor& x);

// The map weights of Eq. 5 for a config's "map_attributes": null or "auto" = every attribute column
// that is not constant; or an explicit list of names. Returns column indices.
std::vector<int> map_attribute_columns(const PointSet& exemplar, const json& spec);

}  // namespace ppsynth
