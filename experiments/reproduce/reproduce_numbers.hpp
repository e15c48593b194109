#pragma once
// The numbers a paper item's verdict reads (experiments/report/reproduce_verdict.hpp), per
// group "panel/column", metric and seed: with --seeds from every run of the sweep (each run's
// metrics.json as gather pooled it, its overlapping disk pairs and iterations, and its
// initialization evaluated as the group "panel/init"); without, from the report's own
// columns (one seed). A panel's published output ("reference" file) is a group drawn once.
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/reproduce_results.hpp"
#include "optim/run/run_store.hpp"

namespace ppsynth {

ItemNumbers collect_item_numbers(const ReproduceConfig& config, const ReproduceResult& result);

// Sum of the optimization iterations a run reported: over its stages (Gabor), else from its
// method's typed stats (roveri2015: merging steps per scale; pcf2017: its descents' steps, every
// class's on a rectangle). InputError naming its run.json for stats its method cannot read,
// its config.json for a malformed method type (optim/run/run_options_of.hpp).
int total_iterations(const RunOutcome& run);

}  // namespace ppsynth
