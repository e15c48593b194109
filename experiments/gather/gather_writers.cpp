// gather, step 3: the result as the command's table and as files (CSV, Markdown, JSON, an
// HTML page with strip plots) in a gather directory of its own.
#include "experiments/gather/gather_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "core/atomic_file.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/render/plot_strips.hpp"
#include "core/report/html_report.hpp"
#include "core/run_directory.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

std::string num(double v, const char* fmt = "%.6g") {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}
std::string opt(const std::optional<double>& v, const char* fmt = "%.6g") { return v ? num(*v, fmt) : ""; }

// "FILE" or "a=FILE, b=FILE" for the reports.
std::string references_text(const GatherOptions& o) {
  std::string s;
  for (size_t i = 0; i < o.references.size(); ++i)
    s += (i ? ", " : "") + (o.references[i].exemplar.empty() ? "" : o.references[i].exemplar + "=") + o.references[i].file;
  return s;
}

std::vector<std::string> summary_header() {
  return {"group", "scope", "metric", "n", "median", "q1", "q3", "min", "max", "pass rate", "reference", "median / reference",
          "share within bound"};
}

// A run count: the pass rate's runs (those that cannot judge included) or the values'.
size_t runs_of(const MetricSummary& s) { return s.rate ? s.rate->runs() : s.values.size(); }

std::vector<std::vector<std::string>> summary_rows(const GatherResult& r) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : r.summaries) {
    if (s.rate)  // the verdict: its rate, not the median of 0s and 1s
      rows.push_back({s.group_label, s.scope, s.metric, std::to_string(runs_of(s)), "", "", "", "", "", s.rate->text(),
                      opt(s.reference, "%g"), "", ""});
    else
      rows.push_back({s.group_label, s.scope, s.metric, std::to_string(s.values.size()), num(s.median), num(s.q1), num(s.q3),
                      num(s.min), num(s.max), "", opt(s.reference), opt(s.ratio, "%.3f"), opt(s.within, "%.2f")});
  }
  return rows;
}

// One row per run, one column per "<scope>/<metric>" (in first-seen order).
std::pair<std::vector<std::string>, std::vector<std::vector<std::string>>> per_seed_table(const GatherResult& r) {
  std::vector<std::string> keys;
  for (const auto& run : r.runs)
    for (const auto& [k, v] : run.values)
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::vector<std::string> header = {"group", "seed", "run directory"};
  header.insert(header.end(), keys.begin(), keys.end());
  std::vector<std::vector<std::string>> rows;
  for (const auto& run : r.runs) {
    std::vector<std::string> row = {run.group_label, std::to_string(run.seed), run.dir};
    for (const auto& k : keys) {
      const auto it = std::find_if(run.values.begin(), run.values.end(), [&](const auto& kv) { return kv.first == k; });
      row.push_back(it == run.values.end() ? "" : num(it->second));
    }
    rows.push_back(row);
  }
  return {header, rows};
}

std::vector<std::string> comparison_header() {
  return {"group", "baseline", "scope", "metric", "n", "n baseline", "median / baseline median", "90 % bootstrap interval",
          "seeds paired", "median of per-seed ratios", "its 90 % interval"};
}

std::vector<std::vector<std::string>> comparison_rows(const GatherResult& r) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : r.comparisons)
    rows.push_back({c.group_label, c.baseline_label, c.scope, c.metric, std::to_string(c.n), std::to_string(c.n_baseline),
                    num(c.ratio, "%.3f"), num(c.lo, "%.2f") + "-" + num(c.hi, "%.2f"), std::to_string(c.paired_seeds.size()),
                    num(c.paired, "%.3f"), c.paired_seeds.empty() ? "-" : num(c.paired_lo, "%.2f") + "-" + num(c.paired_hi, "%.2f")});
  return rows;
}

