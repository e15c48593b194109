#include "core/metrics/eval_protocol.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"
#include "core/metrics/crops.hpp"
#include "core/metrics/quadrant.hpp"

namespace ppsynth {

namespace {

// The paper's protocol: a square output with u^2 = 4 times the exemplar's points; 3..5
// leaves room for outputs whose counts are the density's expectation.
constexpr double kQuadrantMinRatio = 3, kQuadrantMaxRatio = 5;
constexpr double kSquareTolerance = 1e-9;
// How far a requested quadrant's aspect ratio may be from the exemplar's: mapped onto the unit
// square, 1 % moves a feature at radius r by at most 0.01 r, within one of the PCF's 100 bins.
constexpr double kQuadrantShapeTolerance = 0.01;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

bool square(const Domain& d) {
  return std::abs(d.width() - d.height()) <= kSquareTolerance * std::max(d.width(), d.height());
}

// Whether a quadrant of the output has the exemplar's shape: their aspect ratios within
// kQuadrantShapeTolerance of each other.
bool quadrant_shape_fits(const PointSet& exemplar, const PointSet& output) {
  const Domain &e = exemplar.domain(), &o = output.domain();
  const double stretch = (o.width() / o.height()) / (e.width() / e.height());
  return std::isfinite(stretch) && std::abs(std::log(stretch)) <= std::log1p(kQuadrantShapeTolerance);
}

// "each of its quadrants is 2 x 0.5, the exemplar 1 x 1"
std::string quadrant_shapes(const PointSet& exemplar, const PointSet& output) {
  const Domain &e = exemplar.domain(), &o = output.domain();
  return "each of its quadrants is " + fmt(0.5 * o.width()) + " x " + fmt(0.5 * o.height()) + ", the exemplar " +
         fmt(e.width()) + " x " + fmt(e.height());
}

// Whether auto picks quadrants, and why (or why not) in words.
bool quadrants_fit(const PointSet& exemplar, const PointSet& output, std::string& why) {
  const Domain& d = output.domain();
  const double ratio = static_cast<double>(output.size()) / static_cast<double>(exemplar.size());
  if (!square(d)) {
    why = "auto: the output domain is " + fmt(d.width()) + " x " + fmt(d.height()) + ", not square";
    return false;
  }
  if (!square(exemplar.domain())) {
    why = "auto: the exemplar's domain is " + fmt(exemplar.domain().width()) + " x " + fmt(exemplar.domain().height()) +
          ", not square like the output's quadrants";
    return false;
  }
  if (ratio < kQuadrantMinRatio || ratio > kQuadrantMaxRatio) {
    why = "auto: the output holds " + fmt(ratio) + " x the exemplar's points (quadrants need " +
          fmt(kQuadrantMinRatio) + " to " + fmt(kQuadrantMaxRatio) + " x)";
    return false;
  }
  why = "auto: square output holding " + fmt(ratio) + " x the exemplar's points";
  return true;
}

}  // namespace

PatchProtocol parse_patch_protocol(const std::string& name) {
  if (name == "auto") return PatchProtocol::Auto;
  if (name == "quadrants") return PatchProtocol::Quadrants;
  if (name == "crops") return PatchProtocol::Crops;
  throw InputError("protocol (--protocol) must be auto, quadrants or crops (got '" + name + "')");
}

const char* patch_protocol_name(PatchProtocol p) {
  switch (p) {
    case PatchProtocol::Auto: return "auto";
    case PatchProtocol::Quadrants: return "quadrants";
    case PatchProtocol::Crops: return "crops";
  }
  return "?";
}

ProtocolPlan plan_protocol(const PointSet& exemplar, const PointSet& output, PatchProtocol requested, int crops,
                           uint64_t seed, double zoom) {
  ProtocolPlan p;
  p.requested = requested;
  p.zoom = zoom > 0 ? zoom : density_zoom(exemplar, output);
  if (requested == PatchProtocol::Auto) {
    p.used = quadrants_fit(exemplar, output, p.reason) ? PatchProtocol::Quadrants : PatchProtocol::Crops;
  } else {
    p.used = requested;
    p.reason = "requested";
  }
  if (p.used == PatchProtocol::Quadrants) {
    if (!quadrant_shape_fits(exemplar, output)) {
      std::string crops_fit = "--protocol crops compares exemplar-sized crops instead";
      try {
        plan_crops(exemplar, output, 1, seed, zoom);
      } catch (const InputError&) {
        crops_fit = "exemplar-sized crops do not fit it either (it is smaller than the exemplar at its density)";
      }
      throw InputError("--protocol quadrants: " + quadrant_shapes(exemplar, output) +
                       ": mapped onto the unit square, the two would be compared stretched. Quadrants need an output of the "
                       "exemplar's shape; " + crops_fit);
    }
    p.windows = quadrant_windows(output.domain());
    p.patch_width = 0.5 * output.domain().width();
    p.patch_height = 0.5 * output.domain().height();
    return p;
  }
  CropPlan c;
  try {
    c = plan_crops(exemplar, output, crops, seed, zoom);
  } catch (const InputError& e) {  // what else fits, if anything
    if (quadrant_shape_fits(exemplar, output))
      throw InputError(std::string(e.what()) + "; --protocol quadrants compares its 4 quadrants (they have the exemplar's shape)");
    throw InputError(std::string(e.what()) + "; quadrants do not fit it either (" + quadrant_shapes(exemplar, output) +
                     "): evaluate an output at least as large as the exemplar" +
                     (zoom > 0 ? std::string() : ", or give the zoom it was made at (eval --zoom)"));
  }
  p.windows = std::move(c.windows);
  p.patch_width = c.width;
  p.patch_height = c.height;
  p.seed = seed;
  if (c.zoom_fitted) {
    p.zoom = c.zoom;
    p.reason += "; the densities' zoom shrunk by its count spread so that a crop fits the output";
  }
  return p;
}

nlohmann::json protocol_json(const ProtocolPlan& plan) {
  nlohmann::json j = {{"name", patch_protocol_name(plan.used)},
                      {"requested", patch_protocol_name(plan.requested)},
                      {"reason", plan.reason},
                      {"patches", plan.windows.size()},
                      {"crop_size", {plan.patch_width, plan.patch_height}},
                      {"zoom", plan.zoom}};
  if (plan.used == PatchProtocol::Crops) {
    j["seed"] = plan.seed;
    nlohmann::json w = nlohmann::json::array();
    for (const Domain& d : plan.windows) w.push_back({d.x0, d.y0, d.x1, d.y1});
    j["windows"] = w;
  }
  return j;
}

std::string protocol_line(const nlohmann::json& p) {
  std::ostringstream s;
  const std::string name = p.value("name", std::string("quadrants"));
  const auto& size = p["crop_size"];
  s << "protocol: " << name << ", " << p.value("patches", size_t(0)) << (name == "crops" ? " crops" : " quadrants")
    << " of " << fmt(size[0].get<double>()) << " x " << fmt(size[1].get<double>()) << " output units (zoom "
    << fmt(p.value("zoom", 1.0)) << " output units per exemplar unit";
  if (name == "crops") s << ", seed " << p.value("seed", uint64_t(0));
  s << "); " << p.value("reason", std::string());
  return s.str();
}

}  // namespace ppsynth
