#include "experiments/report/report_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <map>
#include <filesystem>
#include <set>

#include "core/revision.hpp"
#include "experiments/report/report_tables.hpp"
#include "experiments/report/verdict_html.hpp"
#include "core/atomic_file.hpp"
#include "core/render/plot_points.hpp"
#include "core/report/html_report.hpp"
#include "optim/run/run_options_of.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

using json = nlohmann::json;

std::string seconds_text(double s) {
  char b[64];
  if (s >= 120) std::snprintf(b, sizeof b, "%.1f s (%.1f min)", s, s / 60);
  else std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

const PanelSpec& writer_panel_spec(const ReproduceConfig& c, const std::string& name) {
  for (auto& s : c.panels)
    if (s.name == name) return s;
  return c.panels.front();
}

// Curves make report.json large; the HTML has them as plots.
json without_curves(json j) {
  if (j.is_object()) {
    j.erase("pcf");
    j.erase("spectrum");
    for (auto& [k, v] : j.items()) v = without_curves(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = without_curves(v);
  }
  return j;
}

void add_wide_table(HtmlReport& rep, const ReportTable& t, const std::string& files_note) {
  rep.add_paragraph(t.caption + files_note);
  rep.add_html("<div style=\"overflow-x:auto\">");
  rep.add_table(t.header, t.rows);
  rep.add_html("</div>");
}

// One row per panel: exemplar + its method columns. Consecutive panels that share an exemplar
// and have a single column (an ablation's variants) share one row: exemplar + each variant.
bool write_overview(const ReproduceConfig& c, const ReproduceResult& r, const std::string& path) {
  using Row = std::vector<std::pair<std::string, PointSet>>;
  std::vector<Row> rows;
  std::string group_source;  // exemplar of the open variant row ("" = none open)
  for (auto& p : r.panels) {
    const PanelSpec& s = writer_panel_spec(c, p.name);
    if (s.kind != "synthesis") continue;
    if (p.columns.size() == 1) {
      const ColumnResult& col = p.columns.front();
      // Same file and same classes (merge_classes changes the exemplar, not its file).
      const std::string key = p.exemplar_source + "|" + std::to_string(p.exemplar.num_classes());
      if (rows.empty() || group_source.empty() || group_source != key) {
        rows.push_back({{"exemplar", p.exemplar}});
        group_source = key;
      }
      rows.back().push_back({s.title + (col.status == "ok" ? "" : " (n/a)"), col.output});
      continue;
    }
    group_source.clear();
    rows.push_back({{p.name + ": exemplar", p.exemplar}});
    for (auto& col : p.columns) rows.back().push_back({p.name + ": " + col.column + (col.status == "ok" ? "" : " (n/a)"), col.output});
  }
  if (rows.empty()) return false;
  size_t width = 0;
  for (auto& row : rows) width = std::max(width, row.size());
  std::vector<std::pair<std::string, PointSet>> sets;
  for (auto& row : rows) {
    for (auto& cell : row) sets.push_back(cell);
    for (size_t k = row.size(); k < width; ++k) sets.push_back({"", PointSet()});
  }
  plot_panels(path, sets, PointStyle{}, 300, static_cast<int>(width));
  return true;
}

std::string command_line(const ReproduceConfig& c, const ReproduceOptions& o) {
  std::string s = "ppsynth reproduce " + (c.source.empty() ? c.name : fs::path(c.source).stem().string());
  if (o.quick) s += " --quick";
  if (!o.seeds.empty()) s += " --seeds " + o.seeds;
  for (auto& v : o.overrides) s += " --set " + v;
  return s;
}

}  // namespace

// A panel's section: its plots, then per synthesized column the run's curves, snapshots,
// per-stage table and config. Returns the panel's numbers for report.json.
json add_panel_section(HtmlReport& rep, const ReproduceConfig& c, const ReproduceResult& r, const PanelResult& p) {
  const std::string& dir = r.dir;
  const PanelSpec& s = writer_panel_spec(c, p.name);
  rep.add_heading(s.name + ": " + s.title);
  if (!s.note.empty()) rep.add_paragraph(s.note);
  rep.add_key_values({{"exemplar", p.exemplar_source},
                      {"exemplar points / classes / attributes", std::to_string(p.exemplar.size()) + " / " +
                                                                     std::to_string(p.exemplar.num_classes()) + " / " +
                                                                     std::to_string(p.exemplar.num_attributes())},
                      {"panel wall time", seconds_text(p.seconds)}});
  for (auto& [img, caption] : p.images) rep.add_image(dir + "/" + img, caption);
  if (!s.paper.empty()) rep.add_code_block(s.paper.dump(2), "published numbers for this panel");

  json pj = {{"name", s.name}, {"title", s.title}, {"note", s.note}, {"exemplar", p.exemplar_source},
             {"exemplar_points", p.exemplar.size()}, {"seconds", p.seconds}, {"paper", s.paper}, {"images", json::array()},
             {"columns", json::array()}};
  for (auto& [img, caption] : p.images) pj["images"].push_back({{"file", img}, {"caption", caption}});
  for (auto& col : p.columns) {
    json cj = {{"column", col.column}, {"status", col.status}, {"source", col.source}, {"run_dir", col.run_dir},
               {"points", col.output.size()}, {"seconds", col.seconds}, {"synthesis_seconds", col.synthesis_seconds},
               {"iterations", col.iterations}, {"cpu_seconds", col.cpu_seconds}, {"processor", col.processor},
               {"preset_variant", col.preset_variant}, {"metrics", without_curves(col.metrics)}};
    pj["columns"].push_back(cj);
    if (col.status == "pending") {
      rep.add_paragraph(col.column + ": not available (the method is not registered in this build).");
      continue;
    }
    if (col.status == "missing") {
      rep.add_paragraph(col.column + ": no " + (col.column == "reference" ? "published output" : "initialization") + " for this panel.");
      continue;
    }
    if (col.run_dir.empty()) continue;  // init / reference: in the plots and tables above
    const std::string run = dir + "/" + col.run_dir;
    const TypedRunOptions run_options = run_options_of(col.config, run + "/config.json");
    rep.add_heading(s.name + " / " + col.column, 3);
    rep.add_key_values({{"run directory", col.run_dir},
                        {"method", run_options.method_type},
                        {"seed", std::to_string(run_options.seed)},
                        {"iterations (all stages)", std::to_string(col.iterations)},
                        {"synthesis wall time", seconds_text(col.synthesis_seconds)},
                        {"run wall time (with plots and metrics)", seconds_text(col.seconds)},
                        {"made on", col.processor.empty() ? "not recorded" : col.processor},
                        {"preset variant", col.preset_variant.empty() ? "no preset" : col.preset_variant}});
    std::vector<std::pair<std::string, std::string>> row;
    if (fs::exists(run + "/loss.png")) row.push_back({run + "/loss.png", "loss per iteration"});
    if (fs::exists(run + "/pcf.png")) row.push_back({run + "/pcf.png", "PCF: exemplar vs output"});
    if (!row.empty()) rep.add_image_row(row);
    if (s.stages) {
      std::vector<std::pair<std::string, std::string>> stages;
      if (fs::exists(run + "/exemplar_vs_output.png")) rep.add_image(run + "/exemplar_vs_output.png", "exemplar, initialization, output");
      for (int k = 1; fs::exists(run + "/snapshots/stage" + (k < 10 ? "0" : "") + std::to_string(k) + ".png"); ++k)
        stages.push_back({run + "/snapshots/stage" + (k < 10 ? "0" : "") + std::to_string(k) + ".png", "after stage " + std::to_string(k)});
      if (!stages.empty()) rep.add_image_row(stages);
    }
    if (!col.stages.empty()) {
      std::vector<std::vector<std::string>> rows;
      for (const StageRecord& st : col.stages)
        rows.push_back({st.stage, format_cell(st.details.value("sigma", json(nullptr)), 5), format_cell(json(st.iterations)),
                        format_cell(json(st.final_loss), 6), format_cell(json(st.seconds), 2)});
      rep.add_table({"stage", "sigma", "iterations", "final loss", "seconds"}, rows, "per stage");
    }
    rep.add_code_block(col.config.dump(2), "resolved run config (" + col.column + ")");
  }
  return pj;
}

// Over seeds (--seeds): what the sweep ran, the all-classes metrics per column (median and
// quartiles), and the strip plots; the whole gather is in seeds/index.html.
void add_seed_section(HtmlReport& rep, const ReproduceResult& r) {
  if (r.sweep_dir.empty()) return;
  std::set<uint64_t> seeds;
  for (const auto& run : r.seeds.runs) seeds.insert(run.seed);
  std::string seed_text;
  for (auto s : seeds) seed_text += (seed_text.empty() ? "" : ", ") + std::to_string(s);
  rep.add_heading("Over seeds");
  rep.add_paragraph("Every synthesized column ran with each of the seeds " + seed_text + " (" + std::to_string(r.seeds.runs.size()) +
                    " runs, the sweep " + r.sweep_dir + "); one seed is one sample. Median [first quartile, third quartile] "
                    "of the all-classes metrics per column; per class, per class pair and per seed: seeds/index.html and "
                    "seeds/gather.csv.");
  std::vector<std::vector<std::string>> rows;
  std::vector<std::pair<std::string, std::string>> plots;
  auto cell = [](const MetricSummary& m) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.4g [%.4g, %.4g]", m.median, m.q1, m.q3);
    return std::string(buf);
  };
  std::map<std::string, std::vector<std::string>> by_group;
  std::vector<std::string> order;
  for (const auto& m : r.seeds.summaries) {
    if (m.scope != "all" || (m.metric != "pcf_mse" && m.metric != "wasserstein" && m.metric != "chamfer")) continue;
    auto& row = by_group[m.group_label];
    if (row.empty()) {
      order.push_back(m.group_label);
      row = {m.group_label, std::to_string(m.values.size()), "", "", ""};
    }
    row[m.metric == "pcf_mse" ? 2 : m.metric == "wasserstein" ? 3 : 4] = cell(m);
  }
  for (const auto& g : order) rows.push_back(by_group[g]);
  rep.add_table({"column (figure-panel-column)", "seeds", "PCF MSE", "Wasserstein", "Chamfer"}, rows);
  for (const char* metric : {"pcf_mse", "wasserstein", "chamfer"}) {
    const std::string png = r.dir + "/seeds/plots/all_" + metric + ".png";
    if (fs::exists(png)) plots.push_back({png, std::string("all classes: ") + metric + " per seed"});
  }
  if (!plots.empty()) rep.add_image_row(plots);
}

