#include "optim/gabor/pipeline/gabor_pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "models/feature_grid.hpp"

namespace ppsynth {

torch::Tensor wrap_unit(const torch::Tensor& x) {
  auto y = torch::where(x > 1, x - torch::floor(x), x);
  return torch::where(y < 0, y + torch::ceil(torch::abs(y)), y);
}

GaborPipeline::GaborPipeline(const GaborSettings& s, uint64_t seed, torch::Device device)
    : s_(s), seed_(seed), device_(device), loss_(s.options.losses, "method.losses"), res_(s.sigma_res.at(0)),
      out_res_(s.sigma_out_res.at(0)), out_rows_(s.sigma_out_rows.at(0)) {
  build_rasterizers();
  in_channels_ = ex_rast_->channels(static_cast<int>(s.attr_cols.size()));
  redraw_network(seed);
}

void GaborPipeline::build_rasterizers() {
  // The exemplar's raster over s_.exemplar_grid, its width the unit (the unit square: res_ x res_).
  const Domain& E = s_.exemplar_grid;
  const int ex_cols = static_cast<int>(std::lround(E.width() * res_)), ex_rows = grid_rows(ex_cols, E.height() / E.width());
  RasterizerArgs ex_args{ex_cols, E.width(), s_.k, false, 0, ex_rows},
      out_args{out_res_, s_.out_scale, s_.k, true, 0, out_rows_};
  ex_rast_ = RasterizerRegistry::instance().create(s_.options.rasterizer, "method.rasterizer", ex_args, &resolved_rast_);
  out_rast_ = RasterizerRegistry::instance().create(s_.options.rasterizer, "method.rasterizer", out_args);
  if (s_.measure_tiles()) {
    RasterizerArgs tile_args = ex_args;
    tile_args.divisor = tile_divisor_;
    tile_rast_ = RasterizerRegistry::instance().create(s_.options.rasterizer, "method.rasterizer", tile_args);
  }
  for (auto* r : {&ex_rast_, &out_rast_, &tile_rast_})
    if (*r) (*r)->to(device_);
}

void GaborPipeline::set_neighbors(int k) {
  if (k == s_.k) return;
  s_.k = k;
  build_rasterizers();
}

void GaborPipeline::set_grid(int sigma_index) {
  const int r = s_.sigma_res.at(sigma_index), o = s_.sigma_out_res.at(sigma_index), rows = s_.sigma_out_rows.at(sigma_index);
  if (r == res_ && o == out_res_ && rows == out_rows_) return;
  res_ = r;
  out_res_ = o;
  out_rows_ = rows;
  build_rasterizers();
}

void GaborPipeline::redraw_network(uint64_t seed) {
  net_ = FeatureNetRegistry::instance().create(s_.feature_net, "method.feature_net", in_channels_, seed, &resolved_net_);
  resolved_net_.update(net_->choices());
  net_->to(device_);  // drawn on the CPU from the seed: the same network on every device
}

void GaborPipeline::set_targets(const torch::Tensor& ex_points, const torch::Tensor& ex_weights, double sigma) {
  torch::NoGradGuard ng;
  // A tile's maps divide as the exemplar's do: by its neighbors summed, min(k, its points).
  const int divisor = static_cast<int>(std::min<int64_t>(s_.k, ex_points.size(0)));
  if (s_.measure_tiles() && divisor != tile_divisor_) {
    tile_divisor_ = divisor;
    build_rasterizers();
  }
  const auto weights = ex_weights.defined() ? ex_weights.to(device_) : ex_weights;
  // In the raster's coordinates: (p - corner) / width (the unit square's are the points').
  const Domain& E = s_.exemplar_grid;
  const bool unit = E.x0 == 0 && E.y0 == 0 && E.x1 == 1 && E.y1 == 1;
  const auto local = unit ? ex_points : (ex_points - torch::tensor({{E.x0, E.y0}}, ex_points.options())) / E.width();
  auto f = net_->forward(ex_rast_->forward(local.to(device_), weights, sigma, {}));
  // Tiles are the exemplar's size: their features match the targets' one to one.
  loss_.set_target(f, LossContext{s_.measure_tiles() ? 1 : s_.upscale, seed_});
}

torch::Tensor GaborPipeline::draw_jitter(std::mt19937_64& rng, bool tile) const {
  if (!s_.options.jitter || !out_rast_->uses_jitter()) return {};
  const int64_t R = tile ? res_ : out_res_, rows = tile ? res_ : out_rows_;
  const float amp = 1.0f / static_cast<float>(R + 1);  // the columns' spacing, the rows' too
  std::uniform_real_distribution<float> unif(-1.0f, 1.0f);
  auto j = torch::empty({rows * R, 2});
  float* ptr = j.data_ptr<float>();
  for (int64_t i = 0; i < j.numel(); ++i) ptr[i] = unif(rng) * amp;
  return j.to(device_);
}

json GaborPipeline::resolved() const {
  return {{"rasterizer", resolved_rast_}, {"feature_net", resolved_net_}, {"losses", loss_.resolved()}};
}

Features measured_part(const Features& f, const std::vector<double>& part) {
  if (part.empty()) return f;
  Features cut;
  for (const auto& F : f) {
    const int64_t H = F.size(2), W = F.size(3);
    auto range = [](double a, double b, int64_t n) {
      const int64_t i0 = std::clamp<int64_t>(std::llround(a * n), 0, n - 1);
      return std::make_pair(i0, std::clamp<int64_t>(std::llround(b * n), i0 + 1, n));
    };
    const auto [c0, c1] = range(part[0], part[2], W);
    const auto [r0, r1] = range(part[1], part[3], H);
    cut.push_back(F.slice(3, c0, c1).slice(2, r0, r1));
  }
  return cut;
}

}  // namespace ppsynth
