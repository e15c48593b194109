#include "experiments/plan/reproduce_config.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "optim/run/run_config.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/run_directory.hpp"
#include "core/generators/generator.hpp"
#include "core/paths.hpp"
#include "models/rasterizer.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/method/method.hpp"
#include "optim/run/presets.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

// "preset=NAME" -> NAME; "" for any other override.
std::string preset_of(const std::string& override_text) {
  const std::string key = "preset=";
  return override_text.rfind(key, 0) == 0 ? override_text.substr(key.size()) : "";
}

json figure_defaults() {
  return json{{"name", ""},           {"title", ""},        {"claim", ""},         {"paper_ref", ""},
              {"description", ""},    {"kind", "figure"},   {"methods", {"ours"}}, {"method_params", nullptr},
              {"pending_methods", json::array()},           {"panels", json::array()},
              {"tables", json::array()},                     {"rule", nullptr},
              {"diagnosis", {{"text", ""}, {"published_code", ""}, {"see", ""}}}};
}

json panel_defaults() {
  return json{{"name", ""},    {"title", ""},         {"note", ""},       {"kind", "synthesis"},
              {"run", nullptr}, {"exemplar_generator", nullptr},         {"methods", nullptr},
              {"reference", ""}, {"stages", false},   {"maps", nullptr},  {"paper", nullptr},
              {"presets_not_equivalent", nullptr}};
}

json generator_defaults() {
  return json{{"generator", {{"type", "ccvt"}}}, {"n", 64}, {"seed", 1}, {"quick", nullptr}};
}

json maps_defaults() {
  // Fig. 3: frequency maps at sigma = 0.078 (gamma = 1), spatial maps at several sigmas (gamma = 0).
  // k and the base frequency are the synthesis's own (declared by the gabor method and rasterizer).
  return json{{"sigma", 0.078}, {"sigmas", {0.02, 0.04, 0.078, 0.12}}, {"res", 128}, {"quick_res", 32},
              {"k", gabor_defaults()["k"]},
              {"base_frequency", RasterizerRegistry::instance().entry("gabor").defaults["base_frequency"]}};
}

json table_defaults() {
  return json{{"type", ""}, {"name", ""}, {"caption", ""}, {"methods", nullptr}, {"paper", nullptr}};
}

const std::set<std::string> kTableTypes = {"comparison", "relative_radius", "runtime"};

std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::vector<std::string> string_list(const json& j, const std::string& kp) {
  if (!j.is_array()) throw config_error(kp, "expected a list of strings");
  std::vector<std::string> v;
  for (size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_string()) throw config_error(at(kp, i), "expected a string");
    v.push_back(j[i].get<std::string>());
  }
  return v;
}

std::string known_columns(const std::vector<std::string>& pending) {
  std::string s = "ours, init, reference";
  for (auto& n : MethodRegistry::instance().names()) s += ", " + n;
  for (auto& n : pending) s += ", " + n + " (pending)";
  return s;
}

void check_methods(const std::vector<std::string>& methods, const std::vector<std::string>& pending, const std::string& kp) {
  std::set<std::string> seen;
  for (size_t j = 0; j < methods.size(); ++j) {
    const std::string& m = methods[j];
    if (!seen.insert(m).second) throw config_error(at(kp, j), "method '" + m + "' listed twice");
    const bool is_pending = std::find(pending.begin(), pending.end(), m) != pending.end();
    if (!is_builtin_column(m) && !MethodRegistry::instance().contains(m) && !is_pending)
      throw config_error(at(kp, j), "unknown method '" + m + "' (known: " + known_columns(pending) + ")");
  }
  if (seen.count("init") && !seen.count("ours")) throw config_error(kp, "'init' is the initialization of 'ours': list 'ours' too");
}

// A panel's run: "parent" (relative to the figure config) merged under the panel's keys.
json load_panel_run(const json& run, const std::string& base_dir, const std::string& kp) {
  if (!run.is_object()) throw config_error(kp, "expected a run config object");
  if (!run.contains("parent")) return run;
  if (!run["parent"].is_string()) throw config_error(kp + ".parent", "expected a path string");
  const fs::path parent = fs::path(base_dir) / run["parent"].get<std::string>();
  if (!fs::exists(parent)) throw config_error(kp + ".parent", "no such file: " + parent.string());
  json over = run;
  over.erase("parent");
  return merge(load_config(parent.string()), over);
}

void require_file(const std::string& path, const std::string& kp) {
  if (!fs::exists(resolve_data_path(path))) throw config_error(kp, "no such file: " + resolve_data_path(path));
}