nlohmann::json to_json(const GatherResult& r) {
  nlohmann::json runs = nlohmann::json::array(), sums = nlohmann::json::array();
  for (const auto& run : r.runs) {
    nlohmann::json v = nlohmann::json::object();
    for (const auto& [k, x] : run.values) v[k] = x;
    runs.push_back({{"dir", shown_text(run.dir)}, {"group", run.group}, {"group_label", run.group_label}, {"seed", run.seed},
                    {"stage", run.stage}, {"values", v}});
  }
  auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  for (const auto& s : r.summaries) {
    nlohmann::json rate;
    if (s.rate)
      rate = {{"passed", s.rate->passed}, {"failed", s.rate->failed}, {"cannot_judge", s.rate->cannot_judge},
              {"runs", s.rate->runs()}, {"share", s.rate->share()}, {"text", s.rate->text()}};
    sums.push_back({{"group", s.group}, {"group_label", s.group_label}, {"scope", s.scope}, {"metric", s.metric},
                    {"n", runs_of(s)}, {"values", s.values}, {"seeds", s.seeds}, {"median", s.median}, {"q1", s.q1},
                    {"q3", s.q3}, {"min", s.min}, {"max", s.max}, {"pass_rate", rate}, {"reference", optional(s.reference)},
                    {"ratio_of_medians", optional(s.ratio)}, {"share_within_bound", optional(s.within)}});
  }
  nlohmann::json refs = nlohmann::json::array();
  for (const auto& ref : r.options.references) refs.push_back({{"exemplar", shown_text(ref.exemplar)}, {"file", shown_text(ref.file)}});
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : r.comparisons)
    comps.push_back({{"group_label", c.group_label}, {"baseline", c.baseline_label}, {"scope", c.scope}, {"metric", c.metric},
                     {"n", c.n}, {"n_baseline", c.n_baseline}, {"ratio_of_medians", c.ratio}, {"bootstrap_5", c.lo},
                     {"bootstrap_95", c.hi}, {"paired_seeds", c.paired_seeds}, {"paired_ratios", c.paired_ratios},
                     {"paired_median", c.paired}, {"paired_bootstrap_5", c.paired_lo},
                     {"paired_bootstrap_95", c.paired_hi}});
  return {{"references", refs}, {"bound", r.options.bound}, {"runs", runs}, {"summaries", sums},
          {"evaluation", r.options.protocol ? std::string(patch_protocol_name(*r.options.protocol)) : std::string("metrics.json")},
          {"baselines", r.options.baselines}, {"comparisons", comps}, {"left_out", r.unfinished}, {"notes", r.notes}};
}

// "12 finished runs" or "10 finished runs and 5 stage snapshots" (GatherOptions::stages).
std::string runs_text(const GatherResult& r) {
  const auto snapshots = std::count_if(r.runs.begin(), r.runs.end(), [](const GatheredRun& x) { return x.stage > 0; });
  const std::string finished = std::to_string(r.runs.size() - static_cast<size_t>(snapshots)) + " finished runs";
  return snapshots == 0 ? finished : finished + " and " + std::to_string(snapshots) + " stage snapshots";
}

// The notes (GatherResult::notes) as paragraphs above the Markdown's tables.
std::string notes_markdown(const std::vector<std::string>& notes) {
  std::string md;
  for (const auto& n : notes) md += "Note: " + n + ".\n\n";
  return md;
}

// A plot's file name: letters, digits, '_' and '-' kept, the rest '_'.
std::string file_stem(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return name;
}

// One strip plot per scope and metric, a column per group.
std::vector<std::pair<std::string, std::string>> write_plots(const GatherResult& r, const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> keys;  // scope, metric in first-seen order
  for (const auto& s : r.summaries)
    if (std::find(keys.begin(), keys.end(), std::make_pair(s.scope, s.metric)) == keys.end()) keys.push_back({s.scope, s.metric});
  std::vector<std::pair<std::string, std::string>> images;
  fs::create_directories(dir + "/plots");
  for (const auto& [scope, metric] : keys) {
    StripPlot plot;
    plot.title = scope + ": " + metric;
    plot.ylabel = metric;
    std::set<double> refs;
    size_t with_reference = 0;
    for (const auto& s : r.summaries)
      if (s.scope == scope && s.metric == metric) {
        plot.groups.push_back(StripGroup{s.group_label, s.values});
        if (s.reference) refs.insert(*s.reference), ++with_reference;
      }
    // One reference value that holds for every group of the plot: draw it and the bound (a
    // line across groups of other exemplars would compare them with a pattern they never had).
    if (refs.size() == 1 && with_reference == plot.groups.size()) {
      plot.reference = *refs.begin();
      plot.reference_label = "reference";
      plot.bound = r.options.bound * *refs.begin();
      plot.bound_label = num(r.options.bound, "%g") + " x reference";
    } else if (metric.rfind("border_density_", 0) == 0) {  // over uniform's by definition
      plot.reference = 1.0;
      plot.reference_label = "uniform points";
    }
    const std::string png = dir + "/plots/" + file_stem(scope + "_" + metric) + ".png";
    plot_strips(png, plot);
    images.push_back({png, plot.title});
  }
  return images;
}

