#include "optim/run/run_config.hpp"

#include <algorithm>

#include "core/config/config.hpp"
#include "core/config/defaults_catalog.hpp"
#include "core/config/json_text.hpp"
#include "core/config/param_bounds.hpp"
#include "core/config/param_docs.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/output_shape.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "optim/method/method.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/runtime.hpp"

namespace ppsynth {

const ParamTable<RunOptions>& RunOptions::params() {
  using O = RunOptions;
  static const ParamTable<O> t("", {
      param("name", &O::name, "", "the run's name (empty: the exemplar's file stem)"),
      param("description", &O::description, "", "a line about the run, kept in its config"),
      param("exemplar", &O::exemplar, "", "the exemplar's point file (\"shared:data/...\" under ../shared)"),
      param("format", &O::format, "", "the exemplar's format: auto, gabor, point-synthesis, plain or json"),
      param("scaling", &O::scaling, "", "a Point-Synthesis file's scaling: per-axis (the published) or uniform"),
      param("merge_classes", &O::merge_classes, "", "every point as one class (positions only)"),
      param("init_file", &O::init_file, "", "the start: one file (with a class column), or a list with one file per class"),
      param("preset", &O::preset, "", "a named preset laid under the config's own keys (\"fast\")"),
      param("seed", &O::seed, "", "the seed of every random draw of the run"),
      param("upscale", &O::upscale, "int [1, 64]", "u: u^2 times the exemplar's points (unless output gives a size)"),
      block("output", &O::output),
      param("method", &O::method, "", "the method's spec: its type and its keys"),
      param("snapshots", &O::snapshots, "", "plot the output after every stage"),
      param("evaluate", &O::evaluate, "", "run the metrics on the output"),
      param("checkpoint_seconds", &O::checkpoint_seconds, "(0, inf)", "wall time between checkpoints (and one at every stage's end)"),
      block("runtime", &O::runtime),
  });
  return t;
}

json run_defaults() { return RunOptions::params().defaults(); }

json resolve_run_config(json config, const std::vector<std::string>& overrides) {
  for (auto& o : overrides) set_override(config, o);
  // A run writes its config as JSON and reads it back (resume, reproduce): text that is not
  // UTF-8 (a file name from the command line) could not be written, and a replaced one
  // would name another file.
  if (const auto key = first_non_utf8(config))
    throw config_error(*key, "not valid UTF-8, and a run records its config as JSON: rename the file (or link it under a UTF-8 name)");
  json r = apply_defaults(run_defaults(), apply_preset(config), "");
  if (!is_seed(r["seed"])) throw config_error("seed", "expected a whole number from 0 to 2^63 - 1, got " + r["seed"].dump());
  check_bounds(r, RunOptions::params().bounds(), "");
  check_runtime(r["runtime"]);
  json resolved_method;
  MethodRegistry::instance().create(r["method"], "method", &resolved_method);
  r["method"] = resolved_method;
  const std::string name = r["name"];
  if (!name.empty() && !is_safe_name(name))  // it names runs/<name>: never a path
    throw config_error("name", "'" + name + "' is not a plain name (letters, digits, '_' or '-')");
  return r;
}

json read_resolved_run_config(const std::string& path) {
  const json c = read_run_config(path);
  json r;
  try {
    r = resolve_run_config(c, {});
  } catch (const InputError& e) {
    throw file_error(path, 0, e.what());
  }
  if (r != c) {
    const json a = c.flatten(), b = r.flatten();
    std::string key;
    for (auto it = b.begin(); it != b.end() && key.empty(); ++it)
      if (!a.contains(it.key()) || a[it.key()] != it.value()) key = it.key();
    for (auto it = a.begin(); it != a.end() && key.empty(); ++it)
      if (!b.contains(it.key())) key = it.key();
    std::replace(key.begin(), key.end(), '/', '.');
    throw file_error(path, 0, "key '" + key.substr(key.empty() ? 0 : 1) +
                                  "' is not as the run resolved it (the file was edited since the run began)");
  }
  return r;
}

PointSet load_exemplar(const json& r, Format* read_as) {
  const std::string file = get_string(r, "exemplar", "");
  if (file.empty()) throw config_error("exemplar", "no exemplar file given");
  ReadOptions o;
  o.format = parse_format(get_string(r, "format", ""));
  try {
    o.scaling = parse_axis_scaling(get_string(r, "scaling", ""));
  } catch (const InputError& e) {
    throw config_error("scaling", e.what());
  }
  PointFile f = read_point_file(file, o);  // once: the points and the format they were read as
  if (read_as) *read_as = f.format;
  PointSet ps = std::move(f.points);
  if (get_bool(r, "merge_classes", "")) {
    for (size_t i = 0; i < ps.size(); ++i) ps.set_cls(i, 0);
    ps.set_class_labels({});
  }
  return ps;
}

std::optional<PointSet> load_initialization(const json& r) {
  const json& f = r["init_file"];
  if (f.is_null() || (f.is_string() && f.get<std::string>().empty())) return std::nullopt;
  if (f.is_string()) return read_points(f.get<std::string>());
  if (!f.is_array()) throw config_error("init_file", "expected a file name or a list of file names (one per class)");
  PointSet all;
  for (size_t k = 0; k < f.size(); ++k) {
    if (!f[k].is_string()) throw config_error("init_file[" + std::to_string(k) + "]", "expected a file name");
    PointSet part = read_points(f[k].get<std::string>());
    for (size_t i = 0; i < part.size(); ++i) all.add(part[i], static_cast<int>(k));
  }
  return all;
}

}  // namespace ppsynth

PPSYNTH_PARAM_DOCS("run", "run", [] { return ppsynth::RunOptions::params().docs(); })

namespace {
[[maybe_unused]] const bool ppsynth_run_kind = ppsynth::register_defaults_kind("run", [] {
  return ppsynth::json{{"run", {{"description", "top-level keys of a synthesis config"}, {"defaults", ppsynth::run_defaults()},
                               {"bounds", ppsynth::RunOptions::params().bounds()}}}};
});
}  // namespace
