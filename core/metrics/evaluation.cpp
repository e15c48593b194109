#include "core/metrics/evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/metrics/border.hpp"
#include "core/metrics/class_match.hpp"
#include "core/metrics/close_pairs.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/patches.hpp"
#include "core/metrics/periodicity.hpp"
#include "core/metrics/periodogram.hpp"
#include "core/metrics/second_order_report.hpp"
#include "core/metrics/spectrum.hpp"
#include "core/metrics/summary_stats.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Inputs from this many points (exemplar + output) log their progress.
constexpr size_t kProgressPoints = 50000;

// The metrics square distances (k-d tree, PCF) and map each set onto the unit square: a
// domain side outside 1e-100..1e100 overflows or underflows them (a 1e300-wide domain lost
// every neighbor, a 1e-310-wide one turned positions into NaN and hung the assignment).
void check_domain(const PointSet& ps, const char* which) {
  const Domain& d = ps.domain();
  for (double side : {d.width(), d.height()})
    if (!(side >= 1e-100 && side <= 1e100)) {
      std::ostringstream s;
      s << "evaluate: the " << which << "'s domain [" << d.x0 << "," << d.x1 << "]x[" << d.y0 << "," << d.y1
        << "] has a side of " << side << "; the metrics need sides in 1e-100..1e100 (rescale the coordinates)";
      throw InputError(s.str());
    }
  for (size_t i = 0; i < ps.size(); ++i)
    if (!std::isfinite(ps[i].x) || !std::isfinite(ps[i].y))
      throw InputError(std::string("evaluate: ") + which + " point " + std::to_string(i) + " has a non-finite coordinate");
}

// The scorecard's border line: the border profiles set_summary measured, output beside
// exemplar (gather reads them from "output" as border_density_*%).
json border_line(const json& r) {
  return {{"measures",
           "the density within each band of the border (fractions of the shorter side) over what uniform points put "
           "there: 1 uniform, > 1 points piled on the edge, < 1 a thin seam behind it (border.hpp)"},
          {"band", r["output"]["border_profile"]["band"]},
          {"exemplar", r["exemplar"]["border_profile"]["over_uniform"]},
          {"output", r["output"]["border_profile"]["over_uniform"]}};
}

json set_summary(const PointSet& ps) {
  json j;
  j["count"] = ps.size();
  j["border_fraction"] = num(border_fraction(ps));
  j["border_fraction_uniform"] = num(uniform_border_fraction(ps.domain()));
  const BorderProfile profile = border_profile(ps);
  json over = json::array();
  for (double v : profile.over_uniform) over.push_back(num(v));
  j["border_profile"] = {{"band", profile.band}, {"over_uniform", over}};
  j["class_counts"] = ps.class_counts();
  if (ps.size() >= 2) {
    // One k-NN pass on the torus gives d_min, mean_nn and the relative radius.
    const NnStats torus = nn_stats(ps, true);
    j["d_min"] = torus.min;
    // The synthesis maps are not periodic, so an output can hold pairs that only the torus
    // brings together (points parked in opposite corners): both distances are reported.
    j["d_min_square"] = min_nn_distance(ps, false);
    j["mean_nn"] = torus.mean;
    j["relative_radius"] = num((torus.min / 2.0) / packing_radius(ps.size(), ps.domain().area()));
  } else {
    j["d_min"] = j["d_min_square"] = j["mean_nn"] = j["relative_radius"] = nullptr;
  }
  json per = json::array();
  if (ps.num_classes() == 1)
    per.push_back(j["relative_radius"]);  // the one class is the whole set: no second pass
  else
    for (const PointSet& c : split_classes(ps, ps.num_classes()))
      per.push_back(c.size() >= 2 ? json(relative_radius(c)) : json(nullptr));
  j["relative_radius_per_class"] = per;
  return j;
}

json curves_json(const Curve& ex, const Curve& out) {
  return {{"r", ex.r}, {"exemplar", ex.g}, {"output", out.g}};
}

json values_json(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}