// Per baseline, one strip plot per metric of all classes: each other group's per-seed ratios
// over the baseline (a dot per seed both ran), a line at 1.
std::vector<std::pair<std::string, std::string>> write_paired_plots(const GatherResult& r, const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> images;
  for (size_t b = 0; b < r.options.baselines.size(); ++b) {
    const std::string& baseline = r.options.baselines[b];
    std::vector<std::string> metrics;  // first-seen order
    for (const auto& c : r.comparisons)
      if (c.baseline_label == baseline && c.scope == "all" && std::find(metrics.begin(), metrics.end(), c.metric) == metrics.end())
        metrics.push_back(c.metric);
    for (const auto& metric : metrics) {
      StripPlot plot;
      plot.title = "all: " + metric + ", per seed over " + baseline;
      plot.ylabel = metric + " / the baseline's (same seed)";
      for (const auto& c : r.comparisons)
        if (c.baseline_label == baseline && c.scope == "all" && c.metric == metric && c.group_label != baseline &&
            !c.paired_ratios.empty())
          plot.groups.push_back(StripGroup{c.group_label, c.paired_ratios});
      if (plot.groups.empty()) continue;
      plot.reference = 1.0;
      plot.reference_label = "the baseline";
      const std::string png = dir + "/plots/paired_" + std::to_string(b + 1) + "_" + file_stem(metric) + ".png";
      plot_strips(png, plot);
      images.push_back({png, plot.title});
    }
  }
  return images;
}

}  // namespace

// Each group's label on a line of its own above its rows: labels carry a sweep's grid keys
// ("lemon_4c_v2 (preset fast) [method.border_relax.iterations=0]") and a column cut to a fixed
// width would print two groups that differ only at the end as one.
std::string format_gather(const GatherResult& r) {
  std::string s = "evaluation: " + evaluation_text(r.options) + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "  %-14s %-22s %3s %11s %11s %11s %9s %7s\n", "scope", "metric", "n", "median", "q1", "q3",
                "ref", "ratio");
  s += line;
  std::string group;
  for (const auto& m : r.summaries) {
    if (m.group != group) s += m.group_label + "\n", group = m.group;
    if (m.rate)  // the verdict's pass rate across the three number columns
      std::snprintf(line, sizeof line, "  %-14.14s %-22.22s %3zu   pass %s\n", m.scope.c_str(), m.metric.c_str(), runs_of(m),
                    m.rate->text().c_str());
    else
      std::snprintf(line, sizeof line, "  %-14.14s %-22.22s %3zu %11s %11s %11s %9s %7s\n", m.scope.c_str(), m.metric.c_str(),
                    m.values.size(), num(m.median, "%.5g").c_str(), num(m.q1, "%.5g").c_str(), num(m.q3, "%.5g").c_str(),
                    opt(m.reference, "%.5g").c_str(), opt(m.ratio, "%.3f").c_str());
    s += line;
  }
  if (!r.comparisons.empty()) {
    std::snprintf(line, sizeof line, "\nagainst baselines: ratio of medians, and paired by seed\n  %-14s %-22s %3s %9s %13s %5s %9s %13s\n",
                  "scope", "metric", "n", "ratio", "90% interval", "pairs", "per-seed", "90% interval");
    s += line;
    std::string pair;
    for (const auto& c : r.comparisons) {
      const std::string heading = c.group_label + "\n  over " + c.baseline_label + "\n";
      if (heading != pair) s += heading, pair = heading;
      std::snprintf(line, sizeof line, "  %-14.14s %-22.22s %3zu %9s %13s %5zu %9s %13s\n", c.scope.c_str(), c.metric.c_str(), c.n,
                    num(c.ratio, "%.3f").c_str(), (num(c.lo, "%.2f") + "-" + num(c.hi, "%.2f")).c_str(), c.paired_seeds.size(),
                    num(c.paired, "%.3f").c_str(),
                    c.paired_seeds.empty() ? "-" : (num(c.paired_lo, "%.2f") + "-" + num(c.paired_hi, "%.2f")).c_str());
      s += line;
    }
  }
  if (!r.unfinished.empty()) s += std::to_string(r.unfinished.size()) + " run(s) left out (not finished)\n";
  for (const auto& n : r.notes) s += "note: " + n + "\n";
  return s;
}

