#include "experiments/reproduce/reproduce_gabor_maps.hpp"

#include <algorithm>
#include <cstdio>

#include "core/render/image_grid.hpp"
#include "core/render/plot_points.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/point_tensor.hpp"

namespace ppsynth {

namespace {

// Channel `c` of a 1 x C x R x R map tensor as an image, rows flipped (y up).
GrayImage channel_image(const torch::Tensor& maps, int c, const std::string& title) {
  auto m = maps.index({0, c}).to(torch::kFloat32).contiguous();
  const int h = static_cast<int>(m.size(0)), w = static_cast<int>(m.size(1));
  const float* p = m.data_ptr<float>();
  GrayImage img;
  img.width = w;
  img.height = h;
  img.title = title;
  img.pixels.resize(static_cast<size_t>(w) * h);
  for (int r = 0; r < h; ++r) std::copy(p + static_cast<size_t>(h - 1 - r) * w, p + static_cast<size_t>(h - r) * w, img.pixels.begin() + static_cast<size_t>(r) * w);
  return img;
}

std::string map_label(const char* f, double a, double b = 0) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> render_gabor_map_figure(const PointSet& exemplar, const nlohmann::json& maps,
                                                                         bool quick, const std::string& dir) {
  torch::NoGradGuard no_grad;
  GaborMapsOptions mo;
  mo.res = maps["res"].get<int>();
  if (quick) mo.res = std::min(mo.res, maps["quick_res"].get<int>());
  mo.upscale = 1.0;
  mo.k = static_cast<int>(std::min<size_t>(exemplar.size(), maps["k"].get<size_t>()));
  mo.base_frequency = maps["base_frequency"].get<double>();
  GaborFeatureMaps module(mo);
  const auto pts = positions_tensor(exemplar);
  const double f = mo.base_frequency;
  const int cell = 200;

  std::vector<std::pair<std::string, std::string>> out;
  PointStyle st;
  st.title = "(a) exemplar, " + std::to_string(exemplar.size()) + " points";
  plot_points(dir + "/gabor_exemplar.png", exemplar, st, 360);
  out.push_back({"gabor_exemplar.png", "(a) the point pattern"});

  const double sigma = maps["sigma"].get<double>();
  auto m = module->forward(pts, torch::Tensor(), sigma);
  std::vector<GrayImage> freq;
  for (int fi = 0; fi < 9; ++fi)
    freq.push_back(channel_image(m, 1 + fi, map_label("nu = (%+.1f, %+.1f)", ((fi % 3) - 1) * f, ((fi / 3) - 1) * f)));
  plot_image_grid(dir + "/gabor_frequencies.png", freq, 3, cell, true, ColorMap::Diverging);
  out.push_back({"gabor_frequencies.png", map_label("(b)-(d) frequency maps, gamma = 1, sigma = %.3f", sigma) + "; " +
                                              std::to_string(mo.res) + " x " + std::to_string(mo.res) + " grid, k = " +
                                              std::to_string(mo.k) + " (blue < 0 < red)"});

  std::vector<GrayImage> spatial;
  for (auto& s : maps["sigmas"]) {
    auto ms = module->forward(pts, torch::Tensor(), s.get<double>());
    spatial.push_back(channel_image(ms, 0, map_label("sigma = %.3f", s.get<double>())));
  }
  if (!spatial.empty()) {
    plot_image_grid(dir + "/gabor_sigmas.png", spatial, static_cast<int>(spatial.size()), cell, true, ColorMap::Gray);
    out.push_back({"gabor_sigmas.png", "(e)-(h) spatial maps, gamma = 0, for varying sigma"});
  }
  return out;
}

}  // namespace ppsynth