json quartiles_json(const std::vector<double>& v) {
  return {num(quantile(v, 0.25)), num(quantile(v, 0.5)), num(quantile(v, 0.75))};
}

// One row: the exemplar (its domain as read) against the patches (on the unit square). With
// crops the per-crop values and their quartiles join the means (evaluation.hpp).
json patch_json(const PointSet& ex, const std::vector<PointSet>& patches, const EvalOptions& opt, bool crops) {
  Curve ce, co;
  PatchMetrics m = patch_metrics(ex, patches, opt.pcf, &ce, &co, opt.wasserstein_max_pairs);
  json j = {{"pcf_mse", num(m.pcf_mse)}, {"wasserstein", num(m.wasserstein)}, {"chamfer", num(m.chamfer)},
            {"exemplar_points", ex.size()}};
  j["wasserstein_method"] = m.wasserstein_exact ? "exact" : "subsample";
  if (!m.wasserstein_exact) {
    j["wasserstein_estimate"] = num(m.wasserstein_estimate);
    j["wasserstein_sample"] = {m.wasserstein_sample_a, m.wasserstein_sample_b};
  }
  if (crops) {
    j["per_crop"] = {{"pcf_mse", values_json(m.patch_pcf_mse)},
                     {"wasserstein", values_json(m.patch_wasserstein)},
                     {"chamfer", values_json(m.patch_chamfer)}};
    j["pcf_mse_quartiles"] = quartiles_json(m.patch_pcf_mse);
    j["wasserstein_quartiles"] = quartiles_json(m.patch_wasserstein);
    j["chamfer_quartiles"] = quartiles_json(m.patch_chamfer);
  }
  if (opt.include_curves) j["pcf"] = curves_json(ce, co);
  return j;
}

// Progress for large inputs: one info line per stage, with the time since the start.
class Progress {
 public:
  explicit Progress(bool on) : on_(on), t0_(std::chrono::steady_clock::now()) {}
  template <class... Args>
  void operator()(const char* fmt, const Args&... args) const {
    if (!on_) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    spdlog::info("eval [{:.1f} s]: {}", s, fmt::format(fmt, args...));
  }

 private:
  bool on_;
  std::chrono::steady_clock::time_point t0_;
};

// The permutation verdict's p and outcome beside each fidelity row of the same scope: two
// readings of one question, the test's and the calibrated distance's.
void verdict_beside_fidelity(const json& verdict, json& fidelity) {
  for (auto& row : fidelity["rows"])
    for (const auto& v : verdict["rows"]) {
      const std::string kind = row["row"].get<std::string>();
      if (v["row"] != kind) continue;
      if ((kind == "class" && v["class"] != row["class"]) || (kind == "pair" && (v["ci"] != row["ci"] || v["cj"] != row["cj"])))
        continue;
      row["verdict_p"] = v["p"];
      row["verdict_outcome"] = v["outcome"];
    }
}

json overlap_json(const PointSet& ps, bool periodic) {
  json a = json::array();
  for (const auto& o : disk_overlaps(ps, periodic))
    a.push_back({{"ci", o.ci}, {"cj", o.cj}, {"pairs", o.pairs}, {"pair_fraction", o.pair_fraction},
                 {"point_fraction", o.point_fraction}});
  return a;
}

}  // namespace