void write_gather(const GatherResult& r, const std::string& out, bool force) {
  // Never into what it read: a gather's directory that holds, or lies inside, one of its inputs
  // would delete runs when replaced (--force) or be gathered by the next gather.
  const fs::path target = fs::weakly_canonical(fs::absolute(out));
  for (const auto& in : r.inputs) {
    const fs::path input = fs::weakly_canonical(fs::absolute(in));
    auto inside = [](const fs::path& a, const fs::path& b) {  // a is b or lies inside it
      auto ai = a.begin(), bi = b.begin();
      for (; bi != b.end(); ++ai, ++bi)
        if (ai == a.end() || *ai != *bi) return false;
      return true;
    };
    if (inside(target, input) || inside(input, target))
      throw InputError("-o " + out + ": " + (inside(target, input) ? "is, or lies inside, the input " : "holds the input ") + in +
                       "; a gather's tables go to a directory of their own. Nothing was changed.");
  }
  RunDirOptions o;
  o.kind = "gather";
  o.force = force;
  RunDirectory dir = RunDirectory::open(out, o);
  try {
    const std::string d = dir.path();
    write_table_csv(d + "/gather.csv", summary_header(), summary_rows(r));
    const auto [seed_header, seed_rows] = per_seed_table(r);
    write_table_csv(d + "/per_seed.csv", seed_header, seed_rows);
    std::string md = "# Gathered runs\n\n" + runs_text(r) +
                     (r.options.references.empty() ? "" : "; reference " + references_text(r.options) + ", bound " + num(r.options.bound, "%g") + " x") +
                     ".\n\n" + notes_markdown(r.notes) + table_markdown(summary_header(), summary_rows(r)) +
                     (r.comparisons.empty() ? std::string()
                                            : "\n## Against baselines\n\nRatio of medians and its 90 % bootstrap interval "
                                              "(seeds resampled); each baseline against itself shows the spread of chance. "
                                              "Paired: the median of the ratios of the seeds both ran (each seed's value over "
                                              "the baseline's of that seed) and its 90 % bootstrap interval (pairs resampled).\n\n" +
                                                  table_markdown(comparison_header(), comparison_rows(r))) +
                     "\n## Per seed\n\n" + table_markdown(seed_header, seed_rows);
    if (!r.comparisons.empty()) write_table_csv(d + "/baselines.csv", comparison_header(), comparison_rows(r));
    write_text_atomic(d + "/gather.md", md);
    write_text_atomic(d + "/gather.json", to_json(r).dump(1) + "\n");
    HtmlReport html("ppsynth gather: " + runs_text(r));
    html.add_paragraph("Every finished run, grouped by configuration with the seeds pooled: one dot per seed, the box from "
                       "the first to the third quartile with the median, whiskers to the extremes.");
    std::vector<std::pair<std::string, std::string>> kv = {{"runs", runs_text(r)},
                                                           {"left out (unfinished)", std::to_string(r.unfinished.size())},
                                                           {"evaluation", evaluation_text(r.options)}};
    if (!r.options.references.empty()) {
      kv.push_back({"reference", references_text(r.options)});
      kv.push_back({"bound", num(r.options.bound, "%g") + " x the reference's value"});
    }
    html.add_key_values(kv);
    for (const auto& n : r.notes) html.add_paragraph("Note: " + n + ".");
    html.add_image_row(write_plots(r, d));
    html.add_heading("Summary");
    html.add_table(summary_header(), summary_rows(r));
    if (!r.comparisons.empty()) {
      html.add_heading("Against baselines");
      html.add_paragraph("Ratio of each group's median to its baseline's, with a 90 % bootstrap interval (the seeds of both "
                         "groups resampled). The baseline against itself shows how far two medians of that many seeds part by chance. "
                         "Paired: each seed both groups ran gives one ratio (its value over the baseline's of the same seed); "
                         "their median and its 90 % bootstrap interval (the pairs resampled). A change that acts late in a run "
                         "shares the seed's trajectory up to it, so the pairs see it through less of the seeds' own luck.");
      html.add_table(comparison_header(), comparison_rows(r));
      if (const auto paired = write_paired_plots(r, d); !paired.empty()) {
        html.add_paragraph("Per seed: each dot is one seed's value over the baseline's value of the same seed.");
        html.add_image_row(paired);
      }
    }
    html.add_heading("Per seed");
    html.add_table(seed_header, seed_rows);
    html.write(d + "/index.html");
    dir.mark_complete({{"runs", r.runs.size()}});
  } catch (...) {
    dir.discard();
    throw;
  }
}

}  // namespace ppsynth
