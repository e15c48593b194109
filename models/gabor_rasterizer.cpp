// "gabor" and "spatial" rasterizers: GaborFeatureMaps behind the Rasterizer interface.
#include "core/config/defaults_catalog.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/rasterizer.hpp"

namespace ppsynth {
namespace {

class GaborRasterizer : public Rasterizer {
 public:
  explicit GaborRasterizer(GaborMapsOptions o) : maps_(register_module("maps", GaborFeatureMaps(o))) {}
  torch::Tensor forward(const torch::Tensor& p, const torch::Tensor& w, double sigma, const torch::Tensor& jitter) override {
    return maps_->forward(p, w, sigma, jitter);
  }
  int channels(int A) const override { return maps_->channels(A); }

 private:
  GaborFeatureMaps maps_;
};

std::unique_ptr<Rasterizer> make(const json& p, const std::string& key, const RasterizerArgs& a, bool spatial_only) {
  GaborMapsOptions o;
  o.res = a.res;
  o.rows = a.rows;
  o.upscale = a.upscale;
  o.k = a.k;
  o.divisor = a.divisor;
  o.base_frequency = get_number(p, "base_frequency", key);
  o.spatial_only = spatial_only;
  // Each raster chooses on its own: periodic output maps alone remove border parking but
  // ask the torus to copy the exemplar's border fade (clumps); periodic exemplar maps too
  // treat the exemplar as a tile, so both sides have no border (docs/lab/method_measurements.md "Border parking").
  o.periodic = get_bool(p, a.output ? "periodic_output" : "periodic_exemplar", key);
  return std::make_unique<GaborRasterizer>(o);
}

// Both rasterizers' parameters, declared once (the frequency's default is the maps' own).
json gabor_rasterizer_defaults() {
  return json{{"base_frequency", GaborMapsOptions{}.base_frequency}, {"periodic_output", false}, {"periodic_exemplar", false}};
}
json gabor_rasterizer_bounds() { return json{{"base_frequency", "(0, inf)"}}; }

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::RasterizerRegistry, "gabor", ppsynth::gabor_rasterizer_defaults(), ppsynth::gabor_rasterizer_bounds(),
                 "Gabor maps: 1 spatial + 9 frequency maps per attribute (paper Eq. 5)",
                 [](const ppsynth::json& p, const std::string& key, ppsynth::RasterizerArgs a) { return ppsynth::make(p, key, a, false); })
PPSYNTH_REGISTER(ppsynth::RasterizerRegistry, "spatial", ppsynth::gabor_rasterizer_defaults(), ppsynth::gabor_rasterizer_bounds(),
                 "spatial maps only (gamma = 0; Fig. 11, irregular-convolution features)",
                 [](const ppsynth::json& p, const std::string& key, ppsynth::RasterizerArgs a) { return ppsynth::make(p, key, a, true); })
PPSYNTH_DEFAULTS_KIND("rasterizer", ppsynth::RasterizerRegistry)