void check_eval_options(const EvalOptions& opt) {
  if (opt.pcf.bins < 2 || opt.pcf.bins > 10000) throw InputError("bins (--bins) must be in 2..10000");
  if (!(opt.pcf.r_max >= 0) || opt.pcf.r_max > 1)
    throw InputError("r_max (--r-max) must be in (0, 1] (0 = from the exemplar's count)");
  if (opt.wasserstein_max_pairs < 1 || opt.wasserstein_max_pairs > 400000000)
    throw InputError("wasserstein_exact_limit (--wasserstein-exact-limit) must be in 1..400000000 pairs (a 3.2 GB cost matrix)");
  if (opt.protocol != PatchProtocol::Auto && opt.protocol != PatchProtocol::Quadrants &&
      opt.protocol != PatchProtocol::Crops)
    throw InputError("protocol (--protocol) must be auto, quadrants or crops");
  if (!(opt.zoom >= 0) || !std::isfinite(opt.zoom))
    throw InputError("zoom (--zoom) must be a number > 0 (output units per exemplar unit; 0 = from the densities)");
  if (opt.crops < 1 || opt.crops > kMaxCrops)
    throw InputError("crops (--crops) must be in 1.." + std::to_string(kMaxCrops) + " (got " +
                     std::to_string(opt.crops) + ")");
  if (opt.verdict) check_verdict_options(opt.verdict_options);
  if (opt.scorecard) {
    check_novelty_options(opt.novelty);
    check_fidelity_options(opt.fidelity);
    check_periodicity_options(opt.periodicity);
  }
  if (opt.spectrum && (opt.spectrum_frequency < 1 || opt.spectrum_frequency > kMaxPeriodogramFrequencies))
    throw InputError("spectrum_frequency must be in 1.." + std::to_string(kMaxPeriodogramFrequencies));
}

