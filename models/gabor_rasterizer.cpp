// "gabor" and "spatial" rasterizers: GaborFeatureMaps behind the Rasterizer interface.
#include "core/config/defaults_catalog.hpp"
#include "core/config/params.hpp"
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

// Both rasterizers' parameters, each declared once (the frequency's default is the maps' own).
struct GaborRasterizerOptions {
  double base_frequency = GaborMapsOptions{}.base_frequency;
  // Each raster chooses on its own: periodic output maps alone remove border parking but ask
  // the torus to copy the exemplar's border fade (clumps); periodic exemplar maps too treat the
  // exemplar as a tile, so both sides have no border (docs/lab/method_measurements.md "Border parking").
  bool periodic_output = false;
  bool periodic_exemplar = false;

  static const ParamTable<GaborRasterizerOptions>& params() {
    using O = GaborRasterizerOptions;
    static const ParamTable<O> t("method.rasterizer", {
        param("base_frequency", &O::base_frequency, "(0, inf)", "the Gabor frequency f before the upscale (f = base u)"),
        param("periodic_output", &O::periodic_output, "", "the output's maps wrap around (a torus)"),
        param("periodic_exemplar", &O::periodic_exemplar, "", "the exemplar's maps wrap around (a tile)"),
    });
    return t;
  }
};

std::unique_ptr<Rasterizer> make(const GaborRasterizerOptions& r, const RasterizerArgs& a, bool spatial_only) {
  GaborMapsOptions o;
  o.res = a.res;
  o.rows = a.rows;
  o.upscale = a.upscale;
  o.k = a.k;
  o.divisor = a.divisor;
  o.base_frequency = r.base_frequency;
  o.spatial_only = spatial_only;
  o.periodic = a.output ? r.periodic_output : r.periodic_exemplar;
  return std::make_unique<GaborRasterizer>(o);
}

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::RasterizerRegistry, "rasterizer", "gabor", ppsynth::GaborRasterizerOptions::params(),
                        "Gabor maps: 1 spatial + 9 frequency maps per attribute (paper Eq. 5)",
                        [](const ppsynth::GaborRasterizerOptions& r, const std::string&, ppsynth::RasterizerArgs a) {
                          return ppsynth::make(r, a, false);
                        })
PPSYNTH_REGISTER_PARAMS(ppsynth::RasterizerRegistry, "rasterizer", "spatial", ppsynth::GaborRasterizerOptions::params(),
                        "spatial maps only (gamma = 0; Fig. 11, irregular-convolution features)",
                        [](const ppsynth::GaborRasterizerOptions& r, const std::string&, ppsynth::RasterizerArgs a) {
                          return ppsynth::make(r, a, true);
                        })
PPSYNTH_DEFAULTS_KIND("rasterizer", ppsynth::RasterizerRegistry)
