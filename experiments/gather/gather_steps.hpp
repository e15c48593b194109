#pragma once
// The steps of gather_runs (gather.hpp), one file each: collect (gather_collect.cpp: find the
// runs, group them, take their numbers) and statistics (gather_statistics.cpp: per group over
// seeds, against references and baselines); the writers (gather_writers.cpp) print and write
// the result. Internal to experiments/gather.
#include <string>
#include <vector>

#include "core/metrics/evaluation.hpp"
#include "experiments/gather/gather.hpp"

namespace ppsynth {

// Every finished run under `dirs` (and each stage's snapshots), with its numbers, grouped and
// labeled; GatherResult::summaries and ::comparisons are left empty.
GatherResult collect_runs(const std::vector<std::string>& dirs, const GatherOptions& options);
// The summaries and comparisons of r.runs (r.options' references, bound and baselines).
void summarize_groups(GatherResult& r);

// How gather evaluates an output itself (a reference; every run with --protocol): the
// evaluation's defaults, the protocol if one is asked for, no curves.
EvalOptions evaluation_options(const GatherOptions& g);
// "each run's metrics.json" or the protocol every output was evaluated with again.
std::string evaluation_text(const GatherOptions& g);

}  // namespace ppsynth
