#include "experiments/plan/sweep_plan.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/content_hash.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/paths.hpp"
#include "core/run_directory.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_store.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

const char* kManifest = "manifest.json";

nlohmann::json spec_defaults() {
  return {{"name", ""},
          {"description", ""},
          {"runs", nlohmann::json::array()},
          {"figures", nlohmann::json::array()},
          {"panels", nlohmann::json::array()},
          {"seeds", nullptr},  // a seed, a range "95-99" or a list of both; none given: 95
          {"grid", nlohmann::json::object({{"*", nullptr}})},
          {"set", nlohmann::json::array()},
          {"quick", false},
          {"resources", {{"cpus", 1}, {"memory_mb", 4096}, {"time_minutes", 240}}}};
}

// A config path of a spec: relative to the spec, else "shared:" or the source root.
std::string find_config(const std::string& path, const std::string& base_dir, const std::string& key) {
  if (path.rfind("shared:", 0) == 0) return resolve_data_path(path);
  for (const fs::path& p : {fs::path(base_dir) / path, fs::path(path), fs::path(source_root()) / path})
    if (fs::is_regular_file(p)) return p.lexically_normal().string();
  throw config_error(key, "'" + path + "': no such config (relative to " + (base_dir.empty() ? "." : base_dir) +
                              ", the current directory or " + source_root() + ")");
}

// Every combination of the grid's axes, as --set assignments (axes in key order).
std::vector<std::vector<std::string>> grid_points(const nlohmann::json& grid) {
  std::vector<std::vector<std::string>> points = {{}};
  for (auto it = grid.begin(); it != grid.end(); ++it) {
    if (!it.value().is_array() || it.value().empty())
      throw config_error("grid." + it.key(), "expected a non-empty list of values");
    std::vector<std::vector<std::string>> next;
    for (const auto& p : points)
      for (const auto& v : it.value()) {
        auto q = p;
        q.push_back(it.key() + "=" + (v.is_string() ? v.get<std::string>() : v.dump()));
        next.push_back(q);
      }
    points = next;
  }
  return points;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

struct Source {
  std::string file, label;
  nlohmann::json config;  // unresolved run config
  bool has_common = false;  // the spec's "set" is applied already (figure columns: method.* to "ours" only)
};

// The run configs a spec names: each run config, and each synthesized column of each panel of
// each figure config.
std::vector<Source> sources(const nlohmann::json& spec, const std::string& base_dir, const std::vector<std::string>& common) {
  std::vector<Source> out;
  for (size_t i = 0; i < spec["runs"].size(); ++i) {
    const std::string key = "runs[" + std::to_string(i) + "]";
    if (!spec["runs"][i].is_string()) throw config_error(key, "expected a config path");
    const std::string file = find_config(spec["runs"][i], base_dir, key);
    out.push_back({file, fs::path(file).stem().string(), load_config(file), false});
  }
  for (size_t i = 0; i < spec["figures"].size(); ++i) {
    const std::string key = "figures[" + std::to_string(i) + "]";
    if (!spec["figures"][i].is_string()) throw config_error(key, "expected a figure name (configs/paper) or path");
    const ReproduceConfig fig = load_reproduce_config(find_reproduce_config(spec["figures"][i]));
    const auto& only = spec["panels"];
    for (const PanelSpec& p : fig.panels) {
      if (p.kind != "synthesis") continue;
      if (!only.empty() && std::find(only.begin(), only.end(), p.name) == only.end()) continue;
      if (!p.generator.is_null())
        throw config_error(key, fig.name + " panel " + p.name +
                                    " synthesizes from a generated exemplar; sweep its run config instead");
      for (const std::string& column : p.methods) {
        if (column == "init" || column == "reference" || !method_available(column)) continue;
        out.push_back({fig.source, fig.name + "-" + p.name + "-" + column, column_run_config(fig, p, column, common), true});
      }
    }
  }
  return out;
}

}  // namespace

