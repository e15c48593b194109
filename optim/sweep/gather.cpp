#include "optim/sweep/gather.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/metrics/summary_stats.hpp"
#include "core/output_shape.hpp"
#include "core/render/plot_strips.hpp"
#include "core/report/html_report.hpp"
#include "core/content_hash.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "optim/run/run_store.hpp"
#include "optim/sweep/sweep_plan.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

struct Found {
  std::string dir, group, group_label;
  nlohmann::json key;     // what decides its group (run_store's group_key)
  bool finished = true;   // false: only its snapshots count (GatherOptions::stages)
};

// How gather evaluates an output itself (a reference; every run with --protocol): the
// evaluation's defaults, the protocol if one is asked for, no curves.
EvalOptions eval_options(const GatherOptions& g) {
  EvalOptions e;
  e.include_curves = false;
  if (g.protocol) e.protocol = *g.protocol;
  return e;
}

// The output shape a run's config made.
OutputShape run_output_shape(const json& config, const PointSet& exemplar) {
  json c = config;
  c["output"] = merge(output_defaults(), c.value("output", json::object()));
  return resolve_output_shape(c, exemplar);
}

// A run's output evaluated at the scale it was made at (its config's output shape), as the
// run's own metrics.json was: crops are exemplar-sized at that scale whatever its density.
EvalOptions eval_options(const GatherOptions& g, const json& config, const PointSet& exemplar) {
  EvalOptions e = eval_options(g);
  e.zoom = run_output_shape(config, exemplar).zoom();
  return e;
}

std::string evaluation_text(const GatherOptions& g) {
  return g.protocol ? std::string("every output evaluated again, protocol ") + patch_protocol_name(*g.protocol)
                    : std::string("each run's metrics.json");
}

// What a run recorded of itself (seed, quick, processor): its run.json once it has finished,
// else its directory's marker (written when it started; run_dir_marker checks its types).
RunRecord recorded(const std::string& dir, const nlohmann::json& config) {
  if (fs::exists(dir + "/run.json")) return read_run_record(dir + "/run.json");
  const nlohmann::json m = run_dir_marker(dir);
  RunRecord r;
  r.seed = config["seed"].get<uint64_t>();
  if (m.is_object()) {
    r.quick = m.value("quick", false);
    r.processor = m.value("processor", std::string());
  }
  return r;
}

// What decides a run's group (run_store's group_key, as a sweep's plan computes it).
nlohmann::json run_group_key(const std::string& dir, const nlohmann::json& config) {
  return group_key(config, recorded(dir, config).quick);
}

// The group of a run directory made outside a sweep.
Found loose_run(const std::string& dir, bool finished) {
  const nlohmann::json config = read_run_config(dir + "/config.json");
  const nlohmann::json key = run_group_key(dir, config);
  return {dir, json_id(key), run_name(config) + " (" + config["method"]["type"].get<std::string>() + ")", key, finished};
}

// Groups of one label but other settings (runs made outside a sweep with `--set upscale=3`;
// two sweeps of one run config with other `set`s) would be columns no reader and no
// --baseline could tell apart: each such label gets the keys in which its groups differ, as a
// sweep's grid labels them ("lines (gabor) [upscale=3]").
void label_by_differences(std::vector<Found>& found) {
  std::map<std::string, std::map<std::string, nlohmann::json>> groups;  // label -> group -> flattened key
  for (const Found& f : found) groups[f.group_label].emplace(f.group, f.key.flatten());
  std::map<std::string, std::string> suffix;  // group -> " [k=v, ...]"
  for (const auto& [label, by_group] : groups) {
    if (by_group.size() < 2) continue;
    std::set<std::string> paths;
    for (const auto& [g, flat] : by_group)
      for (auto it = flat.begin(); it != flat.end(); ++it) paths.insert(it.key());
    for (const auto& [g, flat] : by_group) {
      // The keys it sets that differ; the ones it leaves unset only where it sets none.
      std::string set, unset;
      for (const auto& path : paths) {
        const nlohmann::json mine = flat.contains(path) ? flat[path] : nlohmann::json();
        const bool differs = std::any_of(by_group.begin(), by_group.end(), [&](const auto& other) {
          return (other.second.contains(path) ? other.second[path] : nlohmann::json()) != mine;
        });
        if (!differs) continue;
        std::string dotted = path.substr(1);
        std::replace(dotted.begin(), dotted.end(), '/', '.');
        std::string& text = mine.is_null() ? unset : set;
        text += (text.empty() ? "" : ", ") + dotted +
                (mine.is_null() ? " unset" : "=" + (mine.is_string() ? mine.get<std::string>() : mine.dump()));
      }
      suffix[g] = set.empty() ? unset : set;
    }
  }
  // Into the bracket a sweep's grid label already has ("lines [a=1, b unset]"), else a new one.
  for (Found& f : found)
    if (const auto it = suffix.find(f.group); it != suffix.end()) {
      std::string& label = f.group_label;
      if (!label.empty() && label.back() == ']') label.insert(label.size() - 1, ", " + it->second);
      else label += " [" + it->second + "]";
    }
}

