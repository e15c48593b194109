// gather, step 2: the statistics over seeds of each group (median, quartiles; the verdict's
// pass rate), against a reference output (ratio, share within a bound) and against a baseline
// group (ratio of medians and per-seed ratios with bootstrap intervals); and gather_runs, the
// two steps.
#include "experiments/gather/gather_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/metrics/summary_stats.hpp"
#include "core/run_json.hpp"
#include "optim/run/run_store.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

std::pair<std::string, std::string> split_key(const std::string& key) {
  const size_t slash = key.rfind('/');
  return {key.substr(0, slash), key.substr(slash + 1)};
}

// Ratio of the medians of `a` and `b` and its 5 % and 95 % bootstrap quantiles.
BaselineComparison compare_medians(const std::vector<double>& a, const std::vector<double>& b) {
  BaselineComparison c;
  c.n = a.size(), c.n_baseline = b.size();
  const double mb = summarize(b).median;
  c.ratio = mb != 0 ? summarize(a).median / mb : std::nan("");
  std::mt19937_64 rng(20261125);
  std::vector<double> ratios, ra(a.size()), rb(b.size());
  for (int draw = 0; draw < 2000; ++draw) {
    for (auto& x : ra) x = a[std::uniform_int_distribution<size_t>(0, a.size() - 1)(rng)];
    for (auto& x : rb) x = b[std::uniform_int_distribution<size_t>(0, b.size() - 1)(rng)];
    const double den = summarize(rb).median;
    if (den != 0) ratios.push_back(summarize(ra).median / den);
  }
  c.lo = quantile(ratios, 0.05), c.hi = quantile(ratios, 0.95);
  return c;
}

// Seeds that occur exactly once among `seeds` (a seed gathered twice from loose copies has no
// one value to pair), with their values.
std::map<uint64_t, double> single_seed_values(const MetricSummary& s) {
  std::map<uint64_t, double> once;
  std::set<uint64_t> repeated;
  for (size_t i = 0; i < s.seeds.size(); ++i)
    if (!once.emplace(s.seeds[i], s.values[i]).second) repeated.insert(s.seeds[i]);
  for (uint64_t seed : repeated) once.erase(seed);
  return once;
}

// The per-seed ratios of the seeds both ran, their median and its bootstrap interval
// (BaselineComparison).
void compare_paired(const MetricSummary& s, const MetricSummary& base, BaselineComparison& c) {
  const std::map<uint64_t, double> mine = single_seed_values(s), theirs = single_seed_values(base);
  for (const auto& [seed, value] : mine) {
    const auto b = theirs.find(seed);
    if (b == theirs.end() || !std::isfinite(b->second) || b->second == 0 || !std::isfinite(value)) continue;
    c.paired_seeds.push_back(seed);
    c.paired_ratios.push_back(value / b->second);
  }
  c.paired = c.paired_lo = c.paired_hi = std::nan("");
  if (c.paired_ratios.empty()) return;
  c.paired = summarize(c.paired_ratios).median;
  std::mt19937_64 rng(20261126);
  std::vector<double> medians, draw(c.paired_ratios.size());
  for (int k = 0; k < 2000; ++k) {
    for (auto& x : draw) x = c.paired_ratios[std::uniform_int_distribution<size_t>(0, draw.size() - 1)(rng)];
    medians.push_back(summarize(draw).median);
  }
  c.paired_lo = quantile(medians, 0.05), c.paired_hi = quantile(medians, 0.95);
}

// The verdict's metrics of a group's summaries folded into one per scope: "verdict_pass"
// (1 pass, 0 fail) with its pass rate, the "verdict_cannot_judge" runs counted into it.
void fold_pass_rates(std::vector<MetricSummary>& list) {
  for (auto it = list.begin(); it != list.end();) {
    if (it->metric != "verdict_cannot_judge") {
      ++it;
      continue;
    }
    const MetricSummary cannot = *it;
    it = list.erase(it);
    auto pass = std::find_if(list.begin(), list.end(), [&](const MetricSummary& s) { return s.scope == cannot.scope && s.metric == "verdict_pass"; });
    if (pass == list.end()) {  // no run of the group could judge this row
      MetricSummary fresh;
      fresh.group = cannot.group, fresh.group_label = cannot.group_label, fresh.scope = cannot.scope, fresh.metric = "verdict_pass";
      it = list.insert(it, std::move(fresh));
      pass = it++;
    }
    pass->rate = PassRate{};
    pass->rate->cannot_judge = cannot.values.size();
  }
  for (auto& s : list)
    if (s.metric == "verdict_pass") {
      if (!s.rate) s.rate = PassRate{};
      s.rate->passed = static_cast<size_t>(std::count(s.values.begin(), s.values.end(), 1.0));
      s.rate->failed = s.values.size() - s.rate->passed;
    }
}

}  // namespace

std::string PassRate::text() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%zu/%zu (%.0f %%)", passed, runs(), 100 * share());
  std::string t = buf;
  if (cannot_judge > 0) t += ", " + std::to_string(cannot_judge) + " cannot judge";
  return t;
}