SweepManifest expand_sweep_spec(const nlohmann::json& user, const std::string& source, const std::string& base_dir) {
  nlohmann::json spec = apply_defaults(spec_defaults(), user, "");
  spec["grid"].erase("*");  // the open-object marker of the defaults, when no grid was given
  SweepManifest m;
  m.name = spec["name"];
  if (!is_safe_name(m.name)) throw config_error("name", "expected a plain name (letters, digits, '_' or '-')");
  m.spec_source = source;
  m.spec = spec;
  const auto& res = spec["resources"];
  m.resources.cpus = get_int(res, "cpus", "resources");
  m.resources.memory_mb = get_int(res, "memory_mb", "resources");
  m.resources.time_minutes = get_int(res, "time_minutes", "resources");
  for (const auto& [key, v] : {std::pair<const char*, int>{"resources.cpus", m.resources.cpus},
                               {"resources.memory_mb", m.resources.memory_mb},
                               {"resources.time_minutes", m.resources.time_minutes}})
    check_sweep_resource(key, v);
  const auto seeds =
      parse_number_list(spec["seeds"].is_null() ? nlohmann::json(95) : spec["seeds"], "seeds", "seed", kMaxSeed);
  const bool quick = spec["quick"].get<bool>();
  std::vector<std::string> common;
  for (const auto& s : spec["set"]) {
    if (!s.is_string()) throw config_error("set", "expected \"key.path=value\" strings");
    common.push_back(s);
  }
  const auto srcs = sources(spec, base_dir, common);
  if (srcs.empty()) throw config_error("runs", "the spec names no run config and no figure");
  std::set<std::string> ids;
  for (const Source& src : srcs) {
    std::map<std::string, std::vector<std::string>> point_of_group;  // this source's groups, by the grid point that made each
    for (const auto& point : grid_points(spec["grid"])) {
      std::vector<std::string> overrides = common;
      overrides.insert(overrides.end(), point.begin(), point.end());
      nlohmann::json unseeded = resolve_run_config(src.config, src.has_common ? point : overrides);
      const nlohmann::json key_of_group = group_key(unseeded, quick);
      const std::string group = json_id(key_of_group);
      if (const auto [it, fresh] = point_of_group.emplace(group, point); !fresh)
        throw config_error("grid", "'" + join(it->second, ", ") + "' and '" + join(point, ", ") + "' make the same runs of " +
                                       src.label + ": an axis over a key that does not change the synthesis (name, "
                                       "description, snapshots, evaluate, checkpoint_seconds, format) would give one run "
                                       "for several values; take it out of the grid");
      // The preset in the label: a preset's runs and the default's are told apart in gather
      // and its --baseline even when the preset comes from the spec's "set".
      const std::string preset = unseeded["preset"].is_string() ? " (preset " + unseeded["preset"].get<std::string>() + ")" : "";
      const std::string group_label = src.label + preset + (point.empty() ? "" : " [" + join(point, ", ") + "]");
      for (uint64_t seed : seeds) {
        SweepRow row;
        row.config = unseeded;
        row.config["seed"] = seed;
        nlohmann::json key = key_of_group;
        key["seed"] = seed;
        row.id = json_id(key);
        if (!ids.insert(row.id).second) continue;  // the same run named twice
        row.group = group;
        row.group_label = group_label;
        row.label = group_label + " seed " + std::to_string(seed);
        row.source = src.file;
        row.overrides = overrides;
        row.seed = seed;
        row.quick = quick;
        row.dir = "runs/" + row.id;
        m.rows.push_back(std::move(row));
      }
    }
  }
  return m;
}

SweepManifest expand_sweep_spec(const std::string& spec_path) {
  return expand_sweep_spec(load_config(spec_path), spec_path, fs::path(spec_path).parent_path().string());
}

SweepLock::SweepLock(const std::string& dir, const std::string& what)
    : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
  if (fd_ < 0) throw InputError(dir + ": cannot open the sweep directory to " + what + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw InputError(dir + ": another ppsynth process (a `sweep run` or `sweep plan`) is working on this sweep; cannot " + what +
                     " until it ends");
  }
}

SweepLock::~SweepLock() { ::close(fd_); }

SweepManifest load_sweep(const std::string& dir) {
  const std::string path = (fs::path(dir) / kManifest).string();
  if (!fs::is_regular_file(path)) throw InputError(dir + ": not a sweep directory of ppsynth (no " + kManifest + "; plan it with `ppsynth sweep plan`)");
  return parse_sweep_manifest(read_run_json(path), path);
}

PlanSummary plan_sweep(const SweepManifest& manifest, const std::string& dir_in) {
  const std::string dir = normalize_output_dir(dir_in, "-o");
  PlanSummary s;
  s.dir = dir;
  std::set<std::string> old_ids;
  const RunDirState state = run_dir_state(dir);
  if (state == RunDirState::Absent) {
    fs::create_directories(dir);
  } else if (fs::is_regular_file(fs::path(dir) / kManifest)) {
    for (const auto& r : load_sweep(dir).rows) old_ids.insert(r.id);
  } else if (state != RunDirState::Empty) {
    throw InputError(dir + ": exists and is not a sweep directory of ppsynth; name a new or empty directory. Nothing was changed.");
  }
  SweepLock lock(dir, "plan it again");
  if (!old_ids.empty())
    for (const auto& r : load_sweep(dir).rows)
      if (run_dir_locked((fs::path(dir) / r.dir).string()))
        throw InputError(dir + ": row " + r.id + " (" + r.label + ") is running; plan the sweep again once it has stopped. "
                         "Nothing was changed.");
  std::set<std::string> new_ids;
  for (const auto& r : manifest.rows) {
    new_ids.insert(r.id);
    (old_ids.count(r.id) ? s.kept : s.added)++;
  }
  for (const auto& id : old_ids) s.dropped += new_ids.count(id) ? 0 : 1;
  s.rows = manifest.rows.size();
  fs::create_directories(fs::path(dir) / "runs");
  fs::create_directories(fs::path(dir) / "logs");
  write_text_atomic((fs::path(dir) / kManifest).string(), sweep_manifest_json(manifest).dump(1) + "\n");
  return s;
}

}  // namespace ppsynth
