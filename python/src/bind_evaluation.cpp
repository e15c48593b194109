// evaluate(): the evaluation suite of `ppsynth eval` (core/metrics/evaluation.hpp), returned as
// the nested dict of what `eval --json` prints; the package makes it a ppsynth.Evaluation.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "json_python.hpp"
#include "core/metrics/eval_protocol.hpp"
#include "core/metrics/evaluation.hpp"

namespace ppsynth::python {

void bind_evaluation(py::module_& m) {
  m.def(
      "evaluate",
      [](const py::dict& exemplar, const py::dict& output, int bins, double r_max, bool periodic_pcf, bool curves,
         bool spectrum, size_t wasserstein_exact_limit, const std::string& protocol, int crops, uint64_t crop_seed,
         double zoom) {
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
        check_eval_options(opt);
        const PointSet ex = from_python(exemplar, "exemplar");
        const PointSet out = from_python(output, "output");
        validate(ex, "exemplar");
        validate(out, "output");
        nlohmann::json r;
        {
          py::gil_scoped_release unlocked;  // seconds on large sets; nothing here touches Python
          r = evaluate(ex, out, opt);
        }
        return r;
      },
      py::arg("exemplar"), py::arg("output"), py::arg("bins"), py::arg("r_max"), py::arg("periodic_pcf"),
      py::arg("curves"), py::arg("spectrum"), py::arg("wasserstein_exact_limit"), py::arg("protocol"), py::arg("crops"),
      py::arg("crop_seed"), py::arg("zoom"));
  m.attr("WASSERSTEIN_EXACT_PAIRS") = kWassersteinExactPairs;
}

}  // namespace ppsynth::python
