#include "experiments/report/verdict_html.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "experiments/plan/reproduce_config.hpp"

namespace ppsynth {

namespace {

using json = nlohmann::json;

void add_unique(std::vector<std::string>& v, const std::string& s) {
  if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
}

std::vector<std::vector<std::string>> numbers_rows(const json& numbers, const std::vector<std::string>& metrics) {
  std::vector<std::vector<std::string>> rows;
  if (!numbers.is_object() || !numbers.contains("groups")) return rows;
  for (auto it = numbers["groups"].begin(); it != numbers["groups"].end(); ++it) {
    std::vector<std::string> row = {it.key()};
    bool any = false;
    for (auto& m : metrics) {
      row.push_back(spread_cell(numbers["groups"], it.key(), m));
      any = any || !row.back().empty();
    }
    if (any) rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::vector<std::string> shown_metrics(const ReproduceRule& rule) {
  std::vector<std::string> v = {"all/pcf_mse"};
  for (const RuleCheck& k : rule.checks) add_unique(v, k.metric);
  return v;
}

std::vector<std::string> shown_metrics(const json& rule) {
  std::vector<std::string> v = {"all/pcf_mse"};
  if (rule.is_object() && rule.contains("checks") && rule["checks"].is_array())
    for (auto& k : rule["checks"])
      if (k.is_object() && k.contains("metric") && k["metric"].is_string()) add_unique(v, k["metric"]);
  return v;
}

std::string spread_cell(const json& groups, const std::string& group, const std::string& metric) {
  if (!groups.contains(group) || !groups[group].contains(metric)) return "";
  const json& m = groups[group][metric];
  if (!m["median"].is_number()) return "n/a";
  char b[160];
  if (m.value("fixed", false)) std::snprintf(b, sizeof b, "%.4g (drawn once)", m["median"].get<double>());
  else
    std::snprintf(b, sizeof b, "%.4g [%.4g - %.4g] (%d)", m["median"].get<double>(), m["min"].get<double>(), m["max"].get<double>(),
                  m["n"].get<int>());
  return b;
}

std::string verdict_badge(const std::string& verdict) {
  const char* color = verdict == "reproduced"       ? "#2ca02c"
                      : verdict == "partly"         ? "#ff7f0e"
                      : verdict == "not reproduced" ? "#d62728"
                      : verdict == "not run"        ? "#c7c7c7"
                                                    : "#7f7f7f";
  return "<span style=\"background:" + std::string(color) + ";color:#fff;padding:.1rem .5rem;border-radius:.3rem;white-space:nowrap\">" +
         html_escape(verdict) + "</span>";
}

std::string check_numbers_text(const json& check) {
  std::string text = check.value("numbers", std::string());
  const std::string mixed = check.value("mixed_variants", std::string());
  if (!mixed.empty()) text += ". Not like for like, the runs made under different preset variants: " + mixed;
  return text;
}

void add_verdict_section(HtmlReport& rep, const json& verdict, int level) {
  rep.add_heading("Verdict by rule: " + verdict.value("verdict", std::string("?")), level);
  rep.add_html("<p>" + verdict_badge(verdict.value("verdict", std::string("?"))) + "</p>\n");
  const std::string statement = verdict.value("statement", std::string());
  if (!statement.empty()) rep.add_paragraph("Rule (written before the runs): " + statement);
  std::vector<std::vector<std::string>> rows;
  if (verdict.contains("checks"))
    for (auto& k : verdict["checks"]) rows.push_back({k["check"], k["state"], check_numbers_text(k)});
  if (!rows.empty()) rep.add_table({"check", "result", "the numbers that decided it"}, rows);
}

namespace {

struct DiagnosisLine {
  std::string label, text;
  bool path;  // "see": a file of the repository, shown as code
};

std::vector<DiagnosisLine> diagnosis_lines(const json& d) {
  std::vector<DiagnosisLine> lines;
  if (!d.is_object()) return lines;
  const struct { const char* key; const char* label; } fields[] = {
      {"text", "Why"}, {"published_code", "The published code on this item"}, {"see", "Measured in"}};
  for (const auto& f : fields)
    if (d.contains(f.key) && d[f.key].is_string() && !d[f.key].get<std::string>().empty())
      lines.push_back({f.label, d[f.key].get<std::string>(), std::string(f.key) == "see"});
  return lines;
}

}  // namespace

void add_diagnosis_section(HtmlReport& rep, const json& diagnosis, int level) {
  const auto lines = diagnosis_lines(diagnosis);
  if (lines.empty()) return;
  rep.add_heading("What we know about this verdict (written after the runs)", level);
  std::string html = "<ul>\n";
  for (const auto& l : lines)
    html += "<li><b>" + html_escape(l.label) + ".</b> " +
            (l.path ? "<code>" + html_escape(l.text) + "</code> (in the ppsynth repository)" : html_escape(l.text)) + "</li>\n";
  rep.add_html(html + "</ul>\n");
}

std::string diagnosis_markdown(const json& diagnosis) {
  const auto lines = diagnosis_lines(diagnosis);
  if (lines.empty()) return "";
  std::string md = "**What we know about this verdict** (written after the runs):\n\n";
  for (const auto& l : lines) md += "- **" + l.label + ".** " + (l.path ? "`" + l.text + "`" : l.text) + "\n";
  return md + "\n";
}

void add_numbers_table(HtmlReport& rep, const json& numbers, const std::vector<std::string>& metrics, const std::string& caption) {
  const auto rows = numbers_rows(numbers, metrics);
  if (rows.empty()) return;
  std::vector<std::string> header = {"group (panel/column)"};
  header.insert(header.end(), metrics.begin(), metrics.end());
  rep.add_html("<div style=\"overflow-x:auto\">");
  rep.add_table(header, rows, caption);
  rep.add_html("</div>");
}

std::string numbers_markdown(const json& numbers, const std::vector<std::string>& metrics) {
  const auto rows = numbers_rows(numbers, metrics);
  if (rows.empty()) return "";
  std::vector<std::string> header = {"group (panel/column)"};
  header.insert(header.end(), metrics.begin(), metrics.end());
  return table_markdown(header, rows);
}

std::string rules_markdown(const std::vector<std::string>& config_files) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& f : config_files) {
    const ReproduceConfig c = load_reproduce_config(f);
    std::string checks;
    for (const RuleCheck& k : c.rule.checks) checks += (checks.empty() ? "" : "<br>") + describe_check(k);
    rows.push_back({std::filesystem::path(f).stem().string(), c.paper_ref, c.rule.kind.empty() ? "(none)" : c.rule.kind, c.rule.statement,
                    checks.empty() ? "-" : checks});
  }
  return table_markdown({"item", "paper", "kind", "rule", "checks"}, rows);
}

}  // namespace ppsynth