// Finished runs, and unfinished ones that have begun (their snapshots count for --stage).
void discover(const std::string& dir, std::vector<Found>& found, std::vector<std::string>& unfinished, int depth) {
  if (fs::is_regular_file(fs::path(dir) / "manifest.json")) {
    for (const auto& row : load_sweep(dir).rows) {
      const std::string d = (fs::path(dir) / row.dir).string();
      const RunDirState state = run_dir_state(d);
      if (state != RunDirState::Complete) unfinished.push_back(d);
      if (state == RunDirState::Complete || (state == RunDirState::Unfinished && fs::exists(d + "/config.json")))
        found.push_back({d, row.group, row.group_label, run_group_key(d, read_run_config(d + "/config.json")),
                         state == RunDirState::Complete});
    }
    return;
  }
  switch (run_dir_state(dir)) {
    case RunDirState::Complete:
      if (run_dir_marker(dir).value("kind", "run") == "run") found.push_back(loose_run(dir, true));
      return;
    case RunDirState::Unfinished:
      unfinished.push_back(dir);
      if (run_dir_marker(dir).value("kind", "run") == "run" && fs::exists(dir + "/config.json"))
        found.push_back(loose_run(dir, false));
      return;
    default:
      break;
  }
  if (depth > 0 || !fs::is_directory(dir)) return;
  std::vector<std::string> subdirs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory()) subdirs.push_back(e.path().string());
  std::sort(subdirs.begin(), subdirs.end());
  for (const auto& d : subdirs) discover(d, found, unfinished, depth + 1);
}

std::pair<std::string, std::string> split_key(const std::string& key) {
  const size_t slash = key.rfind('/');
  return {key.substr(0, slash), key.substr(slash + 1)};
}

// Ratio of the medians of `a` and `b` and its 5 % and 95 % bootstrap quantiles.
BaselineComparison compare_medians(const std::vector<double>& a, const std::vector<double>& b) {
  BaselineComparison c;
  c.n = a.size(), c.n_baseline = b.size();
  const double mb = summarize(b).median;
  c.ratio = mb != 0 ? summarize(a).median / mb : std::nan("");
  std::mt19937_64 rng(20261125);
  std::vector<double> ratios, ra(a.size()), rb(b.size());
  for (int draw = 0; draw < 2000; ++draw) {
    for (auto& x : ra) x = a[std::uniform_int_distribution<size_t>(0, a.size() - 1)(rng)];
    for (auto& x : rb) x = b[std::uniform_int_distribution<size_t>(0, b.size() - 1)(rng)];
    const double den = summarize(rb).median;
    if (den != 0) ratios.push_back(summarize(ra).median / den);
  }
  c.lo = quantile(ratios, 0.05), c.hi = quantile(ratios, 0.95);
  return c;
}

// Seeds that occur exactly once among `seeds` (a seed gathered twice from loose copies has no
// one value to pair), with their values.
std::map<uint64_t, double> single_seed_values(const MetricSummary& s) {
  std::map<uint64_t, double> once;
  std::set<uint64_t> repeated;
  for (size_t i = 0; i < s.seeds.size(); ++i)
    if (!once.emplace(s.seeds[i], s.values[i]).second) repeated.insert(s.seeds[i]);
  for (uint64_t seed : repeated) once.erase(seed);
  return once;
}

// The per-seed ratios of the seeds both ran, their median and its bootstrap interval
// (BaselineComparison).
void compare_paired(const MetricSummary& s, const MetricSummary& base, BaselineComparison& c) {
  const std::map<uint64_t, double> mine = single_seed_values(s), theirs = single_seed_values(base);
  for (const auto& [seed, value] : mine) {
    const auto b = theirs.find(seed);
    if (b == theirs.end() || !std::isfinite(b->second) || b->second == 0 || !std::isfinite(value)) continue;
    c.paired_seeds.push_back(seed);
    c.paired_ratios.push_back(value / b->second);
  }
  c.paired = c.paired_lo = c.paired_hi = std::nan("");
  if (c.paired_ratios.empty()) return;
  c.paired = summarize(c.paired_ratios).median;
  std::mt19937_64 rng(20261126);
  std::vector<double> medians, draw(c.paired_ratios.size());
  for (int k = 0; k < 2000; ++k) {
    for (auto& x : draw) x = c.paired_ratios[std::uniform_int_distribution<size_t>(0, draw.size() - 1)(rng)];
    medians.push_back(summarize(draw).median);
  }
  c.paired_lo = quantile(medians, 0.05), c.paired_hi = quantile(medians, 0.95);
}

