#pragma once
// Statistics over seeds: every finished run under the given directories (sweep directories,
// run directories, or folders of run directories), grouped by configuration with the seeds
// pooled (one seed is one sample). For each group and each metric of each scope (all
// classes, each class, each class pair) the median, quartiles, min, max and count (for the
// verdict, the pass rate: passed of all runs, the runs that cannot judge apart); against a
// reference output (a published one, say) the ratio of medians and the share of seeds within
// a bound. Written as CSV, Markdown, JSON and an HTML page with a strip plot per metric.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/metrics/eval_protocol.hpp"

namespace ppsynth {

// A reference output (a published one, say) and the exemplar it was synthesized from: it is
// evaluated against that exemplar and compared with the groups synthesized from it only.
struct ReferenceOutput {
  std::string exemplar;  // the exemplar file's stem ("poisson_n64c2_point"); "" = the only one
  std::string file;      // the point file ("shared:..." allowed)
};
// "FILE" or "EXEMPLAR=FILE" (the command's --reference).
ReferenceOutput parse_reference(const std::string& text);

struct GatherOptions {
  // A plain FILE is refused when the runs come from more than one exemplar: a reference of
  // one pattern judged against another's exemplar would give numbers that mean nothing.
  std::vector<ReferenceOutput> references;
  double bound = 1.25;  // a seed is within when its value <= bound x the reference's
  // Group labels to compare the other groups of their exemplar with ("lines": the default
  // config's group): ratio of medians and its bootstrap interval (below).
  std::vector<std::string> baselines;
  // Unset: each run's metrics.json (the evaluation its run made). Set: every run's output
  // (and every reference) evaluated again against its exemplar with this protocol, e.g.
  // crops for finished u = 2 runs measured away from their frame (docs/lab/large_outputs.md).
  std::optional<PatchProtocol> protocol;
  // Stage numbers (1-based, as snapshots/stageNN.txt): each run's points after that stage
  // also make a group of their own, "<group label> @ stage N", evaluated here (with
  // `protocol`, else the evaluation's defaults, as a run's metrics.json). A run counts there
  // once it has passed the stage, finished or not. What it is for: a plan that appends stages
  // to another's (a border relax after the published stages) holds that plan's output as a
  // snapshot, bit for bit, so one sweep gives both groups, paired by seed, for half the runs
  // (`--baseline "<label> @ stage N"`). Whole outputs only: a snapshot of one window of a large
  // output, or of a padded canvas, is an error naming it.
  std::vector<int> stages;
};

// One finished run and the numbers taken from it.
struct GatheredRun {
  std::string dir, group, group_label;
  uint64_t seed = 0;
  std::vector<std::pair<std::string, double>> values;  // "<scope>/<metric>" -> value
  std::string processor;  // run.json's (core/processor.hpp); "" for runs made before it was recorded
  int stage = 0;          // 0: the run's output; N: its points after stage N (GatherOptions::stages)
};

// A verdict row over seeds: how many runs passed, failed, or could not judge it. A run that
// cannot judge is counted apart, never as a pass: the share is passed over all the runs.
struct PassRate {
  size_t passed = 0, failed = 0, cannot_judge = 0;
  size_t runs() const { return passed + failed + cannot_judge; }
  double share() const { return runs() ? static_cast<double>(passed) / static_cast<double>(runs()) : 0.0; }
  // "2/5 (40 %)", then ", 1 cannot judge" when some could not.
  std::string text() const;
};

struct MetricSummary {
  std::string group, group_label, scope, metric;
  std::vector<double> values;  // per seed, in the order of `seeds`
  std::vector<uint64_t> seeds;
  double median = 0, q1 = 0, q3 = 0, min = 0, max = 0;
  std::optional<double> reference, ratio, within;  // within: share of seeds <= bound x reference
  // Metric "verdict_pass" (values 1 pass, 0 fail, the runs that judged): its pass rate, with
  // the runs that cannot judge ("verdict_cannot_judge", folded in here); its median means nothing.
  std::optional<PassRate> rate;
};

// A group against the baseline of its exemplar, one metric: the ratio of the medians and a
// 90 % bootstrap interval for it (the seeds of each group resampled with replacement, 2000
// times, a fixed generator). The baseline against itself is listed too: its interval is what
// the ratio of two medians of that many seeds spreads over by chance alone.
//
// And paired by seed: a seed both groups ran (once each) starts both runs from the same
// initial points and networks, and a change that acts late in a run (a border relax after the
// published stages) leaves them the same trajectory up to it. The ratio of each such seed's two
// values then holds the change's effect without most of the seed's own luck, which the ratio of
// medians carries twice: the median of the per-seed ratios, with a 90 % bootstrap interval (the
// pairs resampled, 2000 times). NaN with no pair; a seed whose baseline value is 0 or not
// finite is left out of the pairs.
struct BaselineComparison {
  std::string group_label, baseline_label, scope, metric;
  size_t n = 0, n_baseline = 0;
  double ratio = 0, lo = 0, hi = 0;
  std::vector<uint64_t> paired_seeds;  // in ascending order
  std::vector<double> paired_ratios;   // value / the baseline's, per paired seed
  double paired = 0, paired_lo = 0, paired_hi = 0;  // their median and its interval
};

struct GatherResult {
  std::vector<GatheredRun> runs;
  std::vector<MetricSummary> summaries;  // by group, then scope, then metric
  std::vector<BaselineComparison> comparisons;  // by baseline, then group, scope, metric
  std::vector<std::string> unfinished;   // run directories left out (not complete; not past a stage)
  // What a reader of the numbers must know: a group whose seeds ran on more than one kind of
  // processor (their seconds do not compare, and a seed rerun elsewhere is another sample).
  std::vector<std::string> notes;
  GatherOptions options;
  std::vector<std::string> inputs;  // the directories gathered (write_gather never writes into one)
};

GatherResult gather_runs(const std::vector<std::string>& dirs, const GatherOptions& options);

// gather.csv, gather.md, gather.json, per_seed.csv, index.html (+ plots/) into `out`, opened
// as a ppsynth directory (new or empty, or an earlier gather's with force: never a run or a
// report, core/run_directory.hpp). `out` is never one of result.inputs, inside one, or a
// directory holding one.
void write_gather(const GatherResult& result, const std::string& out, bool force);

// The table printed by the command: each group's whole label, then a line per scope and metric;
// against baselines, each group over its baseline, then a line per scope and metric.
std::string format_gather(const GatherResult& result);

}  // namespace ppsynth
