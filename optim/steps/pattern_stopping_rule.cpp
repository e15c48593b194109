// The "pattern" stopping rule: stop a sigma stage when its pattern stops getting
// closer to the exemplar's, whatever the loss still does. Every `check_every` iterations it
// measures the PCF MSE between the stage's points in play and the exemplar's points of the
// same classes (core/metrics/pcf.hpp: radii in each set's own r_max units, so a u x u output
// and its exemplar line up; the output on its torus, the exemplar and a window's grid as
// rectangles with the translation edge correction). It stops once `min_iterations` have run
// and the best value of the last `window` iterations is not `threshold` (relative) below the
// best before them: the pattern, as the evaluation sees it, has stopped improving.
// With `"end_on": "best"` the stage ends on its best checked iterate (its start included)
// instead of its last: in the last sigma of `lines` the PCF MSE rose in 8 of 10 runs while
// the loss still fell (docs/lab/fast_preset.md, "The time / quality curve"); the stage then
// gives back what it lost. `"best_by"` says how the best is judged: "output" (the stage's
// points as one plane rectangle, its border included) or "crops" (the mean PCF MSE of 20
// exemplar-sized crops at fixed places, other than the evaluation's: the pattern away from
// the border, which is where the published border's parked pairs made the whole
// rectangle's PCF a poor judge; docs/lab/large_outputs.md).
// `"rows"` says which PCFs are measured when a stage moves one class among others:
// "moving_class" (the mean MSE of the moving class's own PCF and of its cross PCF with each
// other class in play, as the verdict's rows name them) or "all" (the points in play as one
// pattern, classes pooled). Pooled, a later class's stage is judged mostly by the frozen
// classes, which it cannot change: its own spacing may worsen while the pooled curve improves
// (docs/lab/later_classes/). A stage of one class in play measures the same either way.
//
// Why: the loss of a stage keeps falling for hundreds of iterations while the points only
// jitter around their places (the grid jitter of every iteration feeds Adam fresh noise);
// the loss rule waits for that tail (docs/lab/fast_preset.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/metrics/crops.hpp"
#include "core/metrics/patches.hpp"
#include "core/metrics/pcf.hpp"
#include "optim/steps/stopping_rule.hpp"

namespace ppsynth {
namespace {

struct PatternRuleOptions {
  int window = 50;
  int check_every = 10;
  double threshold = 0.02;
  int min_iterations = 30;
  bool end_on_best = false;
  bool best_by_crops = false;
  bool rows_of_moving_class = true;
  static const ParamTable<PatternRuleOptions>& params() {
    using O = PatternRuleOptions;
    static const ParamTable<O> t("method.convergence", {
        param("window", &O::window, "int [1, 1000000000]", "the iterations in which the PCF MSE must improve"),
        param("check_every", &O::check_every, "int [1, 1000000000]", "iterations between two measures"),
        param("threshold", &O::threshold, "[0, 1]", "the relative improvement the window must bring"),
        param("min_iterations", &O::min_iterations, "int [0, 1000000000]", "iterations before it may stop"),
        choice("end_on", &O::end_on_best, {{"last", false}, {"best", true}}, "the iterate the stage ends on: its last, or its best checked"),
        choice("best_by", &O::best_by_crops, {{"output", false}, {"crops", true}},
               "how the best is judged: the points as one rectangle, or 20 exemplar-sized crops"),
        choice("rows", &O::rows_of_moving_class, {{"moving_class", true}, {"all", false}},
               "the PCFs measured: the moving class's own and cross, or the points in play as one pattern"),
    });
    return t;
  }
};

class PatternStoppingRule : public StoppingRule {
 public:
  PatternStoppingRule(int window, int check_every, double threshold, int min_iterations, bool end_on_best, bool best_by_crops,
                      bool rows_of_moving_class)
      : window_(window), check_every_(check_every), threshold_(threshold), min_iterations_(min_iterations),
        end_on_best_(end_on_best), best_by_crops_(best_by_crops), rows_of_moving_class_(rows_of_moving_class) {}

