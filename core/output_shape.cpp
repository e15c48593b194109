#include "core/output_shape.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

#include "core/config/config.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/metrics/nearest_neighbor.hpp"

namespace ppsynth {

Domain OutputShape::domain() const { return rectangle ? Domain{0, 0, width, height} : Domain{}; }

Domain OutputShape::canvas() const {
  const Domain d = domain();
  return rectangle && clean_border ? Domain{d.x0 - pad, d.y0 - pad, d.x1 + pad, d.y1 + pad} : d;
}

Domain OutputShape::moving_area() const { return exemplar_pad ? domain() : canvas(); }

void OutputShape::require_no_exemplar_pad(const std::string& method) const {
  if (exemplar_pad)
    throw config_error("output.border", "\"context\" (a frozen exemplar pad) is the Gabor method's; " + method +
                                            " takes \"clean\" or \"published\"");
}

std::vector<size_t> OutputShape::class_counts(const PointSet& ex, const Domain& d) const {
  const auto per_class = ex.class_counts();
  std::vector<size_t> n(per_class.size(), 0);
  // Output area in exemplar areas: the paper's unit square holds u^2 exemplars.
  const double exemplars = rectangle ? d.area() / ex.domain().area() : d.area() * upscale * upscale;
  for (size_t c = 0; c < per_class.size(); ++c)
    if (per_class[c] > 0) n[c] = std::max<size_t>(1, static_cast<size_t>(std::llround(per_class[c] * exemplars)));
  return n;
}

double OutputShape::expected_points(const PointSet& ex) const {
  double n = 0;
  for (size_t c : class_counts(ex, domain())) n += static_cast<double>(c);
  return n;
}

std::string OutputShape::describe() const {
  if (!rectangle) return "u = " + std::to_string(upscale) + " (unit square, " + std::to_string(upscale * upscale) + " exemplars)";
  char buf[240];
  const char* border = exemplar_pad ? "context" : clean_border ? "clean" : "published";
  if (from_upscale)
    std::snprintf(buf, sizeof buf, "u = %d (%d x %d copies of the rectangular exemplar: %g x %g exemplar units, %s border)",
                  upscale, upscale, upscale, width, height, border);
  else
    std::snprintf(buf, sizeof buf, "%g x %g exemplar units, %s border", width, height, border);
  return buf;
}

bool is_square(const Domain& d) { return std::abs(d.width() - d.height()) <= 1e-9 * std::max(d.width(), d.height()); }

const ParamTable<OutputOptions>& OutputOptions::params() {
  using O = OutputOptions;
  // null size and points: the paper's u x u output ("upscale"). "pad": null (= "auto") so that
  // the config check takes a length as well as "auto".
  static const ParamTable<O> t("output", {
      param("size", &O::size, "", "[a, b]: a rectangle a exemplar widths by b exemplar heights (null: upscale's)"),
      param("points", &O::points, "", "N: a square holding about N points at the exemplar's density"),
      param("border", &O::border, "", "a rectangle's border: clean (padded, cropped), context (the pad holds the exemplar, frozen) or published"),
      param("pad", &O::pad, "", "the pad of a clean or context border, in exemplar units (null or \"auto\": 2 mean nearest-neighbour distances)"),
  });
  return t;
}

nlohmann::json output_defaults() { return OutputOptions::params().defaults(); }

namespace {
std::atomic<size_t> g_resolutions{0};
}  // namespace

size_t output_shape_resolutions() { return g_resolutions.load(); }

OutputShape resolve_output_shape(const nlohmann::json& r, const PointSet& ex) {
  ++g_resolutions;
  OutputShape o;
  o.upscale = get_int(r, "upscale", "");
  const auto& j = r.at("output");
  const bool has_size = !j["size"].is_null(), has_points = !j["points"].is_null();
  const Domain E = ex.domain();
  o.exemplar_width = E.width();
  if (!has_size && !has_points && is_square(E)) return o;
  if (has_size && has_points) throw config_error("output", "give \"size\" or \"points\", not both");
  o.rectangle = true;
  if (!has_size && !has_points) {
    // A rectangular exemplar: the paper's unit square would pack u^2 exemplars' points into a
    // square of u x u exemplar heights (a 1.6 x 1 exemplar's at 1.6 times its density, its
    // pattern squeezed); u x u copies of its rectangle, in exemplar units, keep its shape and
    // its scale.
    o.from_upscale = true;
    o.width = o.upscale * E.width();
    o.height = o.upscale * E.height();
  } else if (has_size) {
    // In exemplar sides (the exemplar's width and height), as documented: the same request
    // gives the same output of an exemplar in any coordinate units.
    const auto& s = j["size"];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number())
      throw config_error("output.size", "expected [width, height] in exemplar sides (multiples of the exemplar's width and height)");
    o.width = s[0].get<double>() * E.width();
    o.height = s[1].get<double>() * E.height();
  } else {
    if (!j["points"].is_number_integer() || j["points"].get<long long>() < 1)
      throw config_error("output.points", "expected a point count >= 1");
    if (ex.empty()) throw config_error("output.points", "the exemplar has no points, so no density");
    const double area = static_cast<double>(j["points"].get<long long>()) * E.area() / static_cast<double>(ex.size());
    const double aspect = E.width() / E.height();
    o.width = std::sqrt(area * aspect);
    o.height = std::sqrt(area / aspect);
  }
  // A side below a hundredth of the exemplar's holds no pattern; above 10^4 exemplar sides
  // the point count overflows any machine (10^8 exemplars).
  if (!(o.width >= 0.01 * E.width() && o.height >= 0.01 * E.height()) || !(o.width <= 1e4 * E.width() && o.height <= 1e4 * E.height()))
    throw config_error(has_size ? "output.size" : "output.points",
                       "the output must be 0.01 to 10000 exemplar sides wide and high");
  const std::string border = get_string(j, "border", "output");
  if (border != "clean" && border != "context" && border != "published")
    throw config_error("output.border", "expected \"clean\", \"context\" or \"published\"");
  o.clean_border = border != "published";
  o.exemplar_pad = border == "context";
  if (o.clean_border) {
    const auto& p = j["pad"];
    if (p.is_null() || (p.is_string() && p.get<std::string>() == "auto")) {
      o.pad = 2.0 * mean_nn_distance(ex);
    } else if (p.is_number()) {
      o.pad = p.get<double>();
      if (!(o.pad >= 0) || o.pad > 100 * std::max(E.width(), E.height()))
        throw config_error("output.pad", "expected \"auto\" or 0 to 100 exemplar sides");
    } else {
      throw config_error("output.pad", "expected \"auto\" or a length in exemplar units");
    }
  }
  return o;
}

}  // namespace ppsynth
