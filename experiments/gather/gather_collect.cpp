// gather, step 1: find the runs under the given directories, group and label them, and take
// each one's numbers (its metrics.json, or its output evaluated again with --protocol).
#include "experiments/gather/gather_steps.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "core/config/config.hpp"
#include "core/content_hash.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/output_shape.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "optim/run/run_options_of.hpp"
#include "optim/run/run_store.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

EvalOptions evaluation_options(const GatherOptions& g) {
  EvalOptions e;
  e.include_curves = false;
  if (g.protocol) e.protocol = *g.protocol;
  return e;
}

std::string evaluation_text(const GatherOptions& g) {
  return g.protocol ? std::string("every output evaluated again, protocol ") + patch_protocol_name(*g.protocol)
                    : std::string("each run's metrics.json");
}

namespace {

struct Found {
  std::string dir, group, group_label;
  nlohmann::json key;     // what decides its group (run_store's group_key)
  bool finished = true;   // false: only its snapshots count (GatherOptions::stages)
};

// The output shape a run's config made.
OutputShape run_output_shape(const json& config, const PointSet& exemplar) {
  json c = config;
  c["output"] = merge(output_defaults(), c.value("output", json::object()));
  return resolve_output_shape(c, exemplar);
}

// A run's output evaluated at the scale it was made at (its config's output shape), as the
// run's own metrics.json was: crops are exemplar-sized at that scale whatever its density.
EvalOptions eval_options(const GatherOptions& g, const json& config, const PointSet& exemplar) {
  EvalOptions e = evaluation_options(g);
  e.zoom = run_output_shape(config, exemplar).zoom();
  return e;
}

// What a run recorded of itself (seed, quick, processor): its run.json once it has finished,
// else its config's seed and its directory's marker (written when it started; run_dir_marker
// checks its types).
RunRecord recorded(const std::string& dir, const nlohmann::json& config) {
  if (fs::exists(dir + "/run.json")) return read_run_record(dir + "/run.json");
  const nlohmann::json m = run_dir_marker(dir);
  RunRecord r;
  r.seed = run_options_of(config, dir + "/config.json").seed;
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
  return {dir, json_id(key), run_name(config) + " (" + run_options_of(config, dir + "/config.json").method_type + ")", key, finished};
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

GatherResult collect_runs(const std::vector<std::string>& dirs, const GatherOptions& options) {
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
    if (info.cpu_seconds > 0) run.values.push_back({"run/cpu_seconds", info.cpu_seconds});  // 0: not recorded
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
  return r;
}

}  // namespace ppsynth