PanelSpec parse_panel(const json& pj, const ReproduceConfig& c, const std::string& base_dir, size_t i) {
  const std::string kp = at("panels", i);
  json p = apply_defaults(panel_defaults(), pj, kp);
  PanelSpec s;
  s.name = p["name"];
  if (!is_safe_name(s.name)) throw config_error(kp + ".name", "expected a short name of letters, digits, '_' or '-'");
  s.title = p["title"].get<std::string>().empty() ? s.name : p["title"].get<std::string>();
  s.note = p["note"];
  s.kind = p["kind"];
  if (s.kind != "synthesis" && s.kind != "gabor_maps")
    throw config_error(kp + ".kind", "expected \"synthesis\" or \"gabor_maps\", got \"" + s.kind + "\"");
  if (p["run"].is_null()) throw config_error(kp + ".run", "every panel needs a run config (its exemplar at least)");
  s.run = load_panel_run(p["run"], base_dir, kp + ".run");
  s.reference = p["reference"];
  s.stages = p["stages"];
  if (!p["paper"].is_null()) {
    if (!p["paper"].is_object()) throw config_error(kp + ".paper", "expected an object of published values");
    s.paper = p["paper"];
  }
  if (!s.reference.empty()) require_file(s.reference, kp + ".reference");
  if (!p["presets_not_equivalent"].is_null()) {
    const std::string nk = kp + ".presets_not_equivalent";
    if (!p["presets_not_equivalent"].is_object()) throw config_error(nk, "expected {\"PRESET\": \"why it is not equivalent here\"}");
    const json known = presets();
    for (auto& [name, why] : p["presets_not_equivalent"].items()) {
      if (!known.contains(name)) throw config_error(nk + "." + name, "not a preset (`ppsynth config --kind preset`)");
      if (!why.is_string() || why.get<std::string>().empty())
        throw config_error(nk + "." + name, "expected the reason, as a sentence: what was measured, and where");
    }
    s.presets_not_equivalent = p["presets_not_equivalent"];
  }

  if (!p["exemplar_generator"].is_null()) {
    s.generator = apply_defaults(generator_defaults(), p["exemplar_generator"], kp + ".exemplar_generator");
    const std::string gk = kp + ".exemplar_generator";
    if (get_int(s.generator, "n", gk) < 2) throw config_error(gk + ".n", "must be >= 2");
    if (get_int(s.generator, "seed", gk) < 0) throw config_error(gk + ".seed", "must be >= 0");
    GeneratorRegistry::instance().create(s.generator["generator"], gk + ".generator");
    if (!s.generator["quick"].is_null()) {
      if (!s.generator["quick"].is_object()) throw config_error(gk + ".quick", "expected generator parameters");
      GeneratorRegistry::instance().create(merge(s.generator["generator"], s.generator["quick"]), gk + ".quick");
    }
    if (s.run.contains("exemplar")) throw config_error(kp + ".run.exemplar", "a generated exemplar replaces the run's: give one or the other");
  }

  if (s.kind == "gabor_maps") {
    if (!p["methods"].is_null()) throw config_error(kp + ".methods", "a gabor_maps panel runs no method");
    s.maps = apply_defaults(maps_defaults(), p["maps"], kp + ".maps");
    const std::string mk = kp + ".maps";
    if (!(get_number(s.maps, "sigma", mk) > 0)) throw config_error(mk + ".sigma", "must be > 0");
    for (size_t j = 0; j < s.maps["sigmas"].size(); ++j)
      if (!s.maps["sigmas"][j].is_number() || !(s.maps["sigmas"][j].get<double>() > 0))
        throw config_error(at(mk + ".sigmas", j), "expected a number > 0");
    if (get_int(s.maps, "res", mk) < 8) throw config_error(mk + ".res", "must be >= 8");
    if (get_int(s.maps, "quick_res", mk) < 8) throw config_error(mk + ".quick_res", "must be >= 8");
    if (get_int(s.maps, "k", mk) < 1) throw config_error(mk + ".k", "must be >= 1");
  } else {
    if (!p["maps"].is_null()) throw config_error(kp + ".maps", "only gabor_maps panels draw maps");
    const bool own = !p["methods"].is_null();
    s.methods = own ? string_list(p["methods"], kp + ".methods") : c.methods;
    if (s.methods.empty()) throw config_error(kp + ".methods", "list at least one method column");
    check_methods(s.methods, c.pending_methods, own ? kp + ".methods" : "methods");
    if (own && s.reference.empty() && std::count(s.methods.begin(), s.methods.end(), "reference"))
      throw config_error(kp + ".reference", "the panel lists 'reference' but names no reference output file");
  }
  return s;
}

