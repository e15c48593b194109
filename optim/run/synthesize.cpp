#include "optim/run/synthesize.hpp"

#include <chrono>

#include "core/checkpoint_file.hpp"
#include "core/content_hash.hpp"
#include "core/formats/point_io.hpp"
#include "core/process_cpu.hpp"
#include "core/metrics/evaluation.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/runtime.hpp"

namespace ppsynth {

namespace {

// Keeps the initial output (the first event of every run, resumed or not).
struct InitialRecorder : SynthesisObserver {
  PointSet initial;
  void on_start(const PointSet& p) override { initial = p; }
};

}  // namespace

bool can_resume(const nlohmann::json& spec) {
  return MethodRegistry::instance().create(spec["method"], "method")->can_resume();
}

nlohmann::json checkpoint_key(const RunSpec& spec, bool quick) {
  const nlohmann::json& config = spec.config;
  return {{"method", spec.options.method["type"]},
          {"method_version", spec.method->version()},
          {"seed", spec.seed},
          {"quick", quick},
          {"exemplar", content_hash(format_points(spec.exemplar, Format::Plain))},
          {"config_hash", content_hash(config.dump())},
          {"config", config}};
}

void check_checkpoint(const std::string& bytes, const std::string& source, const nlohmann::json& key) {
  const CheckpointFile f = decode_checkpoint(bytes, source);
  if (const std::string differs = checkpoint_key_difference(key, f.key); !differs.empty())
    throw checkpoint_error(source, "made for another synthesis: " + differs);
}

SynthesisResult synthesize(const RunSpec& run, const SynthesisOptions& options) {
  using Clock = std::chrono::steady_clock;
  const RunOptions& spec = run.options;
  SynthesisMethod& method = *run.method;
  SynthesisContext ctx;
  // The caller's options as they are, but a method that cannot resume neither checkpoints nor
  // stops at a signal (it runs to its end; the run layer says so).
  static_cast<SynthesisOptions&>(ctx) = options;
  if (!method.can_resume()) ctx.save_checkpoint = nullptr, ctx.resume_state = nullptr, ctx.stop = nullptr;
  ctx.seed = run.seed;
  ctx.output = run.shape;
  const DeviceSettings device = apply_device_settings(spec.runtime);
  ctx.device = device.device;
  ctx.tf32 = device.tf32;
  ctx.deterministic = device.deterministic;
  const auto from_file = options.initialization ? std::nullopt : load_initialization(run.config);
  ctx.initialization = options.initialization ? options.initialization : from_file ? &*from_file : nullptr;
  InitialRecorder initial;
  ctx.observers.push_back(&initial);
  SynthesisResult r;
  ctx.stats = &r.stats;
  StagesReport stages;
  ctx.stages = &stages;
  if (method.can_resume()) {
    ctx.checkpoint_seconds = spec.checkpoint_seconds;
    ctx.checkpoint_key = checkpoint_key(run, options.quick);
    if (options.resume_state) check_checkpoint(*options.resume_state, options.resume_source, ctx.checkpoint_key);
  } else if (options.resume_state) {
    throw InputError("the method " + spec.method.value("type", std::string("?")) + " cannot resume a checkpoint");
  }
  const auto t0 = Clock::now();
  const double cpu0 = process_cpu_seconds();
  r.output = method.synthesize(run.exemplar, ctx);
  // A resumed run's time includes its earlier processes' (up to their last checkpoint).
  r.seconds_before_resume = stages.seconds_before_resume;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count() + r.seconds_before_resume;
  // 0 (not recorded) when the processes before a resume did not keep theirs.
  if (stages.cpu_seconds_before_resume >= 0) r.cpu_seconds = process_cpu_seconds() - cpu0 + stages.cpu_seconds_before_resume;
  r.initialization = std::move(initial.initial);
  r.stages = std::move(stages.stages);
  if (r.output.empty())  // a rectangle of a point or two whose points all parked outside it
    throw config_error(spec.output.size.is_null() ? "output.points" : "output.size",
                       "the synthesis left no point inside the output (" + ctx.output.describe() + "); give a larger output");
  if (spec.evaluate) {
    // As `ppsynth eval` evaluates the two files (the zoom from their densities), so that a
    // run's metrics.json and eval on its output are one answer whatever the exemplar's domain.
    r.metrics = evaluate(run.exemplar, r.output, EvalOptions{});
  }
  return r;
}

SynthesisResult synthesize(const PointSet& exemplar, const nlohmann::json& spec, const SynthesisOptions& options) {
  return synthesize(make_run_spec(spec, exemplar), options);
}

}  // namespace ppsynth
