#pragma once
// The report of a reproduction (`ppsynth reproduce NAME`), written into the report directory:
//   index.html   one self-contained page (images embedded): the paper's claim, the run's
//                metadata (config, revision, seeds, quick or full, wall time), which shipped
//                exemplar stands in for the paper's, the overview figure (exemplar and outputs
//                side by side), the paper-layout tables and the metrics table, then per panel:
//                the side-by-side plot, PCF comparison, per method the loss curve, PCF plot,
//                wall time, iterations, per-stage snapshots (when the panel asks: Fig. 4),
//                and the resolved run config; finally the figure config itself.
//   figure.png   the overview figure alone
//   metrics.{csv,md}, <table>.{csv,md}   (report_tables.hpp)
//   report.json  the numbers (metrics without curves), per panel and column
#include <string>

#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/reproduce_results.hpp"

namespace ppsynth {

// Into result.dir: index.html, report.json, the tables as CSV and Markdown.
void write_reproduce_report(const ReproduceConfig& config, const ReproduceResult& result, const ReproduceOptions& options);

}  // namespace ppsynth
