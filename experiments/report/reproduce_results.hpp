#pragma once
// What a reproduction (`ppsynth reproduce NAME`) was asked (ReproduceOptions) and what it
// made (ReproduceResult: per panel, per column, the points, metrics and times; the statistics
// over seeds). The runner (experiments/reproduce) fills them; the report writers read them,
// so the writers depend on these types and not on the runner.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "optim/method/stage_record.hpp"
#include "experiments/gather/gather.hpp"
#include "experiments/report/reproduce_verdict.hpp"

namespace ppsynth {

struct ReproduceOptions {
  bool quick = false;
  std::string out;                     // default: reports/<name>
  bool force = false;                  // replace a ppsynth report directory already at `out`
  std::vector<std::string> overrides;  // "--set key=value" for every panel's runs
  // Finished run directories to reuse (find_matching_run): a synthesized column whose resolved
  // config equals one of theirs is copied into the report instead of being run again.
  std::vector<std::string> reuse;
  // Reuse only runs made under this machine's preset variant (find_matching_run's ReuseRule):
  // the runs of the other variant are made again here, so every arm is compared like for like.
  bool reuse_own_variant = false;
  // Only these panels (by name; all when empty). The report says which were left out.
  std::vector<std::string> panels;
  // Over seeds: "95-99" or "95,97" runs every synthesized column with each seed as a sweep
  // (experiments: plan -> execute -> gather) and adds the statistics over seeds to the report;
  // the panels show the runs of the config's own seed when it is one of them. "" = one seed.
  std::string seeds;
  std::string sweep_dir;    // the sweep's directory (default sweeps/<name>, sweeps/<name>-quick)
  int jobs = 1;             // its tasks at once, here
  std::string task_binary;  // the ppsynth executable that runs its tasks (`ppsynth sweep task`)
  bool plan_only = false;   // plan the sweep and return (run it elsewhere: `ppsynth sweep run DIR --slurm`)
  // Set by the runner over seeds: panel -> the generated exemplar file its sweep's runs read.
  std::map<std::string, std::string> generated_exemplars;
};

struct ColumnResult {
  std::string column;
  std::string status = "ok";  // ok | pending (method not registered) | missing (no reference file)
  PointSet output;
  nlohmann::json metrics;     // evaluate(exemplar, output); null unless status ok
  std::string run_dir;        // relative to the report directory; "" for init / reference
  std::string source;         // where the points came from (file or run directory)
  nlohmann::json config;      // resolved run config (synthesized columns)
  std::vector<StageRecord> stages;  // a staged method's stages (the report's per-stage table)
  double seconds = 0;         // wall time of the run (synthesis + its outputs)
  double synthesis_seconds = 0;
  double cpu_seconds = 0;     // the synthesis's CPU time (0: the run did not record it)
  int iterations = 0;         // optimization iterations over all stages
  // What made the run (run.json): its times compare only with runs of the same processor and
  // preset variant, and a reused run may come from another machine.
  std::string processor, preset_variant;  // "": not recorded / no preset
};

struct PanelResult {
  std::string name;
  PointSet exemplar;
  std::string exemplar_source;  // file, or the generator that made it
  std::vector<ColumnResult> columns;
  // Report images of the panel (paths relative to the report directory) with captions.
  std::vector<std::pair<std::string, std::string>> images;
  double seconds = 0;
};

struct ReproduceResult {
  std::string dir;        // the final report directory ("" after plan_only)
  std::string sweep_dir;  // the sweep over seeds ("" without --seeds)
  GatherResult seeds;     // its statistics (gathered into <dir>/seeds)
  ItemNumbers numbers;    // what the rule's verdict reads (experiments/reproduce/reproduce_numbers.hpp)
  std::vector<PanelResult> panels;
  double seconds = 0;
  bool quick = false;
};

}  // namespace ppsynth
