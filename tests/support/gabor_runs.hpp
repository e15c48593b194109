#pragma once
// Test support: an in-process run of a method that keeps every checkpoint (one per
// iteration and stage boundary), resumed from given bytes when asked; and a method spec
// merged with its defaults as a run resolves it.
#include <catch2/catch.hpp>

#include <atomic>
#include <string>
#include <vector>

#include "optim/method/method.hpp"

namespace ppsynth::test {

struct CheckpointedRun {
  PointSet output;
  std::vector<std::string> checkpoints;  // every one saved, in order
  json stats;
  StagesReport report;  // the stages, typed
};

// `method_spec` with --quick, seed `seed`, a checkpoint at every iteration; on `output` when
// given, else on the paper's u x u square.
inline CheckpointedRun checkpointed_run(const json& method_spec, const PointSet& ex, uint64_t seed,
                                        const std::string* resume = nullptr, const std::atomic<bool>* stop = nullptr,
                                        const OutputShape* output = nullptr) {
  auto method = MethodRegistry::instance().create(method_spec, "method");
  REQUIRE(method->can_resume());
  CheckpointedRun run;
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = seed;
  ctx.stats = &run.stats;
  ctx.stages = &run.report;
  ctx.checkpoint_seconds = 0;  // every iteration
  ctx.save_checkpoint = [&](const std::string& bytes) { run.checkpoints.push_back(bytes); };
  ctx.resume_state = resume;
  ctx.stop = stop;
  if (output) ctx.output = *output;
  run.output = method->synthesize(ex, ctx);
  return run;
}

// The method's params as the run sees them (defaults merged, checked against their bounds).
inline json method_params(const json& spec) {
  json m;
  MethodRegistry::instance().create(spec, "method", &m);
  return m;
}

}  // namespace ppsynth::test
