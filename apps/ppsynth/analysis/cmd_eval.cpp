// `ppsynth eval --exemplar E --output O [--json] [--out FILE]`: the evaluation suite
// (core/metrics/evaluation.hpp) of an output against its exemplar: quadrant PCF MSE,
// Wasserstein and Chamfer (all classes, per class, cross-class PCF), relative radius, disk
// overlaps. Human table by default; --json prints the full result (with PCF curves).
// Sub-quadratic in the point count (k-d tree searches) except the exact Wasserstein, which
// is exact up to --wasserstein-exact-limit pairs per quadrant and a labelled subsample
// estimate beyond (core/metrics/wasserstein.hpp); inputs of 50,000+ points log progress.
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/paths.hpp"

namespace {

struct Args {
  std::string exemplar, output, out_file, format = "auto";
  bool json = false, no_curves = false, spectrum = false, periodic = false;
  int bins = 100;
  double r_max = 0;
  size_t wasserstein_pairs = ppsynth::kWassersteinExactPairs;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<Args>();
  app.add_option("--exemplar", a->exemplar, "exemplar point file (\"shared:...\" allowed)")->required();
  app.add_option("--output", a->output, "synthesised point file to evaluate")->required();
  app.add_option("--format", a->format, "input format of both files: auto (detect), gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_flag("--json", a->json, "print the full result as JSON instead of a table");
  app.add_option("--out", a->out_file, "also write the JSON result to this file (atomically)");
  app.add_flag("--no-curves", a->no_curves, "leave the PCF curves out of the JSON");
  app.add_flag("--spectrum", a->spectrum, "add radially averaged power spectra");
  app.add_flag("--periodic-pcf", a->periodic, "PCF on the torus (default: rectangle, edge-corrected)");
  app.add_option("--bins", a->bins, "PCF radii (default 100)");
  app.add_option("--r-max", a->r_max, "PCF r_max in unit-square units, in (0, 1] (default: from the exemplar's count)");
  app.add_option("--wasserstein-exact-limit", a->wasserstein_pairs,
                 "exact Wasserstein up to this many exemplar x patch point pairs per quadrant (default 4000000, "
                 "~0.5 s each); beyond, a labelled subsample estimate");
  return [a]() {
    if (a->bins < 2 || a->bins > 10000) throw ppsynth::InputError("--bins must be in 2..10000");
    // r_max is in unit-square units (radii reach 2.5 r_max): beyond 1 every pair of every
    // point is within reach and the PCF turns quadratic; NaN/inf are refused too.
    if (!(a->r_max >= 0) || a->r_max > 1) throw ppsynth::InputError("--r-max must be in (0, 1] (0 = from the exemplar's count)");
    if (a->wasserstein_pairs < 1 || a->wasserstein_pairs > 400000000)
      throw ppsynth::InputError("--wasserstein-exact-limit must be in 1..400000000 pairs (a 3.2 GB cost matrix)");
    ppsynth::ReadOptions ro;
    ro.format = ppsynth::parse_format(a->format);
    ppsynth::PointSet ex = ppsynth::read_points(ppsynth::resolve_data_path(a->exemplar), ro);
    ppsynth::PointSet out = ppsynth::read_points(ppsynth::resolve_data_path(a->output), ro);
    ppsynth::EvalOptions opt;
    opt.include_curves = !a->no_curves;
    opt.spectrum = a->spectrum;
    opt.pcf.periodic = a->periodic;
    opt.pcf.bins = a->bins;
    opt.pcf.r_max = a->r_max;
    opt.wasserstein_max_pairs = a->wasserstein_pairs;
    nlohmann::json r = ppsynth::evaluate(ex, out, opt);
    r["exemplar"]["path"] = a->exemplar;
    r["output"]["path"] = a->output;
    if (!a->out_file.empty()) ppsynth::write_text_atomic(a->out_file, r.dump(2) + "\n");
    if (a->json)
      std::cout << r.dump(2) << "\n";
    else
      std::cout << "exemplar " << a->exemplar << "\noutput   " << a->output << "\n\n"
                << ppsynth::format_evaluation(r);
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("eval", "metrics of an output against its exemplar (quadrant PCF, Wasserstein, Chamfer, ...)", setup)
