// `ppsynth eval --exemplar E --output O [--json] [--out FILE] [--protocol auto|quadrants|crops]
// [--crops N] [--crop-seed S]`: the evaluation suite (core/metrics/evaluation.hpp) of an
// output against its exemplar: PCF MSE, Wasserstein and Chamfer over patches of the output
// (the paper's 4 quadrants, or N random exemplar-sized crops for rectangles and other sizes:
// core/metrics/eval_protocol.hpp), all classes, per class, cross-class PCF, relative radius,
// disk overlaps, border share; spatstat's K, L, g and mark correlations in exemplar units
// (core/metrics/second_order_report.hpp) and the verdict, a p-value per row for "is the output
// a plausible realization of the exemplar's process?" (core/metrics/verdict.hpp, docs/explanation/verdict.md),
// and the scorecard: novelty (is it a copy of the exemplar?), fidelity (its L and g distances in
// spreads of independent realizations, core/metrics/fidelity.hpp), periodicity (does it repeat with
// the exemplar's period?), the border profile, close pairs, and with --diversity OTHER whether
// it is a translate of another seed's output (core/metrics/novelty.hpp, periodicity.hpp,
// close_pairs.hpp, docs/explanation/scorecard.md).
// Human table by default; --json prints the full result (with curves).
// Sub-quadratic in the point count (k-d tree searches) except the exact Wasserstein, which
// is exact up to --wasserstein-exact-limit pairs per quadrant and a labeled subsample
// estimate beyond (core/metrics/wasserstein.hpp); inputs of 50,000+ points log progress.
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/atomic_file.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/class_match.hpp"
#include "core/metrics/novelty.hpp"

