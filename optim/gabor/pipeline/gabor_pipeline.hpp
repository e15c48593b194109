#pragma once
// GaborPipeline: the parts of the Gabor method for one evaluation, shared by the
// synthesizer (optim/gabor/engine/gabor_synthesizer.hpp) and the benchmark (`ppsynth bench`):
//
//   points --Rasterizer(u)--> maps --FeatureNet--> [F1, F2, F3] --CompositeLoss--> loss
//
// It takes GaborSettings (optim/gabor/settings/gabor_settings.hpp) as resolved
// (optim/gabor/resolution/gabor_resolution.hpp).
#include <torch/torch.h>

#include <memory>
#include <random>
#include <vector>

#include "losses/composite_loss.hpp"
#include "models/feature_net.hpp"
#include "models/rasterizer.hpp"
#include "optim/gabor/settings/gabor_settings.hpp"

namespace ppsynth {

class GaborPipeline {
 public:
  // Every module and tensor of the pipeline lives on `device` (runtime.device): the points
  // and weights given to it must be there too; set_targets moves the exemplar's itself.
  // The rasterizer's and the losses' specs are the settings' options'.
  GaborPipeline(const GaborSettings& s, uint64_t seed, torch::Device device = torch::kCPU);

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

}  // namespace ppsynth
