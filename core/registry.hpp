#pragma once
// Registry<Base, Args...>: name -> factory, one per kind of pluggable part (rasterizers,
// feature nets, losses, optimizers, initializers, synthesis methods, generators, commands).
//
// A part registers itself at the end of its own .cpp with PPSYNTH_REGISTER_PARAMS, giving its
// config name, the table that declares its parameters (core/config/params.hpp: each key's
// default, range and doc line, once) and a one-line description; PPSYNTH_REGISTER takes the
// defaults and bounds as JSON, for parts defined while the program runs (Python's). Creating it from config merges the user's parameters over the defaults and
// refuses unknown keys, wrong types and values out of range, naming the key path; the factory
// gets that key path too, so that what it refuses itself is named the way the user wrote it
// ("method.feature_net.kernel_size", not "feature_net.kernel_size").
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/config.hpp"
#include "core/config/param_bounds.hpp"
#include "core/config/param_docs.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"

namespace ppsynth {

template <class Base, class... Args>
class Registry {
 public:
  // params: the defaults merged with the user's, types and ranges checked; key_path: where
  // they sit in the config ("method.feature_net").
  using Factory = std::function<std::unique_ptr<Base>(const nlohmann::json& params, const std::string& key_path, Args...)>;
  struct Entry {
    Factory make;
    nlohmann::json defaults;  // every parameter with its default value
    nlohmann::json bounds;    // the range of every numeric parameter, nested like `defaults`
    std::string description;
  };

  static Registry& instance() {
    static Registry r;
    return r;
  }

  // Duplicate names are refused: two parts must never silently shadow each other.
  bool add(const std::string& name, Entry e) {
    if (!entries_.emplace(name, std::move(e)).second)
      throw std::logic_error("duplicate registration of '" + name + "'");
    return true;
  }
  // For parts defined while the program runs (a Python callable registered, then redefined in
  // a notebook): replaces the entry of a name the caller added earlier. The caller keeps track
  // of which names are its own; compiled-in parts are never replaced.
  void replace(const std::string& name, Entry e) {
    auto it = entries_.find(name);
    if (it == entries_.end()) throw std::logic_error("replace: '" + name + "' is not registered");
    it->second = std::move(e);
  }
  bool contains(const std::string& name) const { return entries_.count(name) > 0; }
  const Entry& entry(const std::string& name, const std::string& key_path = "type") const {
    auto it = entries_.find(name);
    if (it == entries_.end()) {
      std::string known;
      for (auto& [n, _] : entries_) known += (known.empty() ? "" : ", ") + n;
      throw config_error(key_path, "unknown type '" + name + "' (known: " + known + ")");
    }
    return it->second;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> v;
    for (auto& [n, _] : entries_) v.push_back(n);
    return v;
  }
  // `spec` is {"type": name, ...params}; `key_path` names spec in the config for errors.
  // Returns the part and fills `resolved` (if given) with the defaults-merged spec.
  std::unique_ptr<Base> create(const nlohmann::json& spec, const std::string& key_path,
                               Args... args, nlohmann::json* resolved = nullptr) const {
    nlohmann::json merged = resolve(spec, key_path);
    if (resolved) *resolved = merged;
    const Entry& e = entries_.at(merged["type"].get<std::string>());
    merged.erase("type");
    return e.make(merged, key_path, args...);
  }
  // The spec as create() would build from it: its part's defaults merged with the user's
  // parameters, types and ranges checked, "type" kept. For a caller that needs a parameter's
  // value (a memory estimate) without building the part: it reads the declared default, never
  // a copy of it.
  nlohmann::json resolve(const nlohmann::json& spec, const std::string& key_path) const {
    if (!spec.is_object() || !spec.contains("type") || !spec["type"].is_string())
      throw config_error(key_path, "expected an object with a string \"type\"");
    const std::string type = spec["type"];
    const Entry& e = entry(type, key_path + ".type");
    nlohmann::json params = spec;
    params.erase("type");
    nlohmann::json merged = apply_defaults(e.defaults, params, key_path);
    check_bounds(merged, e.bounds, key_path);
    merged["type"] = type;
    return merged;
  }
  // Every registered part with its defaults (for `ppsynth config --defaults`).
  nlohmann::json describe() const {
    nlohmann::json j = nlohmann::json::object();
    for (auto& [n, e] : entries_)
      j[n] = {{"description", e.description}, {"defaults", e.defaults}, {"bounds", e.bounds}};
    return j;
  }

 private:
  std::map<std::string, Entry> entries_;
};

// A factory for a part whose parameters are a ParamTable: `make(const Options&, key_path,
// args...)` gets the block read through the table, so that the part reads exactly the keys
// its defaults declare (a key it lacks is a logic_error, a key it holds that no line reads is
// refused, naming it).
template <class O, class Make>
auto read_through(const ParamTable<O>& table, Make make) {
  return [&table, make](const nlohmann::json& p, const std::string& key_path, auto&&... args) {
    return make(table.read(p, key_path), key_path, std::forward<decltype(args)>(args)...);
  };
}

}  // namespace ppsynth

#define PPSYNTH_CONCAT_INNER(a, b) a##b
#define PPSYNTH_CONCAT(a, b) PPSYNTH_CONCAT_INNER(a, b)
// PPSYNTH_REGISTER(RegistryType, "name", defaults_json, bounds_json, "description", factory_lambda)
#define PPSYNTH_REGISTER(REG, NAME, DEFAULTS, BOUNDS, DESC, ...)                         \
  namespace {                                                                             \
  [[maybe_unused]] const bool PPSYNTH_CONCAT(ppsynth_registered_, __LINE__) =             \
      REG::instance().add(NAME, REG::Entry{__VA_ARGS__, DEFAULTS, BOUNDS, DESC});         \
  }
// PPSYNTH_REGISTER_PARAMS(RegistryType, "kind", "name", Options::params(), "description",
//                         [](const Options& o, const std::string& key_path, args...) { ... }):
// a part declared by its table (core/config/params.hpp). Its defaults, bounds and the
// reference's doc lines (under "kind", as `ppsynth config --defaults` names the registry) come
// from the table, and the factory gets the block read through it (read_through).
#define PPSYNTH_REGISTER_PARAMS(REG, KIND, NAME, TABLE, DESC, ...)                                          \
  PPSYNTH_REGISTER(REG, NAME, (TABLE).defaults(), (TABLE).bounds(), DESC, ::ppsynth::read_through(TABLE, __VA_ARGS__)) \
  PPSYNTH_PARAM_DOCS(KIND, NAME, [] { return (TABLE).docs(); })
