#include "experiments/reproduce/reproduce_numbers.hpp"

#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/run_json.hpp"
#include "optim/baselines/pcf2017/pcf2017_stats.hpp"
#include "optim/baselines/roveri2015/roveri2015_stats.hpp"
#include "optim/run/run_options_of.hpp"
#include "optim/run/run_store.hpp"

namespace ppsynth {

namespace {

using json = nlohmann::json;

// The metrics a rule may read (reproduce_rule.hpp): the rest of an evaluation (border bands,
// p-values, ...) stays in the runs' own metrics.json and the gather.
bool kept(const std::string& key) {
  static const std::set<std::string> names = {"pcf_mse", "wasserstein", "chamfer", "relative_radius", "min_distance_normalized",
                                              "close_pair_share", "l_sup", "overlap_pairs", "seconds", "cpu_seconds", "iterations"};
  const size_t slash = key.rfind('/');
  return slash != std::string::npos && names.count(key.substr(slash + 1));
}

// Overlapping disk pairs over all classes of the output or of the exemplar (evaluate()'s
// "overlap" block, present when the points have radii).
std::optional<double> overlap_pairs(const json& metrics, const char* which) {
  if (!metrics.is_object() || !metrics.contains("overlap") || !metrics["overlap"].contains(which)) return std::nullopt;
  const json& o = metrics["overlap"][which];
  if (!o.is_array() || o.empty() || !o[0].contains("pairs") || !o[0]["pairs"].is_number()) return std::nullopt;
  return o[0]["pairs"].get<double>();
}

void add_metrics(std::map<std::string, std::map<uint64_t, double>>& group, uint64_t seed, const json& metrics, const std::string& source) {
  for (auto& [key, v] : metric_values(metrics, source))
    if (kept(key)) group[key][seed] = v;
  if (auto o = overlap_pairs(metrics, "output")) group["all/overlap_pairs"][seed] = *o;
}

void add_exemplar(ItemNumbers& n, const std::string& panel, const json& metrics) {
  auto& e = n.exemplar[panel];
  if (metrics.contains("exemplar") && metrics["exemplar"].is_object() && metrics["exemplar"].contains("relative_radius") &&
      metrics["exemplar"]["relative_radius"].is_number())
    e["all/relative_radius"] = metrics["exemplar"]["relative_radius"].get<double>();
  if (auto o = overlap_pairs(metrics, "exemplar")) e["all/overlap_pairs"] = *o;
}

// The panel and column of a sweep run, from its group label (the planner labels a figure
// column "<figure>-<panel>-<column>", then a preset or grid in brackets after a space).
const PanelSpec* match(const ReproduceConfig& c, const std::string& label, std::string& column) {
  for (const PanelSpec& p : c.panels)
    for (const std::string& col : p.methods) {
      const std::string prefix = c.name + "-" + p.name + "-" + col;
      if (label == prefix || label.rfind(prefix + " ", 0) == 0) {
        column = col;
        return &p;
      }
    }
  return nullptr;
}

// Initializations are evaluated for their numbers only: no curves, tests or scorecard.
EvalOptions init_eval_options() {
  EvalOptions e;
  e.include_curves = false;
  e.second_order = false;
  e.verdict = false;
  e.scorecard = false;
  return e;
}

void from_sweep(const ReproduceConfig& c, const ReproduceResult& r, ItemNumbers& n) {
  for (const GatheredRun& run : r.seeds.runs) {
    if (run.stage != 0) continue;
    std::string column;
    const PanelSpec* p = match(c, run.group_label, column);
    if (!p) continue;
    const std::string group = p->name + "/" + column;
    for (auto& [key, v] : run.values)
      if (kept(key)) n.per_seed[group][key][run.seed] = v;
    const RunOutcome o = load_run(run.dir);
    if (auto ov = overlap_pairs(o.metrics, "output")) n.per_seed[group]["all/overlap_pairs"][run.seed] = *ov;
    n.per_seed[group]["run/iterations"][run.seed] = total_iterations(o);
    if (const std::string v = read_run_record(run.dir + "/run.json").preset_variant; !v.empty()) n.made_under[group][run.seed] = v;
    if (!n.exemplar.count(p->name)) add_exemplar(n, p->name, o.metrics);
    if (column == "ours" && !o.initialization.empty())
      add_metrics(n.per_seed[p->name + "/init"], run.seed, evaluate(o.exemplar, o.initialization, init_eval_options()),
                  run.dir + "/init.txt");
  }
}

// A synthesized column's seed: its run's.
uint64_t column_seed(const ReproduceResult& r, const ColumnResult& col) {
  return run_options_of(col.config, r.dir + "/" + col.run_dir + "/config.json").seed;
}

void from_panels(const ReproduceResult& r, ItemNumbers& n) {
  for (const PanelResult& pr : r.panels) {
    uint64_t ours_seed = 0;  // the initialization's: the one "ours" started from
    for (const ColumnResult& col : pr.columns)
      if (col.column == "ours" && !col.run_dir.empty()) ours_seed = column_seed(r, col);
    for (const ColumnResult& col : pr.columns) {
      if (col.status != "ok" || col.column == "reference") continue;
      const uint64_t seed = col.column == "init" ? ours_seed : column_seed(r, col);
      auto& group = n.per_seed[pr.name + "/" + col.column];
      add_metrics(group, seed, col.metrics, pr.name + "/" + col.column);
      if (!col.run_dir.empty()) {
        group["run/seconds"][seed] = col.seconds;
        if (col.cpu_seconds > 0) group["run/cpu_seconds"][seed] = col.cpu_seconds;  // 0: not recorded
        group["run/iterations"][seed] = col.iterations;
        if (!col.preset_variant.empty()) n.made_under[pr.name + "/" + col.column][seed] = col.preset_variant;
      }
    }
  }
}

// Published outputs: the panel's reference column when it has one, else its file evaluated here.
void add_references(const ReproduceConfig& c, const ReproduceResult& r, ItemNumbers& n) {
  for (const PanelResult& pr : r.panels) {
    const PanelSpec* spec = nullptr;
    for (const PanelSpec& p : c.panels)
      if (p.name == pr.name) spec = &p;
    if (!spec || spec->kind != "synthesis") continue;
    for (const ColumnResult& col : pr.columns)
      if (col.status == "ok" && !n.exemplar.count(pr.name)) add_exemplar(n, pr.name, col.metrics);
    if (spec->reference.empty()) continue;
    json metrics;
    for (const ColumnResult& col : pr.columns)
      if (col.column == "reference" && col.status == "ok") metrics = col.metrics;
    if (metrics.is_null()) metrics = evaluate(pr.exemplar, read_points(spec->reference), init_eval_options());
    std::map<std::string, std::map<uint64_t, double>> one;
    add_metrics(one, 0, metrics, spec->reference);
    for (auto& [key, by_seed] : one) n.fixed[pr.name + "/reference"][key] = by_seed.at(0);
  }
}

}  // namespace

int total_iterations(const RunOutcome& run) {
  int n = 0;
  for (const StageRecord& s : run.stages) n += s.iterations;
  const std::string method = run_options_of(run.config, run.dir + "/config.json").method_type;
  try {
    if (method == "pcf2017") {
      const pcf2017::Pcf2017Stats s = pcf2017::pcf2017_stats_from_json(run.stats);
      if (s.descent) n += s.descent->iterations;
      for (const pcf2017::Pcf2017Class& c : s.classes)
        if (c.descent) n += c.descent->iterations;
    } else if (method == "roveri2015") {
      for (const roveri2015::ScaleReport& r : roveri2015::roveri2015_stats_from_json(run.stats).scales) n += r.merge_iterations;
    }
  } catch (const std::invalid_argument& e) {
    throw InputError(run.dir + "/run.json: method_stats: " + e.what());
  }
  return n;
}

ItemNumbers collect_item_numbers(const ReproduceConfig& c, const ReproduceResult& r) {
  ItemNumbers n;
  if (!r.sweep_dir.empty()) from_sweep(c, r, n);
  else from_panels(r, n);
  add_references(c, r, n);
  return n;
}

}  // namespace ppsynth
