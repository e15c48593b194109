#include "optim/gabor/resolution/gabor_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "core/config/param_docs.hpp"
#include "core/config/params.hpp"
#include "core/memory_budget.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "models/feature_net.hpp"
#include "optim/gabor/settings/gabor_options.hpp"
#include "optim/gabor/settings/grid_options.hpp"
#include "optim/gabor/settings/quick_options.hpp"
#include "optim/gabor/settings/sigma_schedule.hpp"
#include "optim/gabor/settings/window_options.hpp"
#include "optim/gabor/settings/window_size.hpp"
#include "optim/gabor/stages/map_term.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/terms/point_term.hpp"

namespace ppsynth {

// Each stage kind's block is method.<name> as its registration declares it
// (optim/gabor/stages/stage_kind.hpp); the method's own keys are GaborOptions' table's.
json gabor_defaults() {
  json d = GaborOptions::params().defaults();
  const json kinds = StageKindRegistry::instance().describe();
  for (const auto& [name, block] : kinds.items()) d[name] = block["defaults"];
  return d;
}

json gabor_bounds() {
  json b = GaborOptions::params().bounds();
  const json kinds = StageKindRegistry::instance().describe();
  for (const auto& [name, block] : kinds.items())
    if (!block["bounds"].empty()) b[name] = block["bounds"];
  return b;
}

PPSYNTH_PARAM_DOCS("method", "gabor", [] { return GaborOptions::params().docs(); })

std::vector<int> map_attribute_columns(const PointSet& ex, const json& spec) {
  std::vector<int> cols;
  if (spec.is_null() || (spec.is_string() && spec.get<std::string>() == "auto")) {
    for (size_t a = 0; a < ex.num_attributes(); ++a) {
      const auto& c = ex.attribute_column(a);
      if (!c.empty() && *std::max_element(c.begin(), c.end()) > *std::min_element(c.begin(), c.end()))
        cols.push_back(static_cast<int>(a));
    }
    return cols;
  }
  if (!spec.is_array()) throw config_error("method.map_attributes", "expected \"auto\" or a list of attribute names");
  for (auto& n : spec) {
    if (!n.is_string()) throw config_error("method.map_attributes", "expected attribute names");
    auto idx = ex.attribute_index(n.get<std::string>());
    if (!idx) throw config_error("method.map_attributes", "the exemplar has no attribute '" + n.get<std::string>() + "'");
    cols.push_back(*idx);
  }
  return cols;
}

namespace {

// A rectangle is synthesized in the exemplar's own units, and the grid's resolution is per
// unit: an exemplar in far smaller or larger units than 1 would get a grid of a fraction of a
// position, or of millions, across it (the maps then failed inside).
void check_exemplar_grid(const Domain& exemplar, int res) {
  const double side = std::min(exemplar.width(), exemplar.height()), across = res * side;
  if (across >= 8 && across <= 8192) return;
  char what[320];
  std::snprintf(what, sizeof what,
                "a rectangle output is synthesized in the exemplar's units on %d grid positions a unit, which "
                "gives %.3g positions across this exemplar's shorter side (%g units), outside 8..8192; give the "
                "exemplar in units where its shorter side is near 1, or set method.grid.res",
                res, across, side);
  throw config_error("method.grid", what);
}

// A rectangle's canvas on one grid, or the fewest windows within the budget; `full_res` and
// `full_num_sigmas`: the settings before --quick's caps.
void lay_out_windows(GaborSettings& s, const GaborOptions& o, const Domain& canvas, bool quick, int full_res, int full_num_sigmas) {
  const WindowOptions& window = o.window;
  // The finest sigma's grid is the largest: the budget is its.
  const double budget = std::pow(static_cast<double>(window.pixels), 2);
  s.window_margin = window.margin ? *window.margin : window.auto_margin(s.sigmas, s.sigma_res);
  std::optional<WindowSize> size = window_size(canvas, budget, s.res, s.window_margin);
  // --quick's coarser grid reaches farther than the full settings'; where its margin leaves the
  // windows no interior, the full settings' is taken, so that a smoke run takes every output
  // the real run takes.
  if (!size && quick && !window.margin) {
    const auto sigmas = sigma_schedule(s.mean_nn_distance, o.c1, o.c2, full_num_sigmas);
    s.window_margin = std::min(s.window_margin, window.auto_margin(sigmas, o.grid.per_stage(sigmas, full_res)));
    size = window_size(canvas, budget, s.res, s.window_margin);
  }
  if (!size)
    throw config_error("method.window", "windows of at most " + std::to_string(window.pixels) + " x " + std::to_string(window.pixels) +
                                            " grid positions cannot hold two margins of " + std::to_string(s.window_margin) +
                                            " exemplar units and an interior (the maps' reach and the network's receptive " +
                                            "field); use larger windows (method.window.pixels) or a larger output");
  s.window = *size;
  s.out_scale = size->width;
  std::tie(s.out_res, s.out_rows) = window_grid(size->width, size->height, s.res);
  for (int r : s.sigma_res) {
    const auto [cols, rows] = window_grid(size->width, size->height, r);
    s.sigma_out_res.push_back(cols);
    s.sigma_out_rows.push_back(rows);
  }
  s.statistics_in_output = window.statistics_in_output;
}

// One iteration keeps the output grid's maps and every layer's activations and gradients.
void check_iteration_memory(const GaborSettings& s, bool rectangle) {
  const double cells = static_cast<double>(s.out_res) * s.out_rows;
  // The network's parameters as its registry resolves them (its declared defaults under the
  // user's). A network without `channels` is costed as the largest fixed bank's (12 filters
  // per input map; identity: 1), so the estimate never falls short.
  const json net = FeatureNetRegistry::instance().resolve(s.feature_net, "method.feature_net");
  const double in_ch = 10.0 * (1 + s.attr_cols.size());
  const double net_ch = net.contains("channels") ? net["channels"].get<double>() : 12 * in_ch;
  const double layers = net.contains("depth") ? net["depth"].get<double>() : 1;
  check_memory(cells * 4.0 * (3 * in_ch + 6 * net_ch * layers + s.k * in_ch),
               "an output grid of " + std::to_string(s.out_res) + " x " + std::to_string(s.out_rows) +
                   (rectangle ? " (method.window.pixels)"
                              : " (method.grid.res " + std::to_string(s.res) + " x upscale " + std::to_string(s.upscale) + ")"));
}

// method.class_order against the exemplar's K classes: every class once; [] = file order.
std::vector<int> class_order(const std::vector<int>& order, int K) {
  std::vector<int> out;
  for (int c : order) {
    if (c >= K) throw config_error("method.class_order", "class ids are 0.." + std::to_string(K - 1));
    out.push_back(c);
  }
  if (out.empty())
    for (int c = 0; c < K; ++c) out.push_back(c);
  auto sorted = out;
  std::sort(sorted.begin(), sorted.end());
  for (int c = 0; c < K; ++c)
    if (static_cast<int>(sorted.size()) != K || sorted[c] != c)
      throw config_error("method.class_order", "must list every class 0.." + std::to_string(K - 1) + " once");
  return out;
}

}  // namespace

GaborParams read_gabor_params(const json& p, const std::string& key_path) {
  // Every key of the params is read here, by the method's table or as a stage kind's block: a
  // key declared but read by no one, or read but declared by no one, is a logic_error.
  ParamReader reader(p, key_path);
  if (p.contains("type")) reader.at("type");  // a spec as its registry resolved it: the method's name
  GaborParams g;
  g.options = GaborOptions::params().read(reader);
  // Each class-end kind's block as the method's registry merged and checked it; the kind
  // reads it, and refuses what it cannot run, naming method.<name>.<key>, as the settings resolve.
  for (const std::string& name : StageKindRegistry::instance().names()) g.stage_kinds[name] = reader.at(name);
  if (const std::vector<std::string> unread = reader.unread(); !unread.empty())
    throw std::logic_error("'" + unread.front() + "' is declared in the method's defaults but read by no one");
  return g;
}

GaborSettings resolve_gabor_settings(const json& p, const PointSet& exemplar, const OutputShape& shape, bool quick) {
  return resolve_gabor_settings(read_gabor_params(p), exemplar, shape, quick);
}

GaborSettings resolve_gabor_settings(const GaborParams& params, const PointSet& exemplar, const OutputShape& shape, bool quick) {
  GaborSettings s;
  if (shape.upscale < 1) throw config_error("upscale", "must be >= 1");
  s.upscale = shape.rectangle ? 1 : shape.upscale;
  const int K = exemplar.num_classes();
  s.mean_nn_distance = mean_nn_distance(exemplar);
  s.options = params.options;
  const GaborOptions& o = s.options;
  for (const auto& [name, block] : params.stage_kinds) s.stage_kinds[name] = block;
  const GridOptions& grid = o.grid;
  s.res = grid.resolved_res(s.mean_nn_distance);
  if (shape.rectangle) {
    s.exemplar_grid = exemplar.domain();
    check_exemplar_grid(exemplar.domain(), s.res);
  }
  int num_sigmas = o.num_sigmas;
  s.max_iterations = o.max_iterations;
  s.feature_net = with_channels_for_classes(o.feature_net, K, "method.feature_net");
  const int full_res = s.res, full_num_sigmas = num_sigmas;  // the window margin's (below)
  if (quick) {
    const QuickOptions& q = o.quick;
    s.res = std::min(s.res, q.res);
    s.max_iterations = std::min(s.max_iterations, q.max_iterations);
    num_sigmas = std::min(num_sigmas, q.num_sigmas);
    // Every network with a filter count (a `channels` parameter, declared where it registers)
    // takes the cap; a fixed bank or the identity has none to shrink.
    if (FeatureNetRegistry::instance().resolve(s.feature_net, "method.feature_net").contains("channels"))
      s.feature_net["channels"] = q.channels;
  }
  s.sigmas = sigma_schedule(s.mean_nn_distance, o.c1, o.c2, num_sigmas);
  s.k = static_cast<int>(std::min<size_t>(exemplar.size(), static_cast<size_t>(o.k)));
  s.attr_cols = map_attribute_columns(exemplar, o.map_attributes);
  s.sigma_res = grid.per_stage(s.sigmas, s.res);
  const std::string named = std::string("\"") + measure_name(o.measure) + "\"";
  if (o.measure != GaborOptions::Measure::grid && shape.rectangle)
    throw config_error("method.measure", named + " measures the paper's u x u square; a rectangle output "
                                         "(output.size or output.points) takes output.border instead");
  const bool map_terms = map_terms_act(o.map_terms, exemplar.num_classes());
  if (o.measure != GaborOptions::Measure::grid && map_terms)
    throw config_error("method.measure", named + " does not combine with method.map_terms (their maps are the unrolled grid's); "
                                         "on several classes set method.map_terms.class_own.weight=0, which is on by default");
  s.rectangle = shape.rectangle;
  s.quick = quick;
  class_end_kinds(s);  // each kind refuses here a block it cannot run
  if (shape.rectangle) {  // windows: only the terms that know them (optim/terms/point_term.hpp, map_term.hpp)
    check_point_terms_in_windows(o.terms);
    check_map_terms_in_windows(o.map_terms);
  }
  if (!shape.rectangle) {
    s.out_res = s.out_rows = s.upscale * s.res;
    s.out_scale = s.upscale;
    for (int r : s.sigma_res) s.sigma_out_res.push_back(s.upscale * r);
    s.sigma_out_rows = s.sigma_out_res;
  } else {
    lay_out_windows(s, o, shape.canvas(), quick, full_res, full_num_sigmas);
  }
  check_iteration_memory(s, shape.rectangle);
  s.class_order = class_order(o.class_order, K);
  return s;
}

}  // namespace ppsynth