// Resolves every run a panel will start (ours and the registered methods), so errors show
// before anything runs; prefixes the message with the panel's key path.
void check_panel_runs(const ReproduceConfig& c, const PanelSpec& p, size_t i, const std::vector<std::string>& overrides) {
  std::vector<std::string> columns = p.methods;
  if (p.kind == "gabor_maps") columns = {"ours"};
  for (const auto& col : columns) {
    if (col == "init" || col == "reference" || !method_available(col)) continue;
    try {
      json run = column_run_config(c, p, col, overrides);
      if (!p.generator.is_null()) run["exemplar"] = "(generated)";
      json r = resolve_run_config(run, {});
      if (p.generator.is_null()) require_file(r["exemplar"], "exemplar");
      if (r["init_file"].is_string() && !r["init_file"].get<std::string>().empty()) require_file(r["init_file"], "init_file");
      if (r["init_file"].is_array())
        for (auto& f : r["init_file"])
          if (f.is_string()) require_file(f, "init_file");
    } catch (const InputError& e) {
      throw InputError(at("panels", i) + ".run (column '" + col + "'): " + e.what());
    }
  }
}

// What a rule's groups may name, per synthesis panel: its synthesized columns, "init" with
// "ours" (each seed's ours run holds its initialization), "reference" with a published output.
std::map<std::string, std::vector<std::string>> rule_columns(const ReproduceConfig& c) {
  std::map<std::string, std::vector<std::string>> m;
  for (const PanelSpec& p : c.panels) {
    if (p.kind != "synthesis") continue;
    auto& cols = m[p.name];
    for (auto& col : p.methods)
      if (col != "init" && col != "reference") cols.push_back(col);
    if (std::count(p.methods.begin(), p.methods.end(), "ours")) cols.push_back("init");
    if (!p.reference.empty()) cols.push_back("reference");
  }
  return m;
}

}  // namespace

void check_reproduce_runs(const ReproduceConfig& c, const std::vector<std::string>& overrides) {
  for (size_t i = 0; i < c.panels.size(); ++i) check_panel_runs(c, c.panels[i], i, overrides);
}

bool is_builtin_column(const std::string& name) { return name == "ours" || name == "init" || name == "reference"; }

bool method_available(const std::string& name) {
  return is_builtin_column(name) || MethodRegistry::instance().contains(name);
}

ReproduceConfig parse_reproduce_config(const json& config, const std::string& source, const std::string& base_dir) {
  try {
    json f = apply_defaults(figure_defaults(), config, "");
    ReproduceConfig c;
    c.raw = config;
    c.source = source;
    c.name = f["name"];
    if (c.name.empty() && !source.empty()) c.name = fs::path(source).stem().string();
    if (!is_safe_name(c.name)) throw config_error("name", "expected a short name of letters, digits, '_' or '-'");
    c.title = f["title"].get<std::string>().empty() ? c.name : f["title"].get<std::string>();
    c.claim = f["claim"];
    c.paper_ref = f["paper_ref"];
    c.description = f["description"];
    c.kind = f["kind"];
    static const std::set<std::string> kinds = {"figure", "table", "ablation", "supplement"};
    if (!kinds.count(c.kind)) throw config_error("kind", "expected figure, table, ablation or supplement, got \"" + c.kind + "\"");
    c.pending_methods = string_list(f["pending_methods"], "pending_methods");
    c.methods = string_list(f["methods"], "methods");
    check_methods(c.methods, c.pending_methods, "methods");
    if (!f["method_params"].is_null()) {
      if (!f["method_params"].is_object()) throw config_error("method_params", "expected {\"method name\": {parameters}}");
      for (auto it = f["method_params"].begin(); it != f["method_params"].end(); ++it) {
        if (!it.value().is_object()) throw config_error("method_params." + it.key(), "expected an object of parameters");
        if (is_builtin_column(it.key())) throw config_error("method_params." + it.key(), "'" + it.key() + "' takes no parameters here (ours: the panel's run)");
      }
      c.method_params = f["method_params"];
    }
    if (!f["panels"].is_array() || f["panels"].empty()) throw config_error("panels", "expected a non-empty list of panels");
    std::set<std::string> names;
    for (size_t i = 0; i < f["panels"].size(); ++i) {
      c.panels.push_back(parse_panel(f["panels"][i], c, base_dir, i));
      if (!names.insert(c.panels.back().name).second) throw config_error(at("panels", i) + ".name", "duplicate panel name '" + c.panels.back().name + "'");
    }
    check_reproduce_runs(c, {});
    std::set<std::string> tnames;
    for (size_t i = 0; i < f["tables"].size(); ++i) {
      const std::string kp = at("tables", i);
      json t = apply_defaults(table_defaults(), f["tables"][i], kp);
      TableSpec ts;
      ts.type = t["type"];
      if (!kTableTypes.count(ts.type)) throw config_error(kp + ".type", "expected comparison, relative_radius or runtime, got \"" + ts.type + "\"");
      ts.name = t["name"].get<std::string>().empty() ? ts.type : t["name"].get<std::string>();
      if (!is_safe_name(ts.name)) throw config_error(kp + ".name", "expected letters, digits, '_' or '-' (it names the CSV file)");
      if (!tnames.insert(ts.name).second || ts.name == "metrics") throw config_error(kp + ".name", "duplicate or reserved table name '" + ts.name + "'");
      ts.caption = t["caption"];
      if (!t["methods"].is_null()) {
        ts.methods = string_list(t["methods"], kp + ".methods");
        check_methods(ts.methods, c.pending_methods, kp + ".methods");
      }
      if (!t["paper"].is_null() && !t["paper"].is_object()) throw config_error(kp + ".paper", "expected an object of published values");
      ts.paper = t["paper"];
      c.tables.push_back(ts);
    }
    if (!f["rule"].is_null()) c.rule = parse_reproduce_rule(f["rule"], rule_columns(c));
    c.diagnosis = f["diagnosis"];
    return c;
  } catch (const InputError& e) {
    if (source.empty()) throw;
    throw InputError(source + ": " + e.what());
  }
}

