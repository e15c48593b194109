#pragma once
// A paper experiment as a config (configs/paper/NAME.json): `ppsynth reproduce NAME` runs it
// and writes a report (experiments/reproduce/reproduce_runner.hpp, report_writer.hpp).
// Schema (docs/howto/reproduce_a_figure.md is the user-facing description; unknown keys are errors naming
// the key path, e.g. "config key 'panels[2].methods[1]': ..."):
//
//   { "name", "title", "claim" (the paper's claim, one sentence), "paper_ref", "description",
//     "kind": "figure" | "table" | "ablation" | "supplement",
//     "methods": ["ours", ...]            columns every panel shows unless it lists its own
//     "method_params": {"pcf2017": {...}} parameters of the registry methods named in columns
//     "pending_methods": ["roveri2015"]   may be absent from MethodRegistry (column "n/a")
//     "panels": [ {
//         "name" (short, file-safe), "title", "note" (e.g. which shipped exemplar stands in),
//         "kind": "synthesis" (default) | "gabor_maps" (Fig. 3: map images, no synthesis),
//         "run": run config object (configs/runs schema; may hold "parent", a path relative
//                to this figure config),
//         "exemplar_generator": {"generator": {"type": "ccvt", ...}, "n", "seed",
//                                "quick": {generator params for --quick}}  (replaces
//                                run.exemplar with a generated pattern, e.g. Table 1's CCVT),
//         "methods": [...], "reference": "shared:data/reference/.../output.txt",
//         "stages": bool (show the per-sigma snapshots, Fig. 4),
//         "maps": {"sigma", "sigmas", "res", "quick_res", "k"}  (gabor_maps panels),
//         "paper": {...} published numbers for this panel, shown beside ours,
//         "presets_not_equivalent": {"fast": "why"}  presets shown not to give this panel the
//                config's result: `--preset fast` (or `--set preset=fast`) leaves ours' run
//                here at the config's own settings, and the report says so with the reason } ],
//     "tables": [ {"type": "comparison" | "relative_radius" | "runtime", "name", "caption",
//                  "methods", "paper": {...}} ] }   each also written as CSV and Markdown.
//     "rule": {...}   how the gathered numbers decide the verdict (reproduce_rule.hpp)
//     "diagnosis": {"text", "published_code", "see"}   written after the runs, where the
//                  verdict falls short: why, the published code's own number on the item,
//                  and the lab page that measured it; shown under the verdict
//
// Method columns: "ours" = the panel's run as configured; "init" = the initialization ours
// started from; "reference" = the panel's "reference" file (the published code's output);
// any other name = that MethodRegistry method on the panel's exemplar (its parameters from
// "method_params"), so a new registered method is one more name in a config, no code change.
// A figure config may itself have a "parent" (e.g. table2.json reuses fig05.json's panels).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/plan/reproduce_rule.hpp"

namespace ppsynth {

using json = nlohmann::json;

struct PanelSpec {
  std::string name, title, note;
  std::string kind = "synthesis";  // synthesis | gabor_maps
  json run;                        // run config with its "parent" chain merged, not resolved
  std::vector<std::string> methods;
  std::string reference;           // "" = none
  json generator;                  // null or {"generator", "n", "seed", "quick"}
  json maps;                       // gabor_maps settings (defaults filled)
  bool stages = false;
  json paper = json::object();
  // preset name -> why it is not equivalent here (a lab measurement): ours runs without it.
  json presets_not_equivalent = json::object();
};

struct TableSpec {
  std::string type, name, caption;
  std::vector<std::string> methods;  // empty = the figure's columns
  json paper;                        // published row(s): {"column": value, ...} or null
};

struct ReproduceConfig {
  std::string name, title, claim, paper_ref, description, kind;
  std::string source;  // the file it was read from ("" if built in memory)
  std::vector<std::string> methods;
  json method_params = json::object();
  std::vector<std::string> pending_methods;
  std::vector<PanelSpec> panels;
  std::vector<TableSpec> tables;
  ReproduceRule rule;  // kind "" when the config states none
  json diagnosis;      // {"text", "published_code", "see"}: strings, "" when not written
  json raw;  // the config after "parent" resolution (written into the report)
};

// Special method columns (not registry names).
bool is_builtin_column(const std::string& name);  // ours | init | reference
// Status of a method column in this build: "ok", or "pending" for an unregistered name
// listed in pending_methods (the runner shows it as not available).
bool method_available(const std::string& name);

// Reads and validates a figure config. Every panel's run is resolved once (so a bad method
// key fails here, before any synthesis runs) and every exemplar/reference file must exist.
ReproduceConfig load_reproduce_config(const std::string& path);
// Same for a config already in memory; `base_dir` resolves relative "parent" paths of runs.
ReproduceConfig parse_reproduce_config(const json& config, const std::string& source, const std::string& base_dir);

// Resolves every run the config will start (with the "--set" overrides), checking method
// keys and that exemplar/init files exist; InputError names the panel and column.
void check_reproduce_runs(const ReproduceConfig& c, const std::vector<std::string>& overrides);

// The run config of one method column of a panel (unresolved): "ours" -> panel.run; a
// registry name -> panel.run with "method" = {"type": name} + method_params[name].
// `overrides` ("--set key=value") apply to every column; keys under "method." and "preset"
// only to ours, and "preset=NAME" not where the panel lists NAME in presets_not_equivalent.
json column_run_config(const ReproduceConfig& c, const PanelSpec& p, const std::string& column,
                       const std::vector<std::string>& overrides);

// The panels where one of `overrides`' presets is set aside (presets_not_equivalent):
// [{"panel", "preset", "why"}], for the report and the page to say so.
json presets_set_aside(const ReproduceConfig& c, const std::vector<std::string>& overrides);

// configs/paper under the source root (core/paths.hpp source_root()).
std::string paper_config_dir();
// Every *.json in `dir`, sorted by file name.
std::vector<std::string> list_reproduce_configs(const std::string& dir);
// NAME (a file stem in paper_config_dir()) or a path to a .json file -> the file's path.
// InputError listing the known names when NAME is neither.
std::string find_reproduce_config(const std::string& name_or_path);

}  // namespace ppsynth