// One note per group whose runs name more than one processor.
std::vector<std::string> processor_notes(const std::vector<GatheredRun>& runs) {
  std::map<std::string, std::map<std::string, std::vector<uint64_t>>> seeds;  // group label -> processor -> seeds
  for (const auto& run : runs) seeds[run.group_label][run.processor.empty() ? "not recorded" : run.processor].push_back(run.seed);
  std::vector<std::string> notes;
  for (const auto& [label, by_processor] : seeds) {
    if (by_processor.size() < 2) continue;
    std::string text = label + ": its seeds ran on " + std::to_string(by_processor.size()) + " kinds of processor (";
    bool first = true;
    for (const auto& [processor, list] : by_processor) {
      text += std::string(first ? "" : "; ") + processor + ": seed" + (list.size() > 1 ? "s" : "");
      for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : " ") + std::to_string(list[i]);
      first = false;
    }
    notes.push_back(text + "): their seconds do not compare, and a seed run on another kind is another trajectory");
  }
  return notes;
}

// Every run's points after `stage` (GatherOptions::stages) as runs of the group "<label> @
// stage N"; finished runs without that snapshot are listed as left out.
void gather_stage(const std::vector<Found>& found, int stage, const GatherOptions& options, GatherResult& r) {
  char name[32];
  std::snprintf(name, sizeof name, "stage%02d.txt", stage);
  const std::string what = "--stage " + std::to_string(stage);
  if (stage < 1) throw InputError(what + ": expected a stage number >= 1 (as the runs' snapshots/stageNN.txt count them)");
  std::set<std::string> seen;
  size_t gathered = 0;
  for (const Found& f : found) {
    if (!seen.insert(fs::weakly_canonical(f.dir).string()).second) continue;  // named twice
    const std::string file = f.dir + "/snapshots/" + name;
    if (!fs::exists(file)) {
      if (f.finished) r.unfinished.push_back(f.dir + " (" + what + ": no snapshots/" + name + ")");
      continue;  // an unfinished run is listed as such already
    }
    const json config = read_run_config(f.dir + "/config.json");
    const PointSet exemplar = run_exemplar(f.dir, config);
    const PointSet points = read_points(file);
    const Domain want = run_output_shape(config, exemplar).domain(), got = points.domain();
    if (got.x0 != want.x0 || got.y0 != want.y0 || got.x1 != want.x1 || got.y1 != want.y1) {
      char text[256];
      std::snprintf(text, sizeof text, ": covers [%g, %g] x [%g, %g], not the output's [%g, %g] x [%g, %g]", got.x0, got.x1, got.y0,
                    got.y1, want.x0, want.x1, want.y0, want.y1);
      throw InputError(file + text + " (one window of a large output, or a padded canvas): " + what + " gathers whole outputs only");
    }
    const std::string n = std::to_string(stage);
    GatheredRun run{f.dir, f.group + "@stage" + n, f.group_label + " @ stage " + n, 0, {}, {}, stage};
    run.values = metric_values(evaluate(exemplar, points, eval_options(options, config, exemplar)), file);
    const RunRecord info = recorded(f.dir, config);
    run.seed = info.seed;
    run.processor = info.processor;
    r.runs.push_back(std::move(run));
    ++gathered;
  }
  if (gathered == 0) throw InputError(what + ": no gathered run has passed that stage (none has snapshots/" + std::string(name) + ")");
}

}  // namespace

ReferenceOutput parse_reference(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos) return {"", text};
  if (eq == 0 || eq + 1 == text.size())
    throw InputError("--reference '" + text + "': expected FILE or EXEMPLAR=FILE");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