void summarize_groups(GatherResult& r) {
  const GatherOptions& options = r.options;
  // group -> key -> summary, keys in first-seen order
  std::map<std::string, std::vector<MetricSummary>> by_group;
  std::vector<std::string> group_order;
  for (const auto& run : r.runs) {
    auto& list = by_group[run.group];
    if (list.empty()) group_order.push_back(run.group);
    for (const auto& [key, value] : run.values) {
      const auto [scope, metric] = split_key(key);
      auto it = std::find_if(list.begin(), list.end(), [&](const MetricSummary& s) { return s.scope == scope && s.metric == metric; });
      if (it == list.end()) {
        MetricSummary fresh;
        fresh.group = run.group, fresh.group_label = run.group_label, fresh.scope = scope, fresh.metric = metric;
        list.push_back(std::move(fresh));
        it = std::prev(list.end());
      }
      it->values.push_back(value);
      it->seeds.push_back(run.seed);
    }
  }
  for (const auto& g : group_order) fold_pass_rates(by_group[g]);
  // Each group's exemplar (the stem of its file) and the reference that belongs to it.
  std::map<std::string, std::string> exemplar_of;
  std::set<std::string> exemplars;
  for (const auto& g : group_order) {
    const auto first = std::find_if(r.runs.begin(), r.runs.end(), [&](const GatheredRun& x) { return x.group == g; });
    exemplar_of[g] = fs::path(read_run_config(first->dir + "/config.json")["exemplar"].get<std::string>()).stem().string();
    exemplars.insert(exemplar_of[g]);
  }
  std::map<std::string, std::string> reference_file;  // exemplar stem -> file
  for (const auto& ref : options.references) {
    std::string stem = ref.exemplar;
    if (stem.empty()) {
      if (exemplars.size() != 1) {
        std::string names;
        for (const auto& e : exemplars) names += (names.empty() ? "" : ", ") + e;
        throw InputError("--reference " + ref.file + ": the runs come from " + std::to_string(exemplars.size()) +
                         " exemplars (" + names + "); name the one it belongs to: --reference EXEMPLAR=" + ref.file);
      }
      stem = *exemplars.begin();
    } else if (!exemplars.count(stem)) {
      std::string names;
      for (const auto& e : exemplars) names += (names.empty() ? "" : ", ") + e;
      throw InputError("--reference " + stem + "=" + ref.file + ": no gathered run comes from an exemplar named '" + stem +
                       "' (they come from: " + names + ")");
    }
    if (!reference_file.emplace(stem, ref.file).second)
      throw InputError("--reference: two references for the exemplar '" + stem + "'");
  }
  for (const auto& g : group_order) {
    std::map<std::string, double> ref;
    if (const auto file = reference_file.find(exemplar_of[g]); file != reference_file.end()) {
      const auto first = std::find_if(r.runs.begin(), r.runs.end(), [&](const GatheredRun& x) { return x.group == g; });
      const PointSet exemplar = load_run(first->dir).exemplar;
      try {
        for (const auto& [k, v] : metric_values(evaluate(exemplar, read_points(file->second), evaluation_options(options)), file->second))
          ref[k] = v;
      } catch (const InputError& e) {  // an evaluation's error ("crops: ...") names no file
        const std::string what = e.what();
        throw InputError(what.rfind(file->second, 0) == 0 ? what : "--reference " + file->second + ": " + what);
      }
    }
    for (auto& s : by_group[g]) {
      const Summary sum = summarize(s.values);
      s.median = sum.median, s.q1 = sum.q1, s.q3 = sum.q3, s.min = sum.min, s.max = sum.max;
      const auto it = ref.find(s.scope + "/" + s.metric);
      if (it != ref.end() && s.rate) {
        s.reference = it->second;  // the reference's own pass (1) or fail (0); no ratio of rates
      } else if (it != ref.end()) {
        s.reference = it->second;
        if (it->second != 0) s.ratio = s.median / it->second;
        const auto within = std::count_if(s.values.begin(), s.values.end(), [&](double v) { return v <= options.bound * it->second; });
        s.within = static_cast<double>(within) / static_cast<double>(s.values.size());
      }
      r.summaries.push_back(s);
    }
  }
  for (const auto& label : options.baselines) {
    std::vector<std::string> matches;
    for (const auto& g : group_order)
      if (by_group[g].front().group_label == label) matches.push_back(g);
    if (matches.size() != 1) {
      std::string labels;
      for (const auto& g : group_order) labels += (labels.empty() ? "" : "; ") + by_group[g].front().group_label;
      throw InputError("--baseline '" + label + "': " + (matches.empty() ? "no group" : "several groups") +
                       " of that label (groups: " + labels + ")");
    }
    const std::string& base = matches.front();
    for (const auto& g : group_order) {
      if (exemplar_of[g] != exemplar_of[base]) continue;
      for (const auto& s : by_group[g]) {
        if (s.rate) continue;  // a ratio of medians of 0s and 1s says nothing: the rates are in the table
        const auto b = std::find_if(by_group[base].begin(), by_group[base].end(),
                                    [&](const MetricSummary& x) { return x.scope == s.scope && x.metric == s.metric; });
        if (b == by_group[base].end()) continue;
        BaselineComparison c = compare_medians(s.values, b->values);
        compare_paired(s, *b, c);
        c.group_label = s.group_label, c.baseline_label = label, c.scope = s.scope, c.metric = s.metric;
        r.comparisons.push_back(c);
      }
    }
  }
}

GatherResult gather_runs(const std::vector<std::string>& dirs, const GatherOptions& options) {
  GatherResult r = collect_runs(dirs, options);
  summarize_groups(r);
  return r;
}

}  // namespace ppsynth
