#pragma once
// The run store: a run as a directory of files, written, read back and found again.
//   output.txt (project format) + output.<exemplar format>.txt, exemplar.txt (as synthesized),
//   init.txt, exemplar_vs_output.png, snapshots/stageNN.{txt,png} (paper Fig. 4), loss.csv +
//   loss.png, config.json (resolved), run.json (seed, revision, threads, processor, wall times,
//   the method's stats), metrics.json and pcf.png (`ppsynth eval` of the output vs the exemplar).
// Directories are opened through RunDirectory (core/run_directory.hpp); running a synthesis
// into one is optim/run/run_synthesis.hpp.
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/formats/format_options.hpp"
#include "core/point_set.hpp"
#include "core/run_json.hpp"
#include "optim/method/stage_record.hpp"
#include "optim/run/run_observers.hpp"

namespace ppsynth {

struct RunOptions;  // run_config.hpp

// A run as the store knows it: where, the resolved config, the points and what was measured.
struct RunOutcome {
  std::string dir;
  PointSet exemplar, initialization, output;
  std::vector<StageRecord> stages;   // a staged method's finished stages (run.json: method_stats.stages)
  nlohmann::json stats, metrics, config;  // stats: the rest of run.json's method_stats
  double seconds = 0;
  double seconds_before_resume = 0;  // the part of `seconds` spent before a resume
  double cpu_seconds = 0;            // the synthesis's CPU time, every process of it (run.json's cpu_seconds)
  // The exemplar file's format, detected when the run began (the run directory's marker keeps
  // it for a resume, whose machine may not have the file): an exemplar in the published
  // integer format gets its output in that format too (output.gabor.txt).
  Format exemplar_format = Format::Plain;
};

// Writes every output file of a finished synthesis into o.dir (o.seconds is set here: the
// run's wall time since `started`); run.json's seed and preset from `options` (o.config read
// through its table: RunSpec::options). `losses` holds every iteration's loss.
void write_run_outputs(RunOutcome& o, const RunOptions& options, const std::string& name, bool quick, const LossRecorder& losses,
                       double synthesis_seconds, std::chrono::steady_clock::time_point started);

// Reads a finished run directory back (config.json, run.json, output.txt, init.txt; the
// exemplar from its exemplar.txt copy, or the config's file for runs made before the copy).
// Throws InputError naming the file (and key) when something is missing or malformed
// (core/run_json.hpp).
RunOutcome load_run(const std::string& dir);

// The exemplar a run synthesized from: its exemplar.txt copy (written when the run begins),
// else its config's file (runs made before the copy).
PointSet run_exemplar(const std::string& dir, const nlohmann::json& config);

// The keys of a resolved run config that decide a synthesis: all but those that only label or
// decorate a run (name, description, snapshots, evaluate, checkpoint_seconds) and the
// exemplar's file name and format (exemplars are compared by content).
nlohmann::json synthesis_key(nlohmann::json resolved);

// What pools runs as seeds of one configuration (a sweep's group, gather's): the synthesis key
// without the seed, with the exemplar's file and the quick setting.
nlohmann::json group_key(const nlohmann::json& resolved, bool quick);

// True when two resolved run configs describe the same synthesis apart from the exemplar:
// everything but the keys that only label or decorate a run (name, description, snapshots,
// evaluate, checkpoint_seconds) and the exemplar's file name and format (exemplars are
// compared by content).
bool same_synthesis(const nlohmann::json& a, const nlohmann::json& b);

// A finished run directory under any of `roots` (each root itself or one of its direct
// subdirectories) made by the same synthesis (same_synthesis) at the same quick setting from
// the same exemplar points (so a generated exemplar in another report's folder matches);
// "" when none. Only directories marked complete count. Lets a report reuse long runs
// instead of repeating them (reproduce --reuse).
// `rule.needs_cpu_seconds`: only runs that recorded their CPU time (run.json `cpu_seconds` > 0;
// runs before 2026-11-30 did not), for a report whose rule reads run/cpu_seconds (table3):
// reusing one would leave its check without a number.
// A run made under the other variant of the config's preset (a machine with bf16 units where
// this one has none, or the reverse) matches when the request was the same
// (presets.hpp's as_every_processor_variant) and no run of this machine's own variant does;
// the reuse warns of the other processor. `other_variant` false: only this machine's variant,
// so an item's arms are compared like for like (reproduce --reuse-own-variant).
struct ReuseRule {
  bool needs_cpu_seconds = false;
  bool other_variant = true;
};
std::string find_matching_run(const nlohmann::json& resolved, bool quick, const std::vector<std::string>& roots,
                              ReuseRule rule = {});

// The run's name: the config's, else the exemplar's file stem.
std::string run_name(const nlohmann::json& resolved);

// What a run recorded of how it computed (`threads`, `processor`: run.json or the running
// marker) that differs from this process, as a phrase ("4 threads (this process 1)"); "" when
// nothing differs. Either difference changes the trajectory from its last bits on.
std::string made_differently(const nlohmann::json& recorded);

}  // namespace ppsynth
