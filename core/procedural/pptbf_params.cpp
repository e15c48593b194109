#include "core/procedural/pptbf_params.hpp"

#include <cmath>

#include "core/config/config.hpp"
#include "core/error.hpp"

namespace ppsynth {

nlohmann::json to_json(const PptbfParams& p) {
  return nlohmann::json{
      {"seed", p.seed},           {"zoom", p.zoom},
      {"rotation", p.rotation},   {"rescalex", p.rescalex},
      {"ampli", p.ampli},         {"tile_type", p.tile_type},
      {"jitter", p.jitter},       {"normblend", p.normblend},
      {"arity", p.arity},         {"larp", p.larp},
      {"wsmooth", p.wsmooth},     {"norm", p.norm},
      {"sigw1", p.sigw1},         {"sigw2", p.sigw2},
      {"mixture", p.mixture},     {"winfeatcorrel", p.winfeatcorrel},
      {"feataniso", p.feataniso}, {"Jmin", p.Jmin},
      {"Jmax", p.Jmax},           {"freq", p.freq},
      {"thickness", p.thickness}, {"curvature", p.curvature},
      {"deltaorient", p.deltaorient}, {"normfeat", p.normfeat},
      {"sigcos", p.sigcos},       {"sigcosvar", p.sigcosvar},
  };
}

nlohmann::json pptbf_default_params_json() {
  nlohmann::json j = to_json(PptbfParams{});
  j["description"] = "";  // free text, ignored
  return j;
}

namespace {
std::string kp(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
void check(bool ok, const std::string& path, const std::string& key, const std::string& msg) {
  if (!ok) throw config_error(kp(path, key), msg);
}
}  // namespace

PptbfParams pptbf_params_from_json(const nlohmann::json& user, const std::string& key_path) {
  const nlohmann::json j = apply_defaults(pptbf_default_params_json(), user, key_path);
  PptbfParams p;
  auto num = [&](const char* k) { return get_number(j, k, key_path); };
  auto integer = [&](const char* k) { return get_int(j, k, key_path); };
  const double seed = num("seed");
  check(seed == std::floor(seed), key_path, "seed", "expected an integer");
  p.seed = static_cast<long long>(seed);
  p.zoom = num("zoom");
  p.rotation = num("rotation");
  p.rescalex = num("rescalex");
  const auto& a = j["ampli"];
  check(a.size() == 3, key_path, "ampli", "expected 3 numbers [amplitude, frequency, falloff]");
  for (int i = 0; i < 3; ++i) {
    check(a[i].is_number(), key_path, "ampli", "expected 3 numbers [amplitude, frequency, falloff]");
    p.ampli[i] = a[i].get<double>();
  }
  p.tile_type = integer("tile_type");
  p.jitter = num("jitter");
  p.normblend = num("normblend");
  p.arity = integer("arity");
  p.larp = num("larp");
  p.wsmooth = num("wsmooth");
  p.norm = num("norm");
  p.sigw1 = num("sigw1");
  p.sigw2 = num("sigw2");
  p.mixture = integer("mixture");
  p.winfeatcorrel = num("winfeatcorrel");
  p.feataniso = num("feataniso");
  p.Jmin = integer("Jmin");
  p.Jmax = integer("Jmax");
  p.freq = num("freq");
  p.thickness = num("thickness");
  p.curvature = num("curvature");
  p.deltaorient = num("deltaorient");
  p.normfeat = num("normfeat");
  p.sigcos = num("sigcos");
  p.sigcosvar = num("sigcosvar");
  validate(p, key_path);
  return p;
}

void validate(const PptbfParams& p, const std::string& path) {
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  check(p.zoom > 0 && std::isfinite(p.zoom), path, "zoom", "must be > 0");
  check(p.rescalex > 0 && std::isfinite(p.rescalex), path, "rescalex", "must be > 0");
  check(std::isfinite(p.rotation), path, "rotation", "must be finite");
  check(p.ampli[0] >= 0 && p.ampli[1] >= 0 && in(p.ampli[2], 0, 1), path, "ampli",
        "needs amplitude >= 0, frequency >= 0, falloff in [0,1]");
  check(p.tile_type >= 0 && p.tile_type <= 17, path, "tile_type", "must be in 0..17");
  check(in(p.jitter, 0, 1), path, "jitter", "must be in [0,1]");
  check(in(p.normblend, 0, 1), path, "normblend", "must be in [0,1]");
  check(p.arity >= 3 && p.arity <= 64, path, "arity", "must be in 3..64");
  check(in(p.larp, 0, 1), path, "larp", "must be in [0,1]");
  check(in(p.wsmooth, 0, 2), path, "wsmooth", "must be in [0,2]");
  check(in(p.norm, 1, 1e9), path, "norm", "must be >= 1");
  check(in(p.sigw1, 1e-6, 1e6), path, "sigw1", "must be > 0");
  check(in(p.sigw2, 0, 1e6), path, "sigw2", "must be >= 0");
  check(p.mixture >= 0 && p.mixture <= 5, path, "mixture", "must be in 0..5");
  check(in(p.winfeatcorrel, 0, 1), path, "winfeatcorrel", "must be in [0,1]");
  check(in(p.feataniso, 1e-6, 1e6), path, "feataniso", "must be > 0");
  check(p.Jmin >= 0 && p.Jmin <= 64, path, "Jmin", "must be in 0..64");
  check(p.Jmax >= p.Jmin && p.Jmax <= 64, path, "Jmax", "must be in Jmin..64");
  check(in(p.freq, 0, 1e4), path, "freq", "must be >= 0");
  check(in(p.thickness, 0, 1e6), path, "thickness", "must be >= 0");
  check(in(p.curvature, 0, 1e6), path, "curvature", "must be >= 0");
  check(std::isfinite(p.deltaorient), path, "deltaorient", "must be finite");
  check(in(p.normfeat, 1, 1e9), path, "normfeat", "must be >= 1");
  check(in(p.sigcos, 1e-6, 1e6), path, "sigcos", "must be > 0");
  check(in(p.sigcosvar, 0, 1e6), path, "sigcosvar", "must be >= 0");
}

}  // namespace ppsynth
