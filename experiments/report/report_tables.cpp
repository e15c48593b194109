#include "experiments/report/report_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/atomic_file.hpp"
#include "core/report/html_report.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"

namespace ppsynth {

namespace {

using json = nlohmann::json;

const json kNull;

// metrics["all"][key], metrics["output"][key], ... ; null when absent.
const json& metric(const ColumnResult& c, const std::string& group, const std::string& key) {
  if (c.status != "ok" || !c.metrics.is_object() || !c.metrics.contains(group)) return kNull;
  const json& g = c.metrics[group];
  return g.is_object() && g.contains(key) ? g[key] : kNull;
}

// Overlapping disk pairs (all classes) of the output, or of the exemplar ("exemplar").
json overlap_pairs(const ColumnResult& c, const std::string& which = "output") {
  if (c.status != "ok" || !c.metrics.contains("overlap")) return nullptr;
  const json& o = c.metrics["overlap"][which];
  return o.is_array() && !o.empty() ? o[0]["pairs"] : json(nullptr);
}

const ColumnResult* find_column(const PanelResult& p, const std::string& name) {
  for (auto& c : p.columns)
    if (c.column == name) return &c;
  return nullptr;
}

const PanelSpec& table_panel_spec(const ReproduceConfig& c, const PanelResult& p) {
  for (auto& s : c.panels)
    if (s.name == p.name) return s;
  return c.panels.front();
}

std::string seconds_cell(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", s);
  return b;
}

std::string panel_label(const PanelSpec& s) { return s.title == s.name ? s.name : s.name + ": " + s.title; }

// The method columns a table shows: its own list, else every column of the figure's panels.
std::vector<std::string> table_methods(const TableSpec& t, const ReproduceConfig& c) {
  if (!t.methods.empty()) return t.methods;
  std::vector<std::string> v;
  for (auto& p : c.panels)
    for (auto& m : p.methods)
      if (std::find(v.begin(), v.end(), m) == v.end()) v.push_back(m);
  return v;
}

void add_unique(std::vector<std::string>& v, const std::string& s) {
  if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
}

ReportTable comparison_table(const TableSpec& t, const ReproduceConfig& c, const ReproduceResult& r) {
  const std::vector<std::pair<std::string, std::string>> metrics = {
      {"pcf_mse", "PCF MSE"}, {"wasserstein", "Wasserstein"}, {"chamfer", "Chamfer"}};
  const auto methods = table_methods(t, c);
  // Per metric: our columns, then published-only names from the panels' "paper" objects.
  std::vector<std::vector<std::string>> cols(metrics.size());
  for (size_t m = 0; m < metrics.size(); ++m) {
    cols[m] = methods;
    for (auto& p : c.panels)
      if (p.paper.contains(metrics[m].first) && p.paper[metrics[m].first].is_object())
        for (auto it = p.paper[metrics[m].first].begin(); it != p.paper[metrics[m].first].end(); ++it) add_unique(cols[m], it.key());
  }
  ReportTable tab;
  tab.header = {"scene"};
  for (size_t m = 0; m < metrics.size(); ++m)
    for (auto& col : cols[m]) tab.header.push_back(metrics[m].second + " " + col);
  for (auto& pr : r.panels) {
    const PanelSpec& s = table_panel_spec(c, pr);
    if (s.kind != "synthesis") continue;
    std::vector<std::string> row = {panel_label(s)};
    for (size_t m = 0; m < metrics.size(); ++m)
      for (auto& col : cols[m]) {
        const ColumnResult* cr = find_column(pr, col);
        row.push_back(cr ? format_cell(metric(*cr, "all", metrics[m].first)) : "n/a");
      }
    tab.rows.push_back(row);
    bool any_paper = false;
    std::vector<std::string> prow = {panel_label(s) + " (paper)"};
    for (size_t m = 0; m < metrics.size(); ++m)
      for (auto& col : cols[m]) {
        const json& pm = s.paper.contains(metrics[m].first) ? s.paper[metrics[m].first] : kNull;
        if (pm.is_object() && pm.contains(col)) {
          prow.push_back(format_cell(pm[col]));
          any_paper = true;
        } else {
          prow.push_back("");
        }
      }
    if (any_paper) tab.rows.push_back(prow);
  }
  return tab;
}

ReportTable relative_radius_table(const TableSpec& t, const ReproduceConfig& c, const ReproduceResult& r) {
  const auto methods = table_methods(t, c);
  std::vector<std::string> cols = {"exemplar"};
  for (auto& m : methods) cols.push_back(m);
  if (t.paper.is_object())
    for (auto it = t.paper.begin(); it != t.paper.end(); ++it) add_unique(cols, it.key());
  ReportTable tab;
  tab.header = {"scene", "exemplar points"};
  for (auto& col : cols) tab.header.push_back("rho " + col);
  for (auto& pr : r.panels) {
    const PanelSpec& s = table_panel_spec(c, pr);
    if (s.kind != "synthesis") continue;
    std::vector<std::string> row = {panel_label(s), std::to_string(pr.exemplar.size())};
    json ex_rho = nullptr;
    for (auto& col : pr.columns)
      if (col.status == "ok") {
        ex_rho = metric(col, "exemplar", "relative_radius");
        break;
      }
    for (auto& col : cols) {
      if (col == "exemplar") {
        row.push_back(format_cell(ex_rho));
        continue;
      }
      const ColumnResult* cr = find_column(pr, col);
      row.push_back(cr ? format_cell(metric(*cr, "output", "relative_radius")) : "n/a");
    }
    tab.rows.push_back(row);
  }
  if (t.paper.is_object()) {
    std::vector<std::string> prow = {"paper", ""};
    for (auto& col : cols) prow.push_back(t.paper.contains(col) ? format_cell(t.paper[col]) : "");
    tab.rows.push_back(prow);
  }
  return tab;
}

// "AMD EPYC (avx512_bf16), preset variant 'every processor'": the run's processor and preset variant.
std::string processor_cell(const ColumnResult& col) {
  const std::string processor = col.processor.empty() ? "not recorded" : col.processor;
  return col.preset_variant.empty() ? processor : processor + ", preset variant '" + col.preset_variant + "'";
}

ReportTable runtime_table(const TableSpec& t, const ReproduceConfig& c, const ReproduceResult& r) {
  const std::string who = t.methods.empty() ? "ours" : t.methods.front();
  // Published columns in Table 3's order first (JSON objects do not keep their key order).
  std::vector<std::string> paper_keys;
  std::vector<std::string> present;
  for (auto& p : c.panels)
    for (auto it = p.paper.begin(); it != p.paper.end(); ++it) add_unique(present, it.key());
  for (const char* k : {"classes", "output samples", "attributes", "PPS runtime (min)", "ours runtime (min)"})
    if (std::find(present.begin(), present.end(), k) != present.end()) paper_keys.push_back(k);
  for (auto& k : present) add_unique(paper_keys, k);
  ReportTable tab;
  tab.header = {"scene", "classes", "map attributes", "exemplar points", "output points", "iterations (" + who + ")",
                "synthesis s (" + who + ")", "synthesis min (" + who + ")", "s per iteration (" + who + ")",
                // what the work cost, whatever shared the cores (0: the run did not record it)
                "synthesis CPU s (" + who + ")", "run total s",
                // times compare only on one kind of processor, and reused runs may come from several
                "processor (" + who + ")"};
  for (auto& k : paper_keys) tab.header.push_back("paper: " + k);
  for (auto& pr : r.panels) {
    const PanelSpec& s = table_panel_spec(c, pr);
    if (s.kind != "synthesis") continue;
    const ColumnResult* cr = find_column(pr, who);
    const bool ok = cr && cr->status == "ok";
    // Attributes that weight the maps (Gabor: method.map_attributes), not every file column.
    std::string attrs = "0";
    if (ok && cr->config["method"].value("type", "") == "gabor")
      attrs = std::to_string(map_attribute_columns(pr.exemplar, cr->config["method"]["map_attributes"]).size());
    std::vector<std::string> row = {panel_label(s), std::to_string(pr.exemplar.num_classes()), attrs, std::to_string(pr.exemplar.size()),
                                    ok ? std::to_string(cr->output.size()) : "n/a", ok ? std::to_string(cr->iterations) : "n/a",
                                    ok ? seconds_cell(cr->synthesis_seconds) : "n/a",
                                    ok ? format_cell(cr->synthesis_seconds / 60.0, 2) : "n/a",
                                    // capped runs (a 2-core machine) compare by cost per iteration
                                    ok && cr->iterations > 0 ? format_cell(cr->synthesis_seconds / cr->iterations, 2) : "n/a",
                                    ok && cr->cpu_seconds > 0 ? seconds_cell(cr->cpu_seconds) : "n/a",
                                    ok ? seconds_cell(cr->seconds) : "n/a", ok ? processor_cell(*cr) : "n/a"};
    for (auto& k : paper_keys) row.push_back(s.paper.contains(k) ? format_cell(s.paper[k], 2) : "");
    tab.rows.push_back(row);
  }
  return tab;
}

}  // namespace

std::string format_cell(const json& v, int decimals) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (!v.is_number()) return "n/a";
  const double x = v.get<double>();
  if (!std::isfinite(x)) return "n/a";
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, x);
  return b;
}