void write_reproduce_report(const ReproduceConfig& c, const ReproduceResult& r, const ReproduceOptions& o) {
  const std::string& dir = r.dir;
  HtmlReport rep(c.title);
  if (!c.claim.empty()) rep.add_html("<blockquote style=\"border-left:4px solid #1f77b4;margin:1rem 0;padding:.2rem 1rem;color:#333\"><b>Paper's claim.</b> " +
                                     html_escape(c.claim) + "</blockquote>\n");
  if (!c.description.empty()) rep.add_paragraph(c.description);
  std::set<std::string> seeds;
  for (auto& p : r.panels)
    for (auto& col : p.columns)
      if (!col.run_dir.empty()) seeds.insert(std::to_string(run_options_of(col.config, dir + "/" + col.run_dir + "/config.json").seed));
  std::string seed_text;
  for (auto& s : seeds) seed_text += (seed_text.empty() ? "" : ", ") + s;
  // Over seeds the pictures are one seed's runs, the numbers every seed's: say both. And the
  // command's own time is then mostly gathering: say what the sweep's runs took as well.
  std::string time_text = seconds_text(r.seconds);
  if (!o.seeds.empty()) {
    // A figure of maps alone (fig03) runs nothing: its pictures are the exemplar's, whatever the seeds.
    seed_text = o.seeds + (seed_text.empty() ? " (no runs: the pictures are the exemplar's)" : " (the pictures: seed " + seed_text + ")");
    if (!r.seeds.runs.empty()) {
      double runs_seconds = 0;
      for (const auto& run : r.seeds.runs)
        for (const auto& [key, value] : run.values)
          if (key == "run/seconds") runs_seconds += value;
      time_text += " for this command; " + std::to_string(r.seeds.runs.size()) + " runs in the sweep took " +
                   seconds_text(runs_seconds) + " together";
    }
  }
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  rep.add_key_values({{"paper", c.paper_ref.empty() ? "-" : c.paper_ref},
                      {"kind", c.kind},
                      {"config", c.source.empty() ? "(in memory)" : c.source},
                      {"command", command_line(c, o)},
                      {"mode", r.quick ? "QUICK (tiny grid, few iterations, few filters: a smoke test, not the paper's settings)"
                                       : "full settings"},
                      {"revision", revision()},
                      {"seed(s)", seed_text.empty() ? "-" : seed_text},
                      {"total wall time", time_text},
                      {"written", date}});
  const json aside = presets_set_aside(c, o.overrides);
  for (auto& a : aside)
    rep.add_paragraph("Panel " + a["panel"].get<std::string>() + " ran at the config's own settings, not the " +
                      a["preset"].get<std::string>() + " preset: " + a["why"].get<std::string>());

  const json verdict = verdict_json(judge_item(c.rule, r.numbers));
  const json numbers = numbers_json(r.numbers);
  add_verdict_section(rep, verdict);
  add_diagnosis_section(rep, c.diagnosis);
  add_numbers_table(rep, numbers, shown_metrics(c.rule),
                    "Our numbers per group: median [min - max] (seeds)" + std::string(r.sweep_dir.empty() ? ", one seed" : " over the seeds") +
                        "; 'init' is the initialization each seed's 'ours' started from, 'reference' the published code's output");

  // Which of our exemplars stands in for the paper's.
  std::vector<std::vector<std::string>> subst;
  for (auto& p : r.panels) {
    const PanelSpec& s = writer_panel_spec(c, p.name);
    subst.push_back({s.name, s.title, p.exemplar_source + " (" + std::to_string(p.exemplar.size()) + " points, " +
                                          std::to_string(p.exemplar.num_classes()) + (p.exemplar.num_classes() == 1 ? " class)" : " classes)"),
                     s.note});
  }
  rep.add_heading("Panels and exemplars");
  rep.add_table({"panel", "title", "exemplar", "note"}, subst);

  if (write_overview(c, r, dir + "/figure.png")) {
    rep.add_heading("Figure");
    rep.add_image(dir + "/figure.png", "Exemplar and outputs side by side (figure.png)");
  }

  // A figure without synthesis panels (maps alone) has no metrics: no table of headers only.
  const ReportTable mt = metrics_table(c, r);
  if (!c.tables.empty() || !mt.rows.empty()) rep.add_heading("Tables");
  for (auto& t : c.tables) {
    ReportTable tab = build_table(t, c, r);
    write_table_files(tab, dir);
    rep.add_heading(tab.name, 3);
    add_wide_table(rep, tab, "  [" + tab.name + ".csv, " + tab.name + ".md]");
  }
  if (!mt.rows.empty()) {
    write_table_files(mt, dir);
    rep.add_heading("metrics", 3);
    add_wide_table(rep, mt, "  [metrics.csv, metrics.md]");
  }
  add_seed_section(rep, r);

  json report = {{"name", c.name}, {"title", c.title}, {"claim", c.claim}, {"paper_ref", c.paper_ref}, {"kind", c.kind},
                 {"config", c.source}, {"quick", r.quick}, {"revision", revision()}, {"seconds", r.seconds},
                 {"overrides", o.overrides}, {"presets_set_aside", aside}, {"seeds", o.seeds}, {"sweep", r.sweep_dir},
                 {"figure", fs::exists(dir + "/figure.png") ? "figure.png" : ""},
                 {"rule", c.raw.contains("rule") ? c.raw["rule"] : json(nullptr)}, {"verdict", verdict}, {"diagnosis", c.diagnosis},
                 {"numbers", numbers},
                 {"panels", json::array()}, {"tables", json::array()}};
  for (auto& t : c.tables) report["tables"].push_back(t.name);

  for (auto& p : r.panels) report["panels"].push_back(add_panel_section(rep, c, r, p));

  rep.add_heading("Configuration");
  rep.add_code_block(c.raw.dump(2), "the figure config after parent resolution (" + (c.source.empty() ? std::string("in memory") : c.source) + ")");
  rep.write(dir + "/index.html");
  write_text_atomic(dir + "/report.json", report.dump(2) + "\n");
}

}  // namespace ppsynth