namespace {

struct Args {
  std::string exemplar, output, out_file, format = "auto", protocol = "auto", diversity;
  int crops = ppsynth::kDefaultCrops;
  uint64_t crop_seed = ppsynth::kDefaultCropSeed;
  bool json = false, force = false, no_curves = false, spectrum = false, periodic = false, no_verdict = false, no_second_order = false,
       no_scorecard = false;
  ppsynth::VerdictOptions verdict;
  ppsynth::NoveltyOptions novelty;
  ppsynth::PeriodicityOptions periodicity;
  ppsynth::FidelityOptions fidelity;
  int bins = 100;
  double r_max = 0, zoom = 0;
  size_t wasserstein_pairs = ppsynth::kWassersteinExactPairs;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<Args>();
  app.add_option("--exemplar", a->exemplar, "exemplar point file (\"shared:...\" allowed)")
      ->required()
      ->check(ppsynth::app::path_text());
  app.add_option("--output", a->output, "synthesized point file to evaluate")->required()->check(ppsynth::app::path_text());
  app.add_option("--format", a->format, "input format of both files: auto (detect), gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_flag("--json", a->json, "print the full result as JSON instead of a table");
  app.add_option("--out", a->out_file, "also write the JSON result to this file (atomically; never over an input)")
      ->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace an existing --out file");
  app.add_flag("--no-curves", a->no_curves, "leave the PCF curves out of the JSON");
  app.add_flag("--spectrum", a->spectrum, "add radially averaged power spectra");
  app.add_flag("--periodic-pcf", a->periodic, "PCF on the torus (default: rectangle, edge-corrected)");
  app.add_option("--bins", a->bins, "PCF radii (default 100)");
  app.add_option("--r-max", a->r_max, "PCF r_max in unit-square units, in (0, 1] (default: from the exemplar's count)");
  app.add_option("--wasserstein-exact-limit", a->wasserstein_pairs,
                 "exact Wasserstein up to this many exemplar x patch point pairs per quadrant (default 4000000, "
                 "~0.5 s each); beyond, a labeled subsample estimate");
  app.add_option("--protocol", a->protocol,
                 "patches compared with the exemplar: auto (quadrants for a square output of 3-5 x the exemplar's "
                 "points, else crops), quadrants (the paper's), crops (random exemplar-sized crops)")
      ->capture_default_str();
  app.add_option("--crops", a->crops, "crops protocol: number of crops, 1..10000")->capture_default_str();
  app.add_option("--crop-seed", a->crop_seed, "crops protocol: seed of the crop positions, 0 to 2^63 - 1")
      ->capture_default_str()
      ->check(ppsynth::app::seed_number());
  app.add_option("--zoom", a->zoom,
                 "crops protocol: output units per exemplar unit (0.5 for the paper's u = 2 square, 1 for a rectangle in "
                 "exemplar units; default 0: from the two densities, which rescales an output made at another density)")
      ->capture_default_str();
  app.add_flag("--no-second-order", a->no_second_order, "leave out K, L, g and the mark correlations (spatstat's estimators)");
  app.add_flag("--no-verdict", a->no_verdict, "leave out the verdict (the two-sample test per class and class pair)");
  app.add_option("--verdict-split", a->verdict.split, "verdict: the exemplar cut into N x N sub-windows, 1..20")
      ->capture_default_str();
  app.add_option("--verdict-guard", a->verdict.guard,
                 "verdict: share of a sub-window cell's side left out between sub-windows, 0..0.9")
      ->capture_default_str();
  app.add_option("--verdict-permutations", a->verdict.permutations, "verdict: random reassignments, up to 1000000, with 1/(1 + N) below --verdict-alpha (at least 20 at 0.05)")
      ->capture_default_str();
  app.add_option("--verdict-seed", a->verdict.seed, "verdict: seed of the reassignments, 0 to 2^63 - 1")
      ->capture_default_str()
      ->check(ppsynth::app::seed_number());
  app.add_option("--verdict-alpha", a->verdict.alpha, "verdict: a row passes when p >= alpha")->capture_default_str();
  app.add_flag("--no-scorecard", a->no_scorecard, "leave out the scorecard (novelty: is the output a copy?; fidelity; periodicity; border; close pairs)");
  app.add_option("--novelty-k", a->novelty.k, "scorecard: neighbours per neighbourhood compared, 1..64")->capture_default_str();
  app.add_option("--novelty-tolerance", a->novelty.tolerance,
                 "scorecard: a neighbourhood matches within this many exemplar mean nearest-neighbour distances, (0, 1]")
      ->capture_default_str();
  app.add_option("--novelty-copy-share", a->novelty.copy_share,
                 "scorecard: the output is flagged a copy when this share of its points match, (0, 1]")
      ->capture_default_str();
  app.add_option("--fidelity-band", a->fidelity.band,
                 "scorecard: fidelity's band, in spreads (the median distance independent realizations show), of a row "
                 "that is not clustered; a clustered row's is this times its clustering^(1/4); the default leaves out 5 % "
                 "of independent realizations per distance, as measured, [1, 100]")
      ->capture_default_str();
  app.add_option("--fidelity-windows", a->fidelity.windows,
                 "scorecard: random exemplar sub-windows that estimate fidelity's spread, 16..4096")
      ->capture_default_str();
  app.add_option("--fidelity-side", a->fidelity.side,
                 "scorecard: those sub-windows' sides, as a fraction of the exemplar's, [0.2, 0.8]")
      ->capture_default_str();
  app.add_option("--periodicity-harmonics", a->periodicity.harmonics,
                 "scorecard: harmonics of the exemplar's period compared along each axis, 1..64")
      ->capture_default_str();
  app.add_option("--periodic-ratio", a->periodicity.periodic_ratio,
                 "scorecard: the output is flagged periodic from this ratio (its median periodogram at the exemplar's period "
                 "and harmonics over the median between them), > 1")
      ->capture_default_str();
  app.add_option("--diversity", a->diversity,
                 "scorecard: another output of the same exemplar (another seed): are the two translates of each other?")
      ->check(ppsynth::app::path_text());
  return [a]() {
    ppsynth::EvalOptions opt;
    opt.protocol = ppsynth::parse_patch_protocol(a->protocol);
    opt.crops = a->crops;
    opt.crop_seed = a->crop_seed;
    opt.zoom = a->zoom;
    opt.include_curves = !a->no_curves;
    opt.spectrum = a->spectrum;
    opt.pcf.periodic = a->periodic;
    opt.pcf.bins = a->bins;
    opt.pcf.r_max = a->r_max;
    opt.wasserstein_max_pairs = a->wasserstein_pairs;
    opt.second_order = !a->no_second_order;
    opt.verdict = !a->no_verdict;
    opt.verdict_options = a->verdict;
    opt.scorecard = !a->no_scorecard;
    opt.novelty = a->novelty;
    opt.periodicity = a->periodicity;
    opt.fidelity = a->fidelity;
    if (!a->diversity.empty() && a->no_scorecard)
      throw ppsynth::InputError("--diversity is a line of the scorecard: it cannot go with --no-scorecard");
    ppsynth::check_eval_options(opt);  // before reading: a bad option is reported first
    std::vector<ppsynth::app::NamedPath> inputs = {{"--exemplar", a->exemplar}, {"--output", a->output}};
    if (!a->diversity.empty()) inputs.push_back({"--diversity", a->diversity});
    ppsynth::app::check_output_files({{"--out", a->out_file}}, inputs, a->force);
    ppsynth::ReadOptions ro;
    ro.format = ppsynth::parse_format(a->format);
    ppsynth::PointSet ex = ppsynth::read_points(a->exemplar, ro);
    ppsynth::PointSet out = ppsynth::read_points(a->output, ro);
    ppsynth::PointSet other;
    if (!a->diversity.empty()) {
      other = ppsynth::read_points(a->diversity, ro);
      if (other.empty()) throw ppsynth::InputError(a->diversity + ": --diversity: the other output is empty");
    }
    nlohmann::json r = ppsynth::evaluate(ex, out, opt);
    r["exemplar"]["path"] = ppsynth::shown_text(a->exemplar);  // any file name can be written as JSON
    r["output"]["path"] = ppsynth::shown_text(a->output);
    if (!a->diversity.empty()) {  // at the output's zoom: two seeds of one run share it
      r["scorecard"]["diversity"] = ppsynth::diversity_report(ex, ppsynth::match_classes(ex, out).output,
                                                              ppsynth::match_classes(ex, other).output,
                                                              r["protocol"]["zoom"].get<double>(), opt.novelty);
      r["scorecard"]["diversity"]["other"] = ppsynth::shown_text(a->diversity);
    }
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

PPSYNTH_COMMAND("eval", "metrics of an output against its exemplar (PCF, Wasserstein, Chamfer over quadrants or crops, ...)", setup)
