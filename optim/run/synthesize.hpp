#pragma once
// The in-memory synthesis: exemplar in, result out, no files, no command. Every front end
// (the `ppsynth` command through run_synthesis.hpp, a Python module, a sweep runner, a test)
// calls this; the run directory, reports and reproduce plans are built on top of it.
//
//   exemplar --spec (resolve_run_config)--> SynthesisMethod (registered by "method.type")
//            --observers: progress, losses, snapshots--> output --evaluate--> metrics
//
// A spec is a resolved run config (optim/run/run_config.hpp); its "exemplar" key is not used
// here (the exemplar is given), its "method", "seed", "upscale", "init_file" and "evaluate" are.
// The run layer resolves it with its exemplar once into a RunSpec (optim/run/run_spec.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_spec.hpp"

namespace ppsynth {

struct SynthesisResult {
  PointSet initialization;           // the output before optimization
  PointSet output;                   // in the unit square, with classes and attributes
  // Each finished stage of a method that works in stages (the Gabor method's classes and
  // sigmas; none for the one-shot baselines): iterations, final loss, wall time, its details.
  std::vector<StageRecord> stages;
  nlohmann::json stats;              // the rest the method measured (grid, sigmas, phase times, ...)
  nlohmann::json metrics;            // evaluate(exemplar, output) when the spec asks, else null
  double seconds = 0;                // wall time of the synthesis (metrics excluded), over every process of a resumed run
  double seconds_before_resume = 0;  // the part of `seconds` spent by the processes before a resume
  // CPU time of the synthesis (core/process_cpu.hpp), over every process of a resumed run:
  // unlike `seconds` it does not grow when other work shares the cores. 0: not known (resumed
  // from a checkpoint that did not keep it).
  double cpu_seconds = 0;
};

// Runs the spec's method on its exemplar. Same spec, seed, exemplar and thread count give the
// same output, bit for bit, resumed or not. Errors are InputError naming the key.
SynthesisResult synthesize(const RunSpec& spec, const SynthesisOptions& options = {});
// The same with the exemplar at hand: make_run_spec(spec, exemplar), then the above (an output
// that cannot be made is refused before any work, run_spec.hpp).
SynthesisResult synthesize(const PointSet& exemplar, const nlohmann::json& spec, const SynthesisOptions& options = {});

// True when the spec's method checkpoints (and so honors SynthesisOptions::stop).
bool can_resume(const nlohmann::json& spec);

// What a checkpoint of `spec` carries to prove where it belongs (core/checkpoint_file.hpp):
// the method and its version, the seed, the quick setting, a content hash of the exemplar's
// points, and the resolved config with its hash.
nlohmann::json checkpoint_key(const RunSpec& spec, bool quick);

// Refuses (CheckpointError naming `source`) a checkpoint that is damaged or of another
// synthesis than `key`'s, saying what differs. Cheap: the arrays are checked, not restored.
void check_checkpoint(const std::string& bytes, const std::string& source, const nlohmann::json& key);

}  // namespace ppsynth
