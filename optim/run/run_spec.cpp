#include "optim/run/run_spec.hpp"

#include <cstdio>

#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/memory_budget.hpp"
#include "optim/run/run_config.hpp"

namespace ppsynth {

namespace {

// make_run_spec's refusals (run_spec.hpp), from the spec's resolved shape.
void check_synthesis_size(const RunSpec& spec) {
  const PointSet& exemplar = spec.exemplar;
  const OutputShape& shape = spec.shape;
  const std::string key = spec.options.output.size.is_null() ? "output.points" : "output.size";
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
    if (spec.options.evaluate && (shape.width < E.width() * kFit || shape.height < E.height() * kFit)) {
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

}  // namespace

RunSpec make_run_spec(const nlohmann::json& resolved, PointSet exemplar, Format exemplar_format) {
  RunSpec s;
  s.config = resolved;
  s.options = RunOptions::params().read(s.config);
  s.exemplar = std::move(exemplar);
  s.exemplar_format = exemplar_format;
  s.shape = resolve_output_shape(s.config, s.exemplar);
  check_synthesis_size(s);
  s.seed = s.options.seed.get<uint64_t>();
  s.method = MethodRegistry::instance().create(s.options.method, "method");
  return s;
}

RunSpec load_run_spec(const nlohmann::json& resolved) {
  Format read_as = Format::Plain;
  PointSet exemplar = load_exemplar(resolved, &read_as);
  return make_run_spec(resolved, std::move(exemplar), read_as);
}

}  // namespace ppsynth
