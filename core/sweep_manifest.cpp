#include "core/sweep_manifest.hpp"

#include <set>

#include "core/content_hash.hpp"
#include "core/error.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"

namespace ppsynth {

namespace {

const char* kKind = "ppsynth-sweep";
const int kVersion = 1;

bool is_hex_id(const nlohmann::json& v) {
  if (!v.is_string() || v.get_ref<const std::string&>().size() != 12) return false;
  for (char c : v.get_ref<const std::string&>())
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

}  // namespace

void check_sweep_resource(const std::string& key, long long v) {
  const long long max = key.find("cpus") != std::string::npos     ? kMaxSweepCpus
                        : key.find("memory") != std::string::npos ? kMaxSweepMemoryMb
                                                                  : kMaxSweepMinutes;
  if (v < 1 || v > max)
    throw InputError(key + " " + std::to_string(v) + ": expected 1 to " + std::to_string(max));
}

nlohmann::json sweep_manifest_json(const SweepManifest& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : m.rows)
    rows.push_back({{"id", r.id}, {"label", r.label}, {"group", r.group}, {"group_label", r.group_label},
                    {"source", r.source}, {"overrides", r.overrides}, {"seed", r.seed}, {"quick", r.quick},
                    {"dir", r.dir}, {"config", r.config}});
  return {{"kind", kKind},
          {"version", kVersion},
          {"name", m.name},
          {"spec_source", m.spec_source},
          {"spec", m.spec},
          {"resources", {{"cpus", m.resources.cpus}, {"memory_mb", m.resources.memory_mb}, {"time_minutes", m.resources.time_minutes}}},
          {"rows", rows}};
}

std::string sweep_manifest_hash(const SweepManifest& m) { return content_hash(sweep_manifest_json(m).dump()); }

SweepManifest parse_sweep_manifest(const nlohmann::json& j, const std::string& source) {
  auto refuse = [&](const std::string& key, const std::string& what) {
    return file_error(source, 0, "key '" + key + "': " + what);
  };
  auto need = [&](const nlohmann::json& o, const char* k, const std::string& key) -> const nlohmann::json& {
    if (!o.contains(k)) throw refuse(key, "missing");
    return o[k];
  };
  auto text = [&](const nlohmann::json& o, const char* k, const std::string& key) {
    const nlohmann::json& v = need(o, k, key);
    if (!v.is_string()) throw refuse(key, "expected a string");
    return v.get<std::string>();
  };
  if (!j.is_object() || j.value("kind", nlohmann::json()) != kKind)
    throw file_error(source, 0, "not a sweep manifest of ppsynth (no \"kind\": \"ppsynth-sweep\")");
  if (j.value("version", nlohmann::json()) != kVersion)
    throw refuse("version", "a manifest of another ppsynth version; plan the sweep again");
  SweepManifest m;
  m.name = text(j, "name", "name");
  if (!is_safe_name(m.name)) throw refuse("name", "expected a plain name (letters, digits, '_' or '-')");
  m.spec_source = text(j, "spec_source", "spec_source");
  m.spec = need(j, "spec", "spec");
  if (!m.spec.is_object()) throw refuse("spec", "expected an object");
  const nlohmann::json& res = need(j, "resources", "resources");
  if (!res.is_object()) throw refuse("resources", "expected an object");
  int* fields[] = {&m.resources.cpus, &m.resources.memory_mb, &m.resources.time_minutes};
  const char* names[] = {"cpus", "memory_mb", "time_minutes"};
  for (int i = 0; i < 3; ++i) {
    const std::string key = std::string("resources.") + names[i];
    const nlohmann::json& v = need(res, names[i], key);
    if (!v.is_number_integer()) throw refuse(key, "expected a whole number");
    try {
      check_sweep_resource(key, v.get<long long>());
    } catch (const InputError& e) {
      throw file_error(source, 0, e.what());
    }
    *fields[i] = v.get<int>();
  }
  const nlohmann::json& rows = need(j, "rows", "rows");
  if (!rows.is_array()) throw refuse("rows", "expected a list");
  std::set<std::string> ids;
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string key = "rows[" + std::to_string(i) + "]";
    const nlohmann::json& r = rows[i];
    if (!r.is_object()) throw refuse(key, "expected an object");
    SweepRow row;
    if (!is_hex_id(need(r, "id", key + ".id"))) throw refuse(key + ".id", "expected 12 hex digits");
    row.id = r["id"];
    if (!ids.insert(row.id).second) throw refuse(key + ".id", "the id " + row.id + " twice");
    if (!is_hex_id(need(r, "group", key + ".group"))) throw refuse(key + ".group", "expected 12 hex digits");
    row.group = r["group"];
    row.label = text(r, "label", key + ".label");
    row.group_label = text(r, "group_label", key + ".group_label");
    row.source = text(r, "source", key + ".source");
    const nlohmann::json& o = need(r, "overrides", key + ".overrides");
    if (!o.is_array()) throw refuse(key + ".overrides", "expected a list of strings");
    for (const auto& s : o) {
      if (!s.is_string()) throw refuse(key + ".overrides", "expected a list of strings");
      row.overrides.push_back(s);
    }
    if (!is_seed(need(r, "seed", key + ".seed"))) throw refuse(key + ".seed", "expected an integer in [0, 2^63)");
    row.seed = r["seed"].get<uint64_t>();
    if (!need(r, "quick", key + ".quick").is_boolean()) throw refuse(key + ".quick", "expected true or false");
    row.quick = r["quick"];
    row.dir = text(r, "dir", key + ".dir");
    if (row.dir != "runs/" + row.id) throw refuse(key + ".dir", "expected runs/" + row.id);
    row.config = need(r, "config", key + ".config");
    check_run_config(row.config, source + " " + key + ".config");
    if (row.config["seed"].get<uint64_t>() != row.seed) throw refuse(key + ".config.seed", "differs from the row's seed");
    m.rows.push_back(std::move(row));
  }
  return m;
}

}  // namespace ppsynth
