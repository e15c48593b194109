#include "optim/sweep/sweep_plan.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/paths.hpp"
#include "core/run_directory.hpp"
#include "optim/reproduce/reproduce_config.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_store.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

const char* kManifest = "manifest.json";
const char* kKind = "ppsynth-sweep";

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

// The run configs a spec names: each run config, and each synthesised column of each panel of
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
                                    " synthesises from a generated exemplar; sweep its run config instead");
      for (const std::string& column : p.methods) {
        if (column == "init" || column == "reference" || !method_available(column)) continue;
        out.push_back({fig.source, fig.name + "-" + p.name + "-" + column, column_run_config(fig, p, column, common), true});
      }
    }
  }
  return out;
}

}  // namespace

std::string json_id(const nlohmann::json& value) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64: stable across platforms and builds
  for (unsigned char c : value.dump()) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return std::string(buf, 12);
}

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
  if (m.resources.cpus < 1 || m.resources.memory_mb < 1 || m.resources.time_minutes < 1)
    throw config_error("resources", "cpus, memory_mb and time_minutes must be >= 1");
  const auto seeds = parse_number_list(spec["seeds"].is_null() ? nlohmann::json(95) : spec["seeds"], "seeds", "seed");
  const bool quick = spec["quick"].get<bool>();
  std::vector<std::string> common;
  for (const auto& s : spec["set"]) {
    if (!s.is_string()) throw config_error("set", "expected \"key.path=value\" strings");
    common.push_back(s);
  }
  const auto srcs = sources(spec, base_dir, common);
  if (srcs.empty()) throw config_error("runs", "the spec names no run config and no figure");
  std::set<std::string> ids;
  for (const Source& src : srcs)
    for (const auto& point : grid_points(spec["grid"])) {
      std::vector<std::string> overrides = common;
      overrides.insert(overrides.end(), point.begin(), point.end());
      nlohmann::json unseeded = resolve_run_config(src.config, src.has_common ? point : overrides);
      const nlohmann::json key_of_group = group_key(unseeded, quick);
      const std::string group = json_id(key_of_group);
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
  return m;
}

SweepManifest expand_sweep_spec(const std::string& spec_path) {
  return expand_sweep_spec(load_config(spec_path), spec_path, fs::path(spec_path).parent_path().string());
}

namespace {

nlohmann::json to_json(const SweepManifest& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : m.rows)
    rows.push_back({{"id", r.id}, {"label", r.label}, {"group", r.group}, {"group_label", r.group_label},
                    {"source", r.source}, {"overrides", r.overrides}, {"seed", r.seed}, {"quick", r.quick},
                    {"dir", r.dir}, {"config", r.config}});
  return {{"kind", kKind},
          {"version", 1},
          {"name", m.name},
          {"spec_source", m.spec_source},
          {"spec", m.spec},
          {"resources", {{"cpus", m.resources.cpus}, {"memory_mb", m.resources.memory_mb}, {"time_minutes", m.resources.time_minutes}}},
          {"rows", rows}};
}

// Holds an advisory lock on the sweep directory while the manifest is rewritten.
class DirLock {
 public:
  explicit DirLock(const std::string& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ < 0 || ::flock(fd_, LOCK_EX | LOCK_NB) != 0)
      throw InputError(dir + ": another ppsynth process is planning this sweep; wait for it");
  }
  ~DirLock() { ::close(fd_); }
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;

 private:
  int fd_;
};

}  // namespace

SweepManifest load_sweep(const std::string& dir) {
  const std::string path = (fs::path(dir) / kManifest).string();
  if (!fs::is_regular_file(path)) throw InputError(dir + ": not a sweep directory of ppsynth (no " + kManifest + "; plan it with `ppsynth sweep plan`)");
  const nlohmann::json j = read_run_json(path);
  if (j.value("kind", "") != kKind) throw file_error(path, 0, "not a sweep manifest of ppsynth");
  SweepManifest m;
  try {
    m.name = j.at("name");
    m.spec_source = j.at("spec_source");
    m.spec = j.at("spec");
    m.resources = {j.at("resources").at("cpus"), j.at("resources").at("memory_mb"), j.at("resources").at("time_minutes")};
    for (const auto& r : j.at("rows")) {
      SweepRow row;
      row.id = r.at("id");
      row.label = r.at("label");
      row.group = r.at("group");
      row.group_label = r.at("group_label");
      row.source = r.at("source");
      row.overrides = r.at("overrides").get<std::vector<std::string>>();
      row.seed = r.at("seed");
      row.quick = r.at("quick");
      row.dir = r.at("dir");
      row.config = r.at("config");
      if (!is_safe_name(row.id) || row.dir != "runs/" + row.id) throw file_error(path, 0, "row " + row.id + ": malformed id or dir");
      m.rows.push_back(std::move(row));
    }
  } catch (const nlohmann::json::exception& e) {
    throw file_error(path, 0, std::string("malformed manifest: ") + e.what());
  }
  return m;
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
  DirLock lock(dir);
  std::set<std::string> new_ids;
  for (const auto& r : manifest.rows) {
    new_ids.insert(r.id);
    (old_ids.count(r.id) ? s.kept : s.added)++;
  }
  for (const auto& id : old_ids) s.dropped += new_ids.count(id) ? 0 : 1;
  s.rows = manifest.rows.size();
  fs::create_directories(fs::path(dir) / "runs");
  fs::create_directories(fs::path(dir) / "logs");
  write_text_atomic((fs::path(dir) / kManifest).string(), to_json(manifest).dump(1) + "\n");
  return s;
}

}  // namespace ppsynth