GatherResult gather_runs(const std::vector<std::string>& dirs, const GatherOptions& options) {
  if (dirs.empty()) throw InputError("gather: name at least one sweep or run directory");
  if (!(options.bound > 0)) throw InputError("--bound: expected a number > 0");
  GatherResult r;
  r.options = options;
  r.inputs = dirs;
  std::vector<Found> found;
  for (const auto& d : dirs) {
    if (!fs::is_directory(d)) throw InputError(d + ": not a directory");
    discover(d, found, r.unfinished, 0);
  }
  label_by_differences(found);
  std::set<std::string> seen;
  for (const Found& f : found) {
    if (!f.finished) continue;
    const std::string canonical = fs::weakly_canonical(f.dir).string();
    if (!seen.insert(canonical).second) continue;  // named twice
    GatheredRun run{f.dir, f.group, f.group_label, 0, {}, {}};
    if (options.protocol) {  // measured again, the same way for every run
      const RunOutcome o = load_run(f.dir);
      run.values = metric_values(evaluate(o.exemplar, o.output, eval_options(options, o.config, o.exemplar)), f.dir);
    } else if (const std::string metrics = f.dir + "/metrics.json"; fs::exists(metrics)) {
      run.values = metric_values(read_run_json(metrics), metrics);
    } else {
      r.unfinished.push_back(f.dir + " (no metrics.json: evaluate was off; --protocol measures it)");
      continue;
    }
    const RunRecord info = read_run_record(f.dir + "/run.json");
    run.seed = info.seed;
    run.processor = info.processor;
    run.values.push_back({"run/seconds", info.total_seconds});
    r.runs.push_back(std::move(run));
  }
  for (const int stage : options.stages) gather_stage(found, stage, options, r);
  // By label, a group's stages after it in their order ("@ stage 2" before "@ stage 10").
  auto base_label = [](const GatheredRun& x) { return x.stage ? x.group_label.substr(0, x.group_label.rfind(" @ stage ")) : x.group_label; };
  std::sort(r.runs.begin(), r.runs.end(), [&](const GatheredRun& a, const GatheredRun& b) {
    const std::string la = base_label(a), lb = base_label(b);
    return std::tie(la, a.stage, a.group, a.seed, a.dir) < std::tie(lb, b.stage, b.group, b.seed, b.dir);
  });
  r.notes = processor_notes(r.runs);
  // group -> key -> summary, keys in first-seen order
  std::map<std::string, std::vector<MetricSummary>> by_group;
  std::vector<std::string> group_order;
  for (const auto& run : r.runs) {
    auto& list = by_group[run.group];
    if (list.empty()) group_order.push_back(run.group);
    for (const auto& [key, value] : run.values) {
      const auto [scope, metric] = split_key(key);
      auto it = std::find_if(list.begin(), list.end(), [&](const MetricSummary& s) { return s.scope == scope && s.metric == metric; });
      if (it == list.end()) {
        MetricSummary fresh;
        fresh.group = run.group, fresh.group_label = run.group_label, fresh.scope = scope, fresh.metric = metric;
        list.push_back(std::move(fresh));
        it = std::prev(list.end());
      }
      it->values.push_back(value);
      it->seeds.push_back(run.seed);
    }
  }
  // Each group's exemplar (the stem of its file) and the reference that belongs to it.
  std::map<std::string, std::string> exemplar_of;
  std::set<std::string> exemplars;
  for (const auto& g : group_order) {
    const auto first = std::find_if(r.runs.begin(), r.runs.end(), [&](const GatheredRun& x) { return x.group == g; });
    exemplar_of[g] = fs::path(read_run_config(first->dir + "/config.json")["exemplar"].get<std::string>()).stem().string();
    exemplars.insert(exemplar_of[g]);
  }
  std::map<std::string, std::string> reference_file;  // exemplar stem -> file
  for (const auto& ref : options.references) {
    std::string stem = ref.exemplar;
    if (stem.empty()) {
      if (exemplars.size() != 1) {
        std::string names;
        for (const auto& e : exemplars) names += (names.empty() ? "" : ", ") + e;
        throw InputError("--reference " + ref.file + ": the runs come from " + std::to_string(exemplars.size()) +
                         " exemplars (" + names + "); name the one it belongs to: --reference EXEMPLAR=" + ref.file);
      }
      stem = *exemplars.begin();
    } else if (!exemplars.count(stem)) {
      std::string names;
      for (const auto& e : exemplars) names += (names.empty() ? "" : ", ") + e;
      throw InputError("--reference " + stem + "=" + ref.file + ": no gathered run comes from an exemplar named '" + stem +
                       "' (they come from: " + names + ")");
    }
    if (!reference_file.emplace(stem, ref.file).second)
      throw InputError("--reference: two references for the exemplar '" + stem + "'");
  }
  for (const auto& g : group_order) {
    std::map<std::string, double> ref;
    if (const auto file = reference_file.find(exemplar_of[g]); file != reference_file.end()) {
      const auto first = std::find_if(r.runs.begin(), r.runs.end(), [&](const GatheredRun& x) { return x.group == g; });
      const PointSet exemplar = load_run(first->dir).exemplar;
      for (const auto& [k, v] : metric_values(evaluate(exemplar, read_points(file->second), eval_options(options)), file->second))
        ref[k] = v;
    }
    for (auto& s : by_group[g]) {
      const Summary sum = summarize(s.values);
      s.median = sum.median, s.q1 = sum.q1, s.q3 = sum.q3, s.min = sum.min, s.max = sum.max;
      const auto it = ref.find(s.scope + "/" + s.metric);
      if (it != ref.end()) {
        s.reference = it->second;
        if (it->second != 0) s.ratio = s.median / it->second;
        const auto within = std::count_if(s.values.begin(), s.values.end(), [&](double v) { return v <= options.bound * it->second; });
        s.within = static_cast<double>(within) / static_cast<double>(s.values.size());
      }
      r.summaries.push_back(s);
    }
  }
  for (const auto& label : options.baselines) {
    std::vector<std::string> matches;
    for (const auto& g : group_order)
      if (by_group[g].front().group_label == label) matches.push_back(g);
    if (matches.size() != 1) {
      std::string labels;
      for (const auto& g : group_order) labels += (labels.empty() ? "" : "; ") + by_group[g].front().group_label;
      throw InputError("--baseline '" + label + "': " + (matches.empty() ? "no group" : "several groups") +
                       " of that label (groups: " + labels + ")");
    }
    const std::string& base = matches.front();
    for (const auto& g : group_order) {
      if (exemplar_of[g] != exemplar_of[base]) continue;
      for (const auto& s : by_group[g]) {
        const auto b = std::find_if(by_group[base].begin(), by_group[base].end(),
                                    [&](const MetricSummary& x) { return x.scope == s.scope && x.metric == s.metric; });
        if (b == by_group[base].end()) continue;
        BaselineComparison c = compare_medians(s.values, b->values);
        compare_paired(s, *b, c);
        c.group_label = s.group_label, c.baseline_label = label, c.scope = s.scope, c.metric = s.metric;
        r.comparisons.push_back(c);
      }
    }
  }
  return r;
}