ReproduceConfig load_reproduce_config(const std::string& path) {
  if (!fs::exists(path)) throw InputError(path + ": no such config file");
  json j;
  try {
    j = load_config(path);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind(path, 0) == 0) throw;
    throw InputError(path + ": " + msg);
  }
  return parse_reproduce_config(j, path, fs::path(path).parent_path().string());
}

json column_run_config(const ReproduceConfig& c, const PanelSpec& p, const std::string& column,
                       const std::vector<std::string>& overrides) {
  json run = p.run;
  if (column != "ours") {
    json m = {{"type", column}};
    if (c.method_params.contains(column)) m = merge(m, c.method_params[column]);
    run["method"] = m;
  }
  run["name"] = c.name + "-" + p.name + "-" + column;  // a label, and a plain name like every run name
  for (const auto& o : overrides) {
    // Method keys, and a preset (it sets the gabor method's keys), belong to ours.
    if (column != "ours" && (o.rfind("method.", 0) == 0 || o.rfind("preset=", 0) == 0)) continue;
    // A preset the project measured as not equivalent on this panel stays off: the verdict
    // must rest on the config's own settings there (presets_set_aside says so in the report).
    if (const std::string preset = preset_of(o); !preset.empty() && p.presets_not_equivalent.contains(preset)) continue;
    set_override(run, o);
  }
  return run;
}

json presets_set_aside(const ReproduceConfig& c, const std::vector<std::string>& overrides) {
  json aside = json::array();
  for (const auto& o : overrides) {
    const std::string preset = preset_of(o);
    if (preset.empty()) continue;
    for (const PanelSpec& p : c.panels)
      if (p.presets_not_equivalent.contains(preset))
        aside.push_back({{"panel", p.name}, {"preset", preset}, {"why", p.presets_not_equivalent[preset]}});
  }
  return aside;
}

std::string paper_config_dir() { return (fs::path(source_root()) / "configs" / "paper").string(); }

std::vector<std::string> list_reproduce_configs(const std::string& dir) {
  std::vector<std::string> v;
  if (!fs::is_directory(dir)) return v;
  for (auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") v.push_back(e.path().string());
  std::sort(v.begin(), v.end());
  return v;
}

std::string find_reproduce_config(const std::string& name) {
  if (name.size() > 5 && name.substr(name.size() - 5) == ".json") {
    if (!fs::exists(name)) throw InputError(name + ": no such config file");
    return name;
  }
  const fs::path p = fs::path(paper_config_dir()) / (name + ".json");
  if (fs::exists(p)) return p.string();
  std::string known;
  for (auto& f : list_reproduce_configs(paper_config_dir())) known += (known.empty() ? "" : ", ") + fs::path(f).stem().string();
  throw InputError("no config '" + name + "' in " + paper_config_dir() + " (known: " + known + ")");
}

}  // namespace ppsynth