json evaluate(const PointSet& exemplar, const PointSet& output_as_read, const EvalOptions& opt) {
  check_eval_options(opt);
  if (exemplar.empty()) throw InputError("evaluate: the exemplar is empty");
  if (output_as_read.empty()) throw InputError("evaluate: the output is empty");
  check_domain(exemplar, "exemplar");
  check_domain(output_as_read, "output");
  // Every row compares a class with the exemplar's class of the same label.
  const ClassMatch match = match_classes(exemplar, output_as_read);
  const PointSet& output = match.output;
  const Progress progress(exemplar.size() + output.size() >= kProgressPoints);
  progress("{} exemplar and {} output points: nearest neighbors", exemplar.size(), output.size());
  json r;
  r["exemplar"] = set_summary(exemplar);
  r["output"] = set_summary(output);
  r["upscale"] = std::sqrt(static_cast<double>(output.size()) / exemplar.size());
  r["classes_matched"] = class_match_json(match);
  const ProtocolPlan plan = plan_protocol(exemplar, output, opt.protocol, opt.crops, opt.crop_seed, opt.zoom);
  const bool crops = plan.used == PatchProtocol::Crops;
  r["protocol"] = protocol_json(plan);
  progress("all classes: PCF, Chamfer, Wasserstein in {} {}", plan.windows.size(), patch_protocol_name(plan.used));
  // The output is cut once; the per-class rows and the cross-class PCFs take the patches'
  // points of each class (the same points as cutting each class's subset).
  const std::vector<PointSet> patches = cut_patches(output, plan.windows);
  r["all"] = patch_json(exemplar, patches, opt, crops);
  const int K = exemplar.num_classes();
  json classes = json::array();
  json cross = json::array();
  if (K > 1) {
    const PatchSplit split = split_patches(exemplar, patches, std::max(K, output.num_classes()));
    const auto ex_k = split_classes(exemplar, K);
    for (int k = 0; k < K; ++k) {
      progress("class {} of {}", k + 1, K);
      std::vector<PointSet> class_patches;
      class_patches.reserve(split.patch_class.size());
      for (const auto& p : split.patch_class) class_patches.push_back(p[k]);
      json c = patch_json(ex_k[k], class_patches, opt, crops);
      c["class"] = k;
      c["label"] = exemplar.class_label(k);
      classes.push_back(c);
    }
    if (K <= kMaxPairClasses) {
      const size_t n_pairs = static_cast<size_t>(K) * (K - 1) / 2;
      size_t done = 0;
      for (int a = 0; a < K; ++a)
        for (int b = a + 1; b < K; ++b) {
          if (done++ % 50 == 0) progress("cross-class PCF, pair {} of {}", done, n_pairs);
          Curve ce, co;
          std::vector<double> per;
          const double mse = patch_cross_pcf_mse(split, a, b, opt.pcf, &ce, &co, &per);
          json c = {{"ci", a}, {"cj", b}, {"pcf_mse", num(mse)}};
          if (crops) {
            c["per_crop"] = {{"pcf_mse", values_json(per)}};
            c["pcf_mse_quartiles"] = quartiles_json(per);
          }
          if (opt.include_curves) c["pcf"] = curves_json(ce, co);
          cross.push_back(c);
        }
    }
  }
  r["classes"] = classes;
  if (K > kMaxPairClasses) {
    r["cross_skipped"] = "the exemplar has " + std::to_string(K) + " classes: the " +
                         std::to_string(static_cast<size_t>(K) * (K - 1) / 2) +
                         " cross-class PCFs and overlap class pairs are computed up to " +
                         std::to_string(kMaxPairClasses) + " classes only";
  }
  r["cross"] = cross;
  if (exemplar.attribute_index("radius") && output.attribute_index("radius")) {
    progress("disk overlaps");
    r["overlap"] = {{"exemplar", overlap_json(exemplar, opt.periodic_overlap)},
                    {"output", overlap_json(output, opt.periodic_overlap)}};
  }
  if (opt.spectrum) {
    Spectrum se = power_spectrum(exemplar, opt.spectrum_frequency);
    Spectrum so = power_spectrum(output, opt.spectrum_frequency);
    r["spectrum"] = {{"frequency", se.frequency}, {"exemplar", se.radial_power}, {"output", so.radial_power}};
    // Repetition (tiles, seams) on a grid in coordinate units of the same size (periodogram.hpp).
    PeriodogramOptions po;
    po.frequencies = opt.spectrum_frequency;
    r["spectrum"]["peak_ratio"] = {{"exemplar", num(spectrum_peak(periodogram(exemplar, po)).ratio)},
                                   {"output", num(spectrum_peak(periodogram(output, po)).ratio)}};
  }
  // In exemplar units, at the zoom the patches were cut at (given, or the densities').
  if (opt.second_order) {
    progress("K, L, g and mark correlations");
    r["second_order"] = second_order_report(exemplar, output, plan.zoom, opt.include_curves);
  }
  if (opt.scorecard) {
    progress("scorecard: novelty, fidelity, periodicity, close pairs");
    r["scorecard"] = {{"novelty", novelty_report(exemplar, output, plan.zoom, opt.novelty)},
                      {"fidelity", fidelity_report(exemplar, output, plan.zoom, opt.fidelity)},
                      {"periodicity", periodicity_report(exemplar, output, plan.zoom, opt.periodicity)},
                      {"close_pairs", close_pairs_report(exemplar, output, plan.zoom)},
                      {"border", border_line(r)}};
  }
  if (opt.verdict) {
    progress("verdict");
    VerdictOptions v = opt.verdict_options;
    v.zoom = plan.zoom;
    r["verdict"] = verdict(exemplar, output, v);
    if (r.contains("scorecard")) verdict_beside_fidelity(r["verdict"], r["scorecard"]["fidelity"]);
  }
  r["options"] = {{"bins", opt.pcf.bins},
                  {"r_max_factor", opt.pcf.r_max_factor},
                  {"sigma_factor", opt.pcf.sigma_factor},
                  {"r_min_factor", opt.pcf.r_min_factor},
                  {"periodic", opt.pcf.periodic},
                  {"r_max", opt.pcf.r_max > 0 ? json(opt.pcf.r_max) : json("from exemplar count")},
                  {"wasserstein_exact_pairs", opt.wasserstein_max_pairs}};
  r["wasserstein_note"] =
      "exact assignment when exemplar points x patch points <= " + std::to_string(opt.wasserstein_max_pairs) +
      (crops ? " (per crop)" : " (per quadrant)") +
      "; beyond, wasserstein is null and wasserstein_estimate is the exact assignment between "
      "random subsamples of the sizes in wasserstein_sample (fixed seed): comparable only with estimates of the "
      "same sample sizes, not with exact values";
  progress("done");
  return r;
}

}  // namespace ppsynth
