#pragma once
// Runs a paper experiment (reproduce_config.hpp) into a report directory:
//
//   <out>/index.html          self-contained report (report_writer.hpp)
//   <out>/metrics.{csv,md}    every panel x method column: PCF MSE, Wasserstein, Chamfer, ...
//   <out>/<table>.{csv,md}    the paper-layout tables the config asks for (Tables 1-3)
//   <out>/report.json         every number of the report, machine-readable
//   <out>/figure.png          overview: exemplar and outputs side by side, as in the paper
//   <out>/panels/<panel>/     exemplar plots, PCF comparison, map images (Fig. 3), and one
//                             run directory per synthesized column (run_synthesis.hpp)
//
// The directory is built as "<out>.partial" and renamed when complete (a failed run keeps the
// previous report). Panels run in config order, each column of a panel on the same exemplar;
// "ours" runs first so "init" can show its initialization. --quick runs every synthesis with
// the methods' quick settings and shrinks generators and map grids (tests, smoke runs).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/reproduce_results.hpp"
#include "experiments/reproduce/reproduce_numbers.hpp"  // total_iterations

namespace ppsynth {

// Runs every panel and writes the report (with --seeds, after the sweep over seeds finished).
ReproduceResult run_reproduction(const ReproduceConfig& config, const ReproduceOptions& options);

}  // namespace ppsynth