namespace {

std::string num(double v, const char* fmt = "%.6g") {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}
std::string opt(const std::optional<double>& v, const char* fmt = "%.6g") { return v ? num(*v, fmt) : ""; }

// "FILE" or "a=FILE, b=FILE" for the reports.
std::string references_text(const GatherOptions& o) {
  std::string s;
  for (size_t i = 0; i < o.references.size(); ++i)
    s += (i ? ", " : "") + (o.references[i].exemplar.empty() ? "" : o.references[i].exemplar + "=") + o.references[i].file;
  return s;
}

std::vector<std::string> summary_header() {
  return {"group", "scope", "metric", "n", "median", "q1", "q3", "min", "max", "reference", "median / reference", "share within bound"};
}

std::vector<std::vector<std::string>> summary_rows(const GatherResult& r) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : r.summaries)
    rows.push_back({s.group_label, s.scope, s.metric, std::to_string(s.values.size()), num(s.median), num(s.q1), num(s.q3),
                    num(s.min), num(s.max), opt(s.reference), opt(s.ratio, "%.3f"), opt(s.within, "%.2f")});
  return rows;
}

// One row per run, one column per "<scope>/<metric>" (in first-seen order).
std::pair<std::vector<std::string>, std::vector<std::vector<std::string>>> per_seed_table(const GatherResult& r) {
  std::vector<std::string> keys;
  for (const auto& run : r.runs)
    for (const auto& [k, v] : run.values)
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::vector<std::string> header = {"group", "seed", "run directory"};
  header.insert(header.end(), keys.begin(), keys.end());
  std::vector<std::vector<std::string>> rows;
  for (const auto& run : r.runs) {
    std::vector<std::string> row = {run.group_label, std::to_string(run.seed), run.dir};
    for (const auto& k : keys) {
      const auto it = std::find_if(run.values.begin(), run.values.end(), [&](const auto& kv) { return kv.first == k; });
      row.push_back(it == run.values.end() ? "" : num(it->second));
    }
    rows.push_back(row);
  }
  return {header, rows};
}

std::vector<std::string> comparison_header() {
  return {"group", "baseline", "scope", "metric", "n", "n baseline", "median / baseline median", "90 % bootstrap interval",
          "seeds paired", "median of per-seed ratios", "its 90 % interval"};
}

