#include "core/procedural/pptbf.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "core/error.hpp"
#include "core/procedural/pptbf_noise.hpp"

namespace ppsynth {

using namespace pptbf_impl;

PptbfEvaluator::PptbfEvaluator(const PptbfParams& params)
    : prm_(params), pp_(params.tile_type, params.jitter, static_cast<std::uint64_t>(params.seed)) {
  validate(prm_);
}

Vec2 PptbfEvaluator::to_model(Vec2 x) const {
  if (prm_.ampli[0] != 0) {
    const Vec2 n = brownnoise(static_cast<std::uint64_t>(prm_.seed),
                              Vec2{prm_.ampli[1] * x.x * prm_.zoom, prm_.ampli[1] * x.y * prm_.zoom},
                              prm_.ampli[2]);
    x.x += prm_.ampli[0] * n.x;
    x.y += prm_.ampli[0] * n.y;
  }
  const double c = std::cos(prm_.rotation), s = std::sin(prm_.rotation);
  const double sx = x.x / prm_.rescalex;
  return {prm_.zoom * (c * sx - s * x.y), prm_.zoom * (s * sx + c * x.y)};
}

Vec2 PptbfEvaluator::model_to_image(Vec2 m) const {
  const double c = std::cos(prm_.rotation), s = std::sin(prm_.rotation);
  const double ux = m.x / prm_.zoom, uy = m.y / prm_.zoom;
  return {(c * ux + s * uy) * prm_.rescalex, -s * ux + c * uy};
}

const CellFeature& PptbfEvaluator::feature_of(const FeaturePoint& fp) {
  auto it = features_.find(fp.key);
  if (it != features_.end()) return it->second;
  return features_.emplace(fp.key, draw_cell_feature(fp, prm_)).first->second;
}

const CellShape& PptbfEvaluator::shape_of(const FeaturePoint& fp) {
  auto it = shapes_.find(fp.key);
  if (it != shapes_.end()) return it->second;
  // neighbors around the site itself, so the shape does not depend on the pixel asking
  std::vector<FeaturePoint> around;
  pp_.points_near(fp.p, pp_.reach(), around);
  CellShape cs = make_cell_shape(fp, around, prm_.norm, prm_.larp, prm_.arity, feature_of(fp).start_angle);
  return shapes_.emplace(fp.key, std::move(cs)).first->second;
}

double PptbfEvaluator::operator()(double x, double y) {
  const Vec2 m = to_model(Vec2{x, y});
  pts_.clear();
  pp_.points_near(m, pp_.reach(), pts_);
  nth_closest(m, pts_, prm_.norm, prm_.larp, order_);
  const double footprint = pp_.footprint();
  const bool max_model = prm_.mixture >= 4;
  double value = 0;
  MaxMixture mx;
  for (size_t k = 0; k < order_.size(); ++k) {
    const FeaturePoint& fp = pts_[order_[k]];
    if (max_model) {
      mx.add_cell(feature_of(fp), fp, m, prm_, footprint);
      continue;
    }
    double w1 = 0;
    if (k == 0 && prm_.normblend > 0) w1 = window_w1(cellular_value(shape_of(fp), m, prm_.wsmooth), prm_.normblend, prm_.sigw1);
    const double sddno = minkowski(Vec2{m.x - fp.p.x, m.y - fp.p.y}, prm_.norm);
    const double w2 = window_w2(sddno, prm_.normblend, prm_.sigw2, footprint);
    if (w1 + w2 == 0) continue;  // contributes (w1 + w2) * feat = 0
    value += (w1 + w2) * feature_sum(feature_of(fp), fp, m, prm_, footprint);
  }
  return max_model ? mx.value : value;
}

double pptbf(const PptbfParams& params, double x, double y) {
  PptbfEvaluator ev(params);
  return ev(x, y);
}

GrayImage render_pptbf(const PptbfParams& params, int width, int height, const Domain& window, int threads) {
  if (width <= 0 || height <= 0) throw InputError("render_pptbf: resolution must be positive");
  validate(params);
  GrayImage img;
  img.width = width;
  img.height = height;
  img.pixels.assign(static_cast<size_t>(width) * height, 0.f);
  int nt = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  nt = std::min(nt, height);
  auto work = [&](int t) {
    PptbfEvaluator ev(params);
    for (int r = t; r < height; r += nt) {
      const double y = window.y1 - (r + 0.5) / height * window.height();
      for (int c = 0; c < width; ++c) {
        const double x = window.x0 + (c + 0.5) / width * window.width();
        img.pixels[static_cast<size_t>(r) * width + c] = static_cast<float>(ev(x, y));
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < nt; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  return img;
}

}  // namespace ppsynth