ReportTable metrics_table(const ReproduceConfig& c, const ReproduceResult& r) {
  ReportTable tab;
  tab.name = "metrics";
  tab.caption = "Every panel and method column against its exemplar: 4-quadrant PCF MSE, Wasserstein and Chamfer "
                "distances (method.md section 6), relative radius of the output (exemplar's in parentheses), "
                "overlapping disk pairs (disk patterns), optimization iterations, the synthesis's wall and CPU time "
                "(the CPU time does not grow when other runs share the cores) and the run's wall time.";
  tab.header = {"panel", "method", "status", "points", "PCF MSE", "Wasserstein", "Chamfer", "rho output (exemplar)",
                "overlapping disk pairs output (exemplar)", "iterations", "synthesis s", "synthesis CPU s", "run s"};
  for (auto& pr : r.panels) {
    const PanelSpec& s = table_panel_spec(c, pr);
    if (s.kind != "synthesis") continue;
    for (auto& col : pr.columns) {
      const bool ran = !col.run_dir.empty();
      tab.rows.push_back({s.name, col.column, col.status, col.status == "ok" ? std::to_string(col.output.size()) : "n/a",
                          format_cell(metric(col, "all", "pcf_mse"), 5), format_cell(metric(col, "all", "wasserstein")),
                          format_cell(metric(col, "all", "chamfer")),
                          format_cell(metric(col, "output", "relative_radius")) + " (" +
                              format_cell(metric(col, "exemplar", "relative_radius")) + ")",
                          overlap_pairs(col).is_null() ? "n/a" : format_cell(overlap_pairs(col)) + " (" + format_cell(overlap_pairs(col, "exemplar")) + ")", ran ? std::to_string(col.iterations) : "",
                          ran ? seconds_cell(col.synthesis_seconds) : "",
                          ran ? (col.cpu_seconds > 0 ? seconds_cell(col.cpu_seconds) : "n/a") : "", ran ? seconds_cell(col.seconds) : ""});
    }
  }
  return tab;
}

ReportTable build_table(const TableSpec& t, const ReproduceConfig& c, const ReproduceResult& r) {
  ReportTable tab = t.type == "comparison" ? comparison_table(t, c, r) : t.type == "relative_radius" ? relative_radius_table(t, c, r) : runtime_table(t, c, r);
  tab.name = t.name;
  tab.caption = t.caption;
  return tab;
}

void write_table_files(const ReportTable& t, const std::string& dir) {
  write_table_csv(dir + "/" + t.name + ".csv", t.header, t.rows);
  std::string md = "**" + t.name + "**" + (t.caption.empty() ? "" : ": " + t.caption) + "\n\n" + table_markdown(t.header, t.rows);
  write_text_atomic(dir + "/" + t.name + ".md", md);
}

}  // namespace ppsynth
