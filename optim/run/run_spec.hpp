#pragma once
// RunSpec: one synthesis as resolved once, from a resolved run config (run_config.hpp): the
// exemplar read (its file once, with the format it was read as), the output shape, the seed,
// the config's keys read through their tables (the run's options: evaluate, snapshots,
// checkpoint_seconds, runtime) and the method built. The run layer (run_synthesis.hpp), the
// checkpoint key and the log read it instead of each reading the file, resolving the shape,
// reading a key of the JSON or building the method again.
#include <cstdint>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/formats/format_options.hpp"
#include "core/output_shape.hpp"
#include "core/point_set.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_config.hpp"

namespace ppsynth {

struct RunSpec {
  // The resolved run config (resolve_run_config) as written: config.json and the checkpoint
  // key hold it; what the run does follows `options`, read from it.
  nlohmann::json config;
  RunOptions options;     // config read through RunOptions' table, once
  PointSet exemplar;      // as synthesized: scaled, classes merged when the config says so
  // The format its file was read as: an exemplar in the published integer format gets its
  // output in that format too (run_store.hpp, output.gabor.txt). Plain for one given in memory.
  Format exemplar_format = Format::Plain;
  OutputShape shape;      // the config's "upscale" and "output" over this exemplar
  uint64_t seed = 0;
  // Built once from config["method"]; shared so that a spec copies (a method is reusable).
  std::shared_ptr<SynthesisMethod> method;
};

// Reads the exemplar file `resolved` names (load_exemplar), once, and resolves the rest.
RunSpec load_run_spec(const nlohmann::json& resolved);

// With the exemplar at hand (in memory, or a run directory's copy of it). Refuses, before any
// work, an output that cannot be made: one that would hold no point (a rectangle smaller than
// one point's share at the exemplar's density), one whose evaluation cannot run (config
// "evaluate" on a rectangle narrower or lower than the exemplar: the evaluation measures
// exemplar-sized crops), one whose points would not fit in memory (core/memory_budget.hpp).
// Errors name the key (output.size, output.points, evaluate).
RunSpec make_run_spec(const nlohmann::json& resolved, PointSet exemplar, Format exemplar_format = Format::Plain);

}  // namespace ppsynth