  void begin_stage(const PointSet& exemplar_in_play, int moving_class) override {
    target_ = pcf(exemplar_in_play);
    exemplar_ = exemplar_in_play;
    crop_pcf_.r_max = pcf_unit(exemplar_.size(), 1.0);  // as the evaluation's patches (patches.hpp)
    crop_target_ = pcf(to_unit_square(exemplar_), crop_pcf_);
    rows_.clear();
    std::vector<int> others;
    for (int c : exemplar_.classes())
      if (c != moving_class && std::find(others.begin(), others.end(), c) == others.end()) others.push_back(c);
    std::sort(others.begin(), others.end());
    const bool moving_in_play = std::find(exemplar_.classes().begin(), exemplar_.classes().end(), moving_class) !=
                                exemplar_.classes().end();
    if (!rows_of_moving_class_ || moving_class < 0 || !moving_in_play || others.empty()) return;  // one pattern
    rows_.push_back(class_row(moving_class, moving_class));
    for (int c : others) rows_.push_back(class_row(moving_class, c));
  }

  StopVerdict judge(const StageView& v, std::vector<double>& record) override {
    if ((v.iteration + 1) % check_every_ != 0) return {};
    if (v.iteration < 0 && !end_on_best_) return {};  // the start matters only as a candidate to end on
    const PointSet points = v.points();
    PcfOptions o;
    o.periodic = v.periodic;
    const double now = whole_mse(points, o);
    StopVerdict verdict;
    size_t stride = 1;
    if (end_on_best_) {
      // The best is chosen as a user sees the output: a plane rectangle, edge-corrected, as
      // the evaluation measures it. On the paper's torus, points parked on opposite borders
      // are close pairs of the torus but not of the square: chosen on the torus, Tree1's
      // stages 3 and 4 never beat their start (docs/lab/fast_preset.md).
      // The record then holds pairs (as optimized, as seen); the stop watches the first.
      stride = 2;
      const double seen = best_by_crops_ ? crops_mse(points, v.zoom, now)
                          : v.periodic    ? whole_mse(points, PcfOptions{})
                                          : now;
      double best_seen = std::numeric_limits<double>::infinity();
      for (size_t i = 1; i < record.size(); i += 2) best_seen = std::min(best_seen, record[i]);
      verdict.best = seen < best_seen;  // strictly below: of equal values the first is kept
      record.push_back(now);
      record.push_back(seen);
    } else {
      record.push_back(now);
    }
    std::vector<double> watched;
    for (size_t i = 0; i < record.size(); i += stride) watched.push_back(record[i]);
    const size_t recent = static_cast<size_t>(std::max(1, window_ / check_every_));
    if (v.iteration + 1 < min_iterations_ || watched.size() <= recent) return verdict;
    const auto split = watched.end() - static_cast<std::ptrdiff_t>(recent);
    const double before = *std::min_element(watched.begin(), split), last = *std::min_element(split, watched.end());
    verdict.stop = last > (1 - threshold_) * before;
    return verdict;
  }

  // The checks' PCF MSEs in order (the first at the stage's start where the stage ends on its
  // best) and, ending on the best, the iteration it ended on (-1: its start) and the measure
  // that chose it where that is not the first (the plane rectangle of a torus, the crops).
  nlohmann::json summary(const std::vector<double>& record) const override {
    nlohmann::json s = {{"check_every", check_every_}};
    const size_t stride = end_on_best_ ? 2 : 1;
    std::vector<double> watched, seen;
    for (size_t i = 0; i + stride - 1 < record.size(); i += stride) {
      watched.push_back(record[i]);
      if (end_on_best_) seen.push_back(record[i + 1]);
    }
    s["pcf_mse"] = watched;
    if (end_on_best_ && !seen.empty()) {
      // the first of equal minima, as judge() keeps it; check i is iteration i * check_every - 1
      const auto best = std::min_element(seen.begin(), seen.end()) - seen.begin();
      s["ended_on_iteration"] = static_cast<int>(best) * check_every_ - 1;
      if (seen != watched) s["pcf_mse_chosen_by"] = seen;
    }
    return s;
  }

 private:
  // One PCF the rule measures of a stage moving a class among others: class a's own (a == b)
  // or the cross PCF from a to b, with the exemplar's curve whole and as a unit-square crop.
  struct Row {
    int a = 0, b = 0;
    Curve target, crop_target;
    PcfOptions crop;  // r_max of the exemplar's row on the unit square, as the evaluation's patches
  };

  Row class_row(int a, int b) const {
    Row row{a, b, {}, {}, {}};
    const PointSet ea = exemplar_.subset_class(a), eb = exemplar_.subset_class(b);
    row.target = row_curve(row, ea, eb, PcfOptions{});
    row.crop.r_max = pcf_unit(a == b ? ea.size() : ea.size() + eb.size(), 1.0);
    row.crop_target = row_curve(row, to_unit_square(ea), to_unit_square(eb), row.crop);
    return row;
  }

