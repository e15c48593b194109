#include "optim/run/synthesize.hpp"

#include <chrono>
#include <cstdio>

#include "core/checkpoint_file.hpp"
#include "core/content_hash.hpp"
#include "core/formats/point_io.hpp"
#include "core/memory_budget.hpp"
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

void check_synthesis_size(const nlohmann::json& spec, const PointSet& exemplar) {
  const OutputShape shape = resolve_output_shape(spec, exemplar);
  const std::string key = spec["output"]["size"].is_null() ? "output.points" : "output.size";
  const Domain E = exemplar.domain(), out = shape.domain();
  char size[96];
  std::snprintf(size, sizeof size, "%g x %g exemplar units", shape.width, shape.height);
  if (shape.rectangle) {
    const double expected = static_cast<double>(exemplar.size()) * out.area() / E.area();
    if (expected < 1) {
      char what[256];
      std::snprintf(what, sizeof what, "%s hold about %.2g points at the exemplar's density; an output needs at least one",
                    size, expected);
      throw config_error(key, what);
    }
    constexpr double kFit = 1 - 1e-9;  // crops as large as the output up to rounding fit (core/metrics/crops.cpp)
    if (spec["evaluate"].get<bool>() && (shape.width < E.width() * kFit || shape.height < E.height() * kFit)) {
      char what[320];
      std::snprintf(what, sizeof what,
                    "%s is smaller than the exemplar (%g x %g) on a side, and the run's evaluation measures "
                    "exemplar-sized crops of the output: give at least %g x %g, or --set evaluate=false",
                    size, E.width(), E.height(), E.width(), E.height());
      throw config_error(key, what);
    }
  }
  // What every point costs while the synthesis holds it: its position, class and attributes in
  // the output and the canvas, the tensors of the positions, the copies a checkpoint
  // serializes, and the initialization's search grid.
  constexpr double kBytesPerPoint = 256;
  double points = 0;
  for (size_t n : shape.class_counts(exemplar, shape.canvas())) points += static_cast<double>(n);
  const double per_point = kBytesPerPoint + 16.0 * exemplar.num_attributes();
  // The pad counts: a 1 x 1 output padded by 100 is a 201 x 201 canvas to initialize and move.
  const Domain canvas = shape.canvas();
  char pad[160] = "";
  if (shape.rectangle && shape.pad > 0)
    std::snprintf(pad, sizeof pad, ", output.pad %g: a %g x %g canvas", shape.pad, canvas.width(), canvas.height());
  char what[320];
  std::snprintf(what, sizeof what, "an output of %.3g points (%s%s)", points,
                shape.rectangle ? (key + " " + size).c_str() : ("upscale " + std::to_string(shape.upscale)).c_str(), pad);
  check_memory(points * per_point, what);
}

nlohmann::json checkpoint_key(const nlohmann::json& spec, const PointSet& exemplar, bool quick) {
  return {{"method", spec["method"]["type"]},
          {"method_version", MethodRegistry::instance().create(spec["method"], "method")->version()},
          {"seed", spec["seed"]},
          {"quick", quick},
          {"exemplar", content_hash(format_points(exemplar, Format::Plain))},
          {"config_hash", content_hash(spec.dump())},
          {"config", spec}};
}

void check_checkpoint(const std::string& bytes, const std::string& source, const nlohmann::json& key) {
  const CheckpointFile f = decode_checkpoint(bytes, source);
  if (const std::string differs = checkpoint_key_difference(key, f.key); !differs.empty())
    throw checkpoint_error(source, "made for another synthesis: " + differs);
}

SynthesisResult synthesize(const PointSet& exemplar, const nlohmann::json& spec, const SynthesisOptions& options) {
  using Clock = std::chrono::steady_clock;
  check_synthesis_size(spec, exemplar);
  auto method = MethodRegistry::instance().create(spec["method"], "method");
  SynthesisContext ctx;
  // The caller's options as they are, but a method that cannot resume neither checkpoints nor
  // stops at a signal (it runs to its end; the run layer says so).
  static_cast<SynthesisOptions&>(ctx) = options;
  if (!method->can_resume()) ctx.save_checkpoint = nullptr, ctx.resume_state = nullptr, ctx.stop = nullptr;
  ctx.seed = spec["seed"].get<uint64_t>();
  ctx.output = resolve_output_shape(spec, exemplar);
  // A config resolved before "runtime" existed (an older run directory's) runs on the CPU.
  const DeviceSettings device = apply_device_settings(spec.value("runtime", runtime_defaults()));
  ctx.device = device.device;
  ctx.tf32 = device.tf32;
  ctx.deterministic = device.deterministic;
  const auto from_file = options.initialization ? std::nullopt : load_initialization(spec);
  ctx.initialization = options.initialization ? options.initialization : from_file ? &*from_file : nullptr;
  InitialRecorder initial;
  ctx.observers.push_back(&initial);
  SynthesisResult r;
  ctx.stats = &r.stats;
  StagesReport stages;
  ctx.stages = &stages;
  if (method->can_resume()) {
    ctx.checkpoint_seconds = spec["checkpoint_seconds"].get<double>();
    ctx.checkpoint_key = checkpoint_key(spec, exemplar, options.quick);
    if (options.resume_state) check_checkpoint(*options.resume_state, options.resume_source, ctx.checkpoint_key);
  } else if (options.resume_state) {
    throw InputError("the method " + spec["method"].value("type", std::string("?")) + " cannot resume a checkpoint");
  }
  const auto t0 = Clock::now();
  r.output = method->synthesize(exemplar, ctx);
  // A resumed run's time includes its earlier processes' (up to their last checkpoint).
  r.seconds_before_resume = stages.seconds_before_resume;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count() + r.seconds_before_resume;
  r.initialization = std::move(initial.initial);
  r.stages = std::move(stages.stages);
  if (r.output.empty())  // a rectangle of a point or two whose points all parked outside it
    throw config_error(spec["output"]["size"].is_null() ? "output.points" : "output.size",
                       "the synthesis left no point inside the output (" + ctx.output.describe() + "); give a larger output");
  if (spec["evaluate"].get<bool>()) {
    // As `ppsynth eval` evaluates the two files (the zoom from their densities), so that a
    // run's metrics.json and eval on its output are one answer whatever the exemplar's domain.
    r.metrics = evaluate(exemplar, r.output, EvalOptions{});
  }
  return r;
}

}  // namespace ppsynth
