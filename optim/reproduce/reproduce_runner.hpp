#pragma once
// Runs a paper experiment (reproduce_config.hpp) into a report directory:
//
//   <out>/index.html          self-contained report (report_writer.hpp)
//   <out>/metrics.{csv,md}    every panel x method column: PCF MSE, Wasserstein, Chamfer, ...
//   <out>/<table>.{csv,md}    the paper-layout tables the config asks for (Tables 1-3)
//   <out>/report.json         every number of the report, machine-readable
//   <out>/figure.png          overview: exemplar and outputs side by side, as in the paper
//   <out>/panels/<panel>/     exemplar plots, PCF comparison, map images (Fig. 3), and one
//                             run directory per synthesised column (run_synthesis.hpp)
//
// The directory is built as "<out>.partial" and renamed when complete (a failed run keeps the
// previous report). Panels run in config order, each column of a panel on the same exemplar;
// "ours" runs first so "init" can show its initialisation. --quick runs every synthesis with
// the methods' quick settings and shrinks generators and map grids (tests, smoke runs).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "optim/reproduce/reproduce_config.hpp"
#include "optim/sweep/gather.hpp"

namespace ppsynth {

struct ReproduceOptions {
  bool quick = false;
  std::string out;                     // default: reports/<name>
  bool force = false;                  // replace a ppsynth report directory already at `out`
  std::vector<std::string> overrides;  // "--set key=value" for every panel's runs
  // Finished run directories to reuse (find_matching_run): a synthesised column whose resolved
  // config equals one of theirs is copied into the report instead of being run again.
  std::vector<std::string> reuse;
  // Only these panels (by name; all when empty). The report says which were left out.
  std::vector<std::string> panels;
  // Over seeds: "95-99" or "95,97" runs every synthesised column with each seed as a sweep
  // (optim/sweep: plan -> execute -> gather) and adds the statistics over seeds to the report;
  // the panels show the runs of the config's own seed when it is one of them. "" = one seed.
  std::string seeds;
  std::string sweep_dir;    // the sweep's directory (default sweeps/<name>, sweeps/<name>-quick)
  int jobs = 1;             // its tasks at once, here
  std::string task_binary;  // the ppsynth executable that runs its tasks (`ppsynth sweep task`)
  bool plan_only = false;   // plan the sweep and return (run it elsewhere: `ppsynth sweep run DIR --slurm`)
};

struct ColumnResult {
  std::string column;
  std::string status = "ok";  // ok | pending (method not registered) | missing (no reference file)
  PointSet output;
  nlohmann::json metrics;     // evaluate(exemplar, output); null unless status ok
  std::string run_dir;        // relative to the report directory; "" for init / reference
  std::string source;         // where the points came from (file or run directory)
  nlohmann::json config;      // resolved run config (synthesised columns)
  nlohmann::json stats;       // the method's own statistics (iterations, grid, ...)
  double seconds = 0;         // wall time of the run (synthesis + its outputs)
  double synthesis_seconds = 0;
  int iterations = 0;         // optimisation iterations over all stages
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
  std::vector<PanelResult> panels;
  double seconds = 0;
  bool quick = false;
};

// Runs every panel and writes the report (with --seeds, after the sweep over seeds finished).
ReproduceResult run_reproduction(const ReproduceConfig& config, const ReproduceOptions& options);

// Sum of the optimisation iterations a method reported in its stats (Gabor: per stage).
int total_iterations(const nlohmann::json& stats);

}  // namespace ppsynth