  static Curve row_curve(const Row& row, const PointSet& a, const PointSet& b, const PcfOptions& o) {
    return row.a == row.b ? pcf(a, o) : cross_pcf(a, b, o);
  }

  // The row's curve can be measured: two points of each of its classes (a cross PCF from
  // one point is that point's neighbourhood, not the pattern's).
  static bool measurable(const Row& row, const PointSet& a, const PointSet& b) {
    return a.size() >= 2 && (row.a == row.b || b.size() >= 2);
  }

  // The mean MSE of the rows' curves of `points` to their targets (`crop`: the crop targets);
  // a row without enough points in `points` is left out; NaN when every row is.
  double rows_mse(const PointSet& points, const PcfOptions& o, bool crop) const {
    double sum = 0;
    int measured = 0;
    int classes = 0;
    for (const Row& row : rows_) classes = std::max({classes, row.a + 1, row.b + 1});
    const std::vector<PointSet> parts = split_classes(points, classes);  // each class once, not once per row
    for (const Row& row : rows_) {
      const PointSet &a = parts[static_cast<size_t>(row.a)], &b = parts[static_cast<size_t>(row.b)];
      if (!measurable(row, a, b)) continue;
      PcfOptions ro = o;
      if (crop) ro.r_max = row.crop.r_max;
      sum += curve_mse(row_curve(row, a, b, ro), crop ? row.crop_target : row.target);
      ++measured;
    }
    return measured ? sum / measured : std::numeric_limits<double>::quiet_NaN();
  }

  // The stage's points against the exemplar's: its rows, or the points as one pattern (also
  // where none of the rows can be measured, e.g. a window without two points of the moving class).
  double whole_mse(const PointSet& points, const PcfOptions& o) const {
    if (!rows_.empty()) {
      const double by_rows = rows_mse(points, o, false);
      if (std::isfinite(by_rows)) return by_rows;
    }
    return curve_mse(pcf(points, o), target_);
  }

  // The mean PCF MSE of kCrops exemplar-sized crops of `points` (at `zoom`), each mapped onto
  // the unit square as the evaluation maps its patches; `whole` where no crop fits.
  double crops_mse(const PointSet& points, double zoom, double whole) const {
    const Domain& d = points.domain();
    if (points.empty() || exemplar_.domain().width() * zoom > d.width() || exemplar_.domain().height() * zoom > d.height())
      return whole;
    const CropPlan plan = plan_crops(exemplar_, points, kCrops, kCropSeed, zoom);
    double sum = 0;
    for (const PointSet& patch : cut_patches(points, plan.windows)) {
      const double by_rows = rows_.empty() ? std::numeric_limits<double>::quiet_NaN() : rows_mse(patch, PcfOptions{}, true);
      sum += std::isfinite(by_rows) ? by_rows : curve_mse(pcf(patch, crop_pcf_), crop_target_);
    }
    return sum / static_cast<double>(plan.windows.size());
  }

  static constexpr int kCrops = 20;
  static constexpr uint64_t kCropSeed = 7919;  // not the evaluation's windows (kDefaultCropSeed)
  int window_, check_every_;
  double threshold_;
  int min_iterations_;
  bool end_on_best_, best_by_crops_, rows_of_moving_class_;
  Curve target_, crop_target_;
  PointSet exemplar_;
  PcfOptions crop_pcf_;
  std::vector<Row> rows_;  // empty: the points in play as one pattern
};

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::StoppingRuleRegistry, "convergence", "pattern", ppsynth::PatternRuleOptions::params(),
                        "stop when the PCF MSE of the stage's points to the exemplar's has not improved by `threshold` (relative) in `window` iterations; end_on: last | best (the stage ends on its best checked iterate); best_by: output (the points as one rectangle) | crops (20 exemplar-sized crops: the pattern away from the border); rows: moving_class (a stage moving one class among others is judged by that class's own PCF and its cross PCFs) | all (the points in play as one pattern)",
                        [](const ppsynth::PatternRuleOptions& o, const std::string&) -> std::unique_ptr<ppsynth::StoppingRule> {
                          return std::make_unique<ppsynth::PatternStoppingRule>(o.window, o.check_every, o.threshold, o.min_iterations,
                                                                                o.end_on_best, o.best_by_crops, o.rows_of_moving_class);
                        })