std::vector<std::vector<std::string>> comparison_rows(const GatherResult& r) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : r.comparisons)
    rows.push_back({c.group_label, c.baseline_label, c.scope, c.metric, std::to_string(c.n), std::to_string(c.n_baseline),
                    num(c.ratio, "%.3f"), num(c.lo, "%.2f") + "-" + num(c.hi, "%.2f"), std::to_string(c.paired_seeds.size()),
                    num(c.paired, "%.3f"), c.paired_seeds.empty() ? "-" : num(c.paired_lo, "%.2f") + "-" + num(c.paired_hi, "%.2f")});
  return rows;
}

nlohmann::json to_json(const GatherResult& r) {
  nlohmann::json runs = nlohmann::json::array(), sums = nlohmann::json::array();
  for (const auto& run : r.runs) {
    nlohmann::json v = nlohmann::json::object();
    for (const auto& [k, x] : run.values) v[k] = x;
    runs.push_back({{"dir", run.dir}, {"group", run.group}, {"group_label", run.group_label}, {"seed", run.seed},
                    {"stage", run.stage}, {"values", v}});
  }
  auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  for (const auto& s : r.summaries)
    sums.push_back({{"group", s.group}, {"group_label", s.group_label}, {"scope", s.scope}, {"metric", s.metric},
                    {"n", s.values.size()}, {"values", s.values}, {"seeds", s.seeds}, {"median", s.median}, {"q1", s.q1},
                    {"q3", s.q3}, {"min", s.min}, {"max", s.max}, {"reference", optional(s.reference)},
                    {"ratio_of_medians", optional(s.ratio)}, {"share_within_bound", optional(s.within)}});
  nlohmann::json refs = nlohmann::json::array();
  for (const auto& ref : r.options.references) refs.push_back({{"exemplar", ref.exemplar}, {"file", ref.file}});
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : r.comparisons)
    comps.push_back({{"group_label", c.group_label}, {"baseline", c.baseline_label}, {"scope", c.scope}, {"metric", c.metric},
                     {"n", c.n}, {"n_baseline", c.n_baseline}, {"ratio_of_medians", c.ratio}, {"bootstrap_5", c.lo},
                     {"bootstrap_95", c.hi}, {"paired_seeds", c.paired_seeds}, {"paired_ratios", c.paired_ratios},
                     {"paired_median", c.paired}, {"paired_bootstrap_5", c.paired_lo},
                     {"paired_bootstrap_95", c.paired_hi}});
  return {{"references", refs}, {"bound", r.options.bound}, {"runs", runs}, {"summaries", sums},
          {"evaluation", r.options.protocol ? std::string(patch_protocol_name(*r.options.protocol)) : std::string("metrics.json")},
          {"baselines", r.options.baselines}, {"comparisons", comps}, {"left_out", r.unfinished}, {"notes", r.notes}};
}

// "12 finished runs" or "10 finished runs and 5 stage snapshots" (GatherOptions::stages).
std::string runs_text(const GatherResult& r) {
  const auto snapshots = std::count_if(r.runs.begin(), r.runs.end(), [](const GatheredRun& x) { return x.stage > 0; });
  const std::string finished = std::to_string(r.runs.size() - static_cast<size_t>(snapshots)) + " finished runs";
  return snapshots == 0 ? finished : finished + " and " + std::to_string(snapshots) + " stage snapshots";
}

// The notes (GatherResult::notes) as paragraphs above the Markdown's tables.
std::string notes_markdown(const std::vector<std::string>& notes) {
  std::string md;
  for (const auto& n : notes) md += "Note: " + n + ".\n\n";
  return md;
}

// A plot's file name: letters, digits, '_' and '-' kept, the rest '_'.
std::string file_stem(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return name;
}

// One strip plot per scope and metric, a column per group.
std::vector<std::pair<std::string, std::string>> write_plots(const GatherResult& r, const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> keys;  // scope, metric in first-seen order
  for (const auto& s : r.summaries)
    if (std::find(keys.begin(), keys.end(), std::make_pair(s.scope, s.metric)) == keys.end()) keys.push_back({s.scope, s.metric});
  std::vector<std::pair<std::string, std::string>> images;
  fs::create_directories(dir + "/plots");
  for (const auto& [scope, metric] : keys) {
    StripPlot plot;
    plot.title = scope + ": " + metric;
    plot.ylabel = metric;
    std::set<double> refs;
    size_t with_reference = 0;
    for (const auto& s : r.summaries)
      if (s.scope == scope && s.metric == metric) {
        plot.groups.push_back(StripGroup{s.group_label, s.values});
        if (s.reference) refs.insert(*s.reference), ++with_reference;
      }
    // One reference value that holds for every group of the plot: draw it and the bound (a
    // line across groups of other exemplars would compare them with a pattern they never had).
    if (refs.size() == 1 && with_reference == plot.groups.size()) {
      plot.reference = *refs.begin();
      plot.reference_label = "reference";
      plot.bound = r.options.bound * *refs.begin();
      plot.bound_label = num(r.options.bound, "%g") + " x reference";
    } else if (metric.rfind("border_density_", 0) == 0) {  // over uniform's by definition
      plot.reference = 1.0;
      plot.reference_label = "uniform points";
    }
    const std::string png = dir + "/plots/" + file_stem(scope + "_" + metric) + ".png";
    plot_strips(png, plot);
    images.push_back({png, plot.title});
  }
  return images;
}

