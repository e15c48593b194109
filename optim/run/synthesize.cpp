#include "optim/run/synthesize.hpp"

#include <chrono>

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

std::vector<StageResult> stage_results(const nlohmann::json& stats) {
  std::vector<StageResult> v;
  if (!stats.is_object() || !stats.contains("stages")) return v;
  for (const auto& s : stats["stages"])
    v.push_back({s.value("stage", ""), s.value("iterations", 0), s.value("final_loss", 0.0), s.value("seconds", 0.0)});
  return v;
}

}  // namespace

bool can_resume(const nlohmann::json& spec) {
  return MethodRegistry::instance().create(spec["method"], "method")->can_resume();
}

SynthesisResult synthesize(const PointSet& exemplar, const nlohmann::json& spec, const SynthesisOptions& options) {
  using Clock = std::chrono::steady_clock;
  auto method = MethodRegistry::instance().create(spec["method"], "method");
  SynthesisContext ctx;
  ctx.seed = spec["seed"].get<uint64_t>();
  ctx.output = resolve_output_shape(spec, exemplar);
  ctx.quick = options.quick;
  // A config resolved before "runtime" existed (an older run directory's) runs on the CPU.
  const DeviceSettings device = apply_device_settings(spec.value("runtime", runtime_defaults()));
  ctx.device = device.device;
  ctx.tf32 = device.tf32;
  ctx.deterministic = device.deterministic;
  const auto from_file = options.initialization ? std::nullopt : load_initialization(spec);
  ctx.initialization = options.initialization ? options.initialization : from_file ? &*from_file : nullptr;
  InitialRecorder initial;
  ctx.observers = options.observers;
  ctx.observers.push_back(&initial);
  SynthesisResult r;
  ctx.stats = &r.stats;
  if (method->can_resume()) {
    ctx.save_checkpoint = options.save_checkpoint;
    ctx.checkpoint_seconds = spec["checkpoint_seconds"].get<double>();
    ctx.resume_state = options.resume_state;
    ctx.stop = options.stop;
  } else if (options.resume_state) {
    throw InputError("the method " + spec["method"].value("type", std::string("?")) + " cannot resume a checkpoint");
  }
  const auto t0 = Clock::now();
  r.output = method->synthesize(exemplar, ctx);
  // A resumed run's time includes its earlier processes' (up to their last checkpoint).
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count() +
              (r.stats.is_object() ? r.stats.value("seconds_before_resume", 0.0) : 0.0);
  r.initialization = std::move(initial.initial);
  r.stages = stage_results(r.stats);
  if (spec["evaluate"].get<bool>()) {
    EvalOptions eo;
    eo.zoom = ctx.output.zoom();  // crops at the scale the output was made at, whatever its density
    r.metrics = evaluate(exemplar, r.output, eo);
  }
  return r;
}

}  // namespace ppsynth
