#include "core/run_json.hpp"

#include <cmath>
#include <filesystem>

#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace ppsynth {

namespace {

InputError key_error(const std::string& source, const std::string& key, const std::string& what) {
  return file_error(source, 0, "key '" + key + "': " + what);
}

}  // namespace

bool is_seed(const nlohmann::json& v) {
  if (v.is_number_unsigned()) return v.get<uint64_t>() <= kMaxSeed;
  return v.is_number_integer() && v.get<int64_t>() >= 0;
}

nlohmann::json read_run_json(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw file_error(path, 0, "missing (not a finished run directory?)");
  return parse_json_text(read_file_text(path), path, false);
}

void check_run_config(const nlohmann::json& c, const std::string& source) {
  if (!c.is_object()) throw file_error(source, 0, "expected a JSON object (a resolved run config)");
  for (const char* k : {"name", "description", "exemplar", "format", "scaling"})
    if (c.contains(k) && !c[k].is_string()) throw key_error(source, k, "expected a string");
  for (const char* k : {"name", "exemplar"})
    if (!c.contains(k)) throw key_error(source, k, "missing (not a resolved run config)");
  if (!c.contains("method") || !c["method"].is_object() || !c["method"].contains("type") || !c["method"]["type"].is_string())
    throw key_error(source, "method", "expected an object with a string \"type\"");
  if (!c.contains("seed") || !is_seed(c["seed"]))
    throw key_error(source, "seed", "expected an integer in [0, 2^63)");
  if (c.contains("output") && !c["output"].is_object()) throw key_error(source, "output", "expected an object");
}

nlohmann::json read_run_config(const std::string& path) {
  nlohmann::json c = read_run_json(path);
  check_run_config(c, path);
  return c;
}

RunRecord parse_run_record(const nlohmann::json& j, const std::string& source) {
  if (!j.is_object()) throw file_error(source, 0, "expected a JSON object (a run's record)");
  RunRecord r;
  auto has = [&](const char* k) { return j.contains(k) && !j[k].is_null(); };
  auto text = [&](const char* k, std::string& out) {
    if (!has(k)) return;
    if (!j[k].is_string()) throw key_error(source, k, "expected a string");
    out = j[k].get<std::string>();
  };
  auto seconds = [&](const char* k, double& out) {
    if (!has(k)) return;
    if (!j[k].is_number() || !(j[k].get<double>() >= 0) || !std::isfinite(j[k].get<double>()))
      throw key_error(source, k, "expected a number of seconds >= 0");
    out = j[k].get<double>();
  };
  text("name", r.name);
  text("revision", r.revision);
  text("processor", r.processor);
  if (has("seed")) {
    if (!is_seed(j["seed"]))
      throw key_error(source, "seed", "expected an integer in [0, 2^63)");
    r.seed = j["seed"].get<uint64_t>();
  }
  if (has("quick")) {
    if (!j["quick"].is_boolean()) throw key_error(source, "quick", "expected true or false");
    r.quick = j["quick"].get<bool>();
  }
  if (has("threads")) {
    if (!j["threads"].is_number_integer() || j["threads"].get<int64_t>() < 1 || j["threads"].get<int64_t>() > 1024)
      throw key_error(source, "threads", "expected a thread count in [1, 1024]");
    r.threads = j["threads"].get<int>();
  }
  if (has("preset")) {
    const nlohmann::json& preset = j["preset"];
    if (!preset.is_object() || (preset.contains("variant") && !preset["variant"].is_string()))
      throw key_error(source, "preset", "expected null or an object with a string \"variant\"");
    r.preset_variant = preset.value("variant", "");
  }
  seconds("synthesis_seconds", r.synthesis_seconds);
  seconds("total_seconds", r.total_seconds);
  seconds("cpu_seconds", r.cpu_seconds);
  if (has("method_stats")) {
    if (!j["method_stats"].is_object()) throw key_error(source, "method_stats", "expected an object");
    r.method_stats = j["method_stats"];
  }
  return r;
}

RunRecord read_run_record(const std::string& path) { return parse_run_record(read_run_json(path), path); }

}  // namespace ppsynth