// Per baseline, one strip plot per metric of all classes: each other group's per-seed ratios
// over the baseline (a dot per seed both ran), a line at 1.
std::vector<std::pair<std::string, std::string>> write_paired_plots(const GatherResult& r, const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> images;
  for (size_t b = 0; b < r.options.baselines.size(); ++b) {
    const std::string& baseline = r.options.baselines[b];
    std::vector<std::string> metrics;  // first-seen order
    for (const auto& c : r.comparisons)
      if (c.baseline_label == baseline && c.scope == "all" && std::find(metrics.begin(), metrics.end(), c.metric) == metrics.end())
        metrics.push_back(c.metric);
    for (const auto& metric : metrics) {
      StripPlot plot;
      plot.title = "all: " + metric + ", per seed over " + baseline;
      plot.ylabel = metric + " / the baseline's (same seed)";
      for (const auto& c : r.comparisons)
        if (c.baseline_label == baseline && c.scope == "all" && c.metric == metric && c.group_label != baseline &&
            !c.paired_ratios.empty())
          plot.groups.push_back(StripGroup{c.group_label, c.paired_ratios});
      if (plot.groups.empty()) continue;
      plot.reference = 1.0;
      plot.reference_label = "the baseline";
      const std::string png = dir + "/plots/paired_" + std::to_string(b + 1) + "_" + file_stem(metric) + ".png";
      plot_strips(png, plot);
      images.push_back({png, plot.title});
    }
  }
  return images;
}

}  // namespace

// Each group's label on a line of its own above its rows: labels carry a sweep's grid keys
// ("lemon_4c_v2 (preset fast) [method.border_relax.iterations=0]") and a column cut to a fixed
// width would print two groups that differ only at the end as one.
std::string format_gather(const GatherResult& r) {
  std::string s = "evaluation: " + evaluation_text(r.options) + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "  %-14s %-22s %3s %11s %11s %11s %9s %7s\n", "scope", "metric", "n", "median", "q1", "q3",
                "ref", "ratio");
  s += line;
  std::string group;
  for (const auto& m : r.summaries) {
    if (m.group != group) s += m.group_label + "\n", group = m.group;
    std::snprintf(line, sizeof line, "  %-14.14s %-22.22s %3zu %11s %11s %11s %9s %7s\n", m.scope.c_str(), m.metric.c_str(),
                  m.values.size(), num(m.median, "%.5g").c_str(), num(m.q1, "%.5g").c_str(), num(m.q3, "%.5g").c_str(),
                  opt(m.reference, "%.5g").c_str(), opt(m.ratio, "%.3f").c_str());
    s += line;
  }
  if (!r.comparisons.empty()) {
    std::snprintf(line, sizeof line, "\nagainst baselines: ratio of medians, and paired by seed\n  %-14s %-22s %3s %9s %13s %5s %9s %13s\n",
                  "scope", "metric", "n", "ratio", "90% interval", "pairs", "per-seed", "90% interval");
    s += line;
    std::string pair;
    for (const auto& c : r.comparisons) {
      const std::string heading = c.group_label + "\n  over " + c.baseline_label + "\n";
      if (heading != pair) s += heading, pair = heading;
      std::snprintf(line, sizeof line, "  %-14.14s %-22.22s %3zu %9s %13s %5zu %9s %13s\n", c.scope.c_str(), c.metric.c_str(), c.n,
                    num(c.ratio, "%.3f").c_str(), (num(c.lo, "%.2f") + "-" + num(c.hi, "%.2f")).c_str(), c.paired_seeds.size(),
                    num(c.paired, "%.3f").c_str(),
                    c.paired_seeds.empty() ? "-" : (num(c.paired_lo, "%.2f") + "-" + num(c.paired_hi, "%.2f")).c_str());
      s += line;
    }
  }
  if (!r.unfinished.empty()) s += std::to_string(r.unfinished.size()) + " run(s) left out (not finished)\n";
  for (const auto& n : r.notes) s += "note: " + n + "\n";
  return s;
}

