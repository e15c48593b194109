// evaluate(): the evaluation suite of `ppsynth eval` (core/metrics/evaluation.hpp), returned as
// the nested dict of what `eval --json` prints; the package makes it a ppsynth.Evaluation.
// It runs on the caller's thread with the GIL released; a PollScope (core/poll.hpp) takes the
// GIL every few hundredths of a second of its work to check for Ctrl-C, as the synthesis's
// PythonWatch does at every iteration (bind_synthesis.cpp), and a signal's exception (a
// KeyboardInterrupt) ends the evaluation and is raised when the call returns.
#include <pybind11/stl.h>

#include <chrono>
#include <memory>

#include "bindings.hpp"
#include "json_python.hpp"
#include "core/metrics/eval_protocol.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/poll.hpp"

namespace ppsynth::python {

namespace {

// Thrown through the evaluation when a signal handler raised: the Python error is kept here.
struct Interrupted {};

class SignalCheck {
 public:
  ~SignalCheck() {
    py::gil_scoped_acquire gil;  // the Python error held here goes with the GIL
    error_.reset();
  }
  // Without the GIL, from the evaluation's poll(): at most every kEvery, takes it and runs the
  // signal handlers.
  void operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < kEvery) return;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return;
    error_ = std::make_unique<py::error_already_set>();
    throw Interrupted{};
  }
  // With the GIL: raises what ended the evaluation.
  [[noreturn]] void raise() { throw py::error_already_set(*error_); }

 private:
  static constexpr std::chrono::milliseconds kEvery{20};
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::unique_ptr<py::error_already_set> error_;
};

}  // namespace

void bind_evaluation(py::module_& m) {
  m.def(
      "evaluate",
      [](const py::dict& exemplar, const py::dict& output, int bins, double r_max, bool periodic_pcf, bool curves,
         bool spectrum, size_t wasserstein_exact_limit, const std::string& protocol, int crops, uint64_t crop_seed,
         double zoom, bool second_order, bool verdict, int verdict_split, double verdict_guard,
         int verdict_permutations, uint64_t verdict_seed, double verdict_alpha) {
        EvalOptions opt;
        opt.pcf.bins = bins;
        opt.pcf.r_max = r_max;
        opt.pcf.periodic = periodic_pcf;
        opt.include_curves = curves;
        opt.spectrum = spectrum;
        opt.wasserstein_max_pairs = wasserstein_exact_limit;
        opt.protocol = parse_patch_protocol(protocol);
        opt.crops = crops;
        opt.crop_seed = crop_seed;
        opt.zoom = zoom;
        opt.second_order = second_order;
        opt.verdict = verdict;
        opt.verdict_options.split = verdict_split;
        opt.verdict_options.guard = verdict_guard;
        opt.verdict_options.permutations = verdict_permutations;
        opt.verdict_options.seed = verdict_seed;
        opt.verdict_options.alpha = verdict_alpha;
        check_eval_options(opt);
        const PointSet ex = from_python(exemplar, "exemplar");
        const PointSet out = from_python(output, "output");
        validate(ex, "exemplar");
        validate(out, "output");
        nlohmann::json r;
        SignalCheck check;
        try {
          py::gil_scoped_release unlocked;  // seconds to minutes on large sets
          const PollScope scope([&check] { check(); });
          r = evaluate(ex, out, opt);
        } catch (const Interrupted&) {
          check.raise();
        }
        return r;
      },
      py::arg("exemplar"), py::arg("output"), py::arg("bins"), py::arg("r_max"), py::arg("periodic_pcf"),
      py::arg("curves"), py::arg("spectrum"), py::arg("wasserstein_exact_limit"), py::arg("protocol"), py::arg("crops"),
      py::arg("crop_seed"), py::arg("zoom"), py::arg("second_order"), py::arg("verdict"), py::arg("verdict_split"),
      py::arg("verdict_guard"), py::arg("verdict_permutations"), py::arg("verdict_seed"), py::arg("verdict_alpha"));
  m.attr("WASSERSTEIN_EXACT_PAIRS") = kWassersteinExactPairs;
  // The verdict's defaults, as `ppsynth eval` takes them (core/metrics/verdict.hpp).
  const VerdictOptions v;
  py::dict defaults;
  defaults["split"] = v.split;
  defaults["guard"] = v.guard;
  defaults["permutations"] = v.permutations;
  defaults["seed"] = v.seed;
  defaults["alpha"] = v.alpha;
  m.attr("VERDICT_DEFAULTS") = defaults;
}

}  // namespace ppsynth::python