void write_gather(const GatherResult& r, const std::string& out, bool force) {
  // Never into what it read: a gather's directory that holds, or lies inside, one of its inputs
  // would delete runs when replaced (--force) or be gathered by the next gather.
  const fs::path target = fs::weakly_canonical(fs::absolute(out));
  for (const auto& in : r.inputs) {
    const fs::path input = fs::weakly_canonical(fs::absolute(in));
    auto inside = [](const fs::path& a, const fs::path& b) {  // a is b or lies inside it
      auto ai = a.begin(), bi = b.begin();
      for (; bi != b.end(); ++ai, ++bi)
        if (ai == a.end() || *ai != *bi) return false;
      return true;
    };
    if (inside(target, input) || inside(input, target))
      throw InputError("-o " + out + ": " + (inside(target, input) ? "is, or lies inside, the input " : "holds the input ") + in +
                       "; a gather's tables go to a directory of their own. Nothing was changed.");
  }
  RunDirOptions o;
  o.kind = "gather";
  o.force = force;
  RunDirectory dir = RunDirectory::open(out, o);
  try {
    const std::string d = dir.path();
    write_table_csv(d + "/gather.csv", summary_header(), summary_rows(r));
    const auto [seed_header, seed_rows] = per_seed_table(r);
    write_table_csv(d + "/per_seed.csv", seed_header, seed_rows);
    std::string md = "# Gathered runs\n\n" + runs_text(r) +
                     (r.options.references.empty() ? "" : "; reference " + references_text(r.options) + ", bound " + num(r.options.bound, "%g") + " x") +
                     ".\n\n" + notes_markdown(r.notes) + table_markdown(summary_header(), summary_rows(r)) +
                     (r.comparisons.empty() ? std::string()
                                            : "\n## Against baselines\n\nRatio of medians and its 90 % bootstrap interval "
                                              "(seeds resampled); each baseline against itself shows the spread of chance. "
                                              "Paired: the median of the ratios of the seeds both ran (each seed's value over "
                                              "the baseline's of that seed) and its 90 % bootstrap interval (pairs resampled).\n\n" +
                                                  table_markdown(comparison_header(), comparison_rows(r))) +
                     "\n## Per seed\n\n" + table_markdown(seed_header, seed_rows);
    if (!r.comparisons.empty()) write_table_csv(d + "/baselines.csv", comparison_header(), comparison_rows(r));
    write_text_atomic(d + "/gather.md", md);
    write_text_atomic(d + "/gather.json", to_json(r).dump(1) + "\n");
    HtmlReport html("ppsynth gather: " + runs_text(r));
    html.add_paragraph("Every finished run, grouped by configuration with the seeds pooled: one dot per seed, the box from "
                       "the first to the third quartile with the median, whiskers to the extremes.");
    std::vector<std::pair<std::string, std::string>> kv = {{"runs", runs_text(r)},
                                                           {"left out (unfinished)", std::to_string(r.unfinished.size())},
                                                           {"evaluation", evaluation_text(r.options)}};
    if (!r.options.references.empty()) {
      kv.push_back({"reference", references_text(r.options)});
      kv.push_back({"bound", num(r.options.bound, "%g") + " x the reference's value"});
    }
    html.add_key_values(kv);
    for (const auto& n : r.notes) html.add_paragraph("Note: " + n + ".");
    html.add_image_row(write_plots(r, d));
    html.add_heading("Summary");
    html.add_table(summary_header(), summary_rows(r));
    if (!r.comparisons.empty()) {
      html.add_heading("Against baselines");
      html.add_paragraph("Ratio of each group's median to its baseline's, with a 90 % bootstrap interval (the seeds of both "
                         "groups resampled). The baseline against itself shows how far two medians of that many seeds part by chance. "
                         "Paired: each seed both groups ran gives one ratio (its value over the baseline's of the same seed); "
                         "their median and its 90 % bootstrap interval (the pairs resampled). A change that acts late in a run "
                         "shares the seed's trajectory up to it, so the pairs see it through less of the seeds' own luck.");
      html.add_table(comparison_header(), comparison_rows(r));
      if (const auto paired = write_paired_plots(r, d); !paired.empty()) {
        html.add_paragraph("Per seed: each dot is one seed's value over the baseline's value of the same seed.");
        html.add_image_row(paired);
      }
    }
    html.add_heading("Per seed");
    html.add_table(seed_header, seed_rows);
    html.write(d + "/index.html");
    dir.mark_complete({{"runs", r.runs.size()}});
  } catch (...) {
    dir.discard();
    throw;
  }
}

}  // namespace ppsynth
