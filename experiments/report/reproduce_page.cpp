#include "experiments/report/reproduce_page.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/report/html_report.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/verdict_html.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

using json = nlohmann::json;

const char* kMarker = "<!-- ppsynth: reproduction page -->";

// The paper's order: its figures (ablations among them), tables, the supplement, then the rest.
int item_rank(const std::string& name) {
  for (auto [prefix, rank] : {std::pair<const char*, int>{"fig", 0}, {"table", 1}, {"suppl", 2}})
    if (name.rfind(prefix, 0) == 0) return rank;
  return 3;
}

// "fig03" before "fig10": the digits compared as numbers.
std::pair<std::string, int> natural(const std::string& name) {
  size_t i = name.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(name[i - 1]))) --i;
  return {name.substr(0, i), i < name.size() ? std::stoi(name.substr(i, 9)) : -1};
}

struct Item {
  std::string dir;  // the report's folder name
  json report;
};

bool paper_order(const std::string& a, const std::string& b) {
  return std::make_tuple(item_rank(a), natural(a)) < std::make_tuple(item_rank(b), natural(b));
}

std::string str(const json& j, const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; }

// The paper's items (configs/paper) without a report in `dir`, as summary rows "not run": the
// page then says what is left instead of looking complete. None when the source tree's configs
// are not there (an installed binary).
std::vector<std::vector<std::string>> not_run_rows(const std::vector<Item>& items) {
  std::vector<std::vector<std::string>> rows;
  std::error_code ec;
  if (!fs::is_directory(paper_config_dir(), ec)) return rows;
  for (const std::string& file : list_reproduce_configs(paper_config_dir())) {
    const std::string name = fs::path(file).stem().string();
    if (std::any_of(items.begin(), items.end(), [&](const Item& it) { return it.dir == name; })) continue;
    json c;
    try {
      c = json::parse(read_file_text(file));
    } catch (const json::exception&) {
      c = json::object();  // `ppsynth reproduce --check` names what is wrong with it; here it is a row
    }
    rows.push_back({name, str(c, "paper_ref"), str(c, "claim"), "not run", "-", "-"});
  }
  return rows;
}

std::vector<Item> read_reports(const std::string& dir) {
  std::vector<Item> items;
  for (const auto& e : fs::directory_iterator(dir)) {
    const fs::path file = e.path() / "report.json";
    if (!e.is_directory() || !fs::is_regular_file(file)) continue;
    json j;
    try {
      j = json::parse(read_file_text(file.string()));
    } catch (const json::exception& ex) {
      throw InputError(file.string() + ": not a report's JSON (" + ex.what() + ")");
    }
    if (!j.is_object() || !j.contains("name") || !j["name"].is_string()) throw InputError(file.string() + ": not a report's JSON (no \"name\")");
    items.push_back({e.path().filename().string(), j});
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return paper_order(a.dir, b.dir); });
  return items;
}


const json& verdict_of(const json& r) {
  static const json none = {{"verdict", "no verdict (a report made before rules)"}, {"statement", ""}, {"checks", json::array()}};
  return r.contains("verdict") && r["verdict"].is_object() ? r["verdict"] : none;
}

std::string checks_passed(const json& v) {
  size_t pass = 0, n = 0;
  for (auto& k : v["checks"]) ++n, pass += k.value("state", "") == "pass";
  return n ? std::to_string(pass) + "/" + std::to_string(n) : "-";
}

// The --set overrides a report ran with ("preset=fast"), or the configs' own settings; then
// the panels that kept the config's own settings under that preset (presets_set_aside).
std::string overrides_text(const json& r) {
  std::string t;
  if (r.contains("overrides") && r["overrides"].is_array())
    for (auto& o : r["overrides"])
      if (o.is_string()) t += (t.empty() ? "" : ", ") + o.get<std::string>();
  if (t.empty()) return "the configs' own";
  if (r.contains("presets_set_aside") && r["presets_set_aside"].is_array())
    for (auto& a : r["presets_set_aside"])
      t += "; panel " + a.value("panel", "?") + " at the config's own settings (the " + a.value("preset", "?") +
           " preset is not equivalent there)";
  return t;
}

// The preset variants the item's runs were made under (numbers.made_under), counted over its
// groups and seeds: "without bf16 units (25)", "every processor (10), without bf16 units (5)".
// Kept runs come from machines of both kinds; this line says which network each item rests on.
std::map<std::string, int> variant_counts(const json& r) {
  std::map<std::string, int> count;
  if (r.contains("numbers") && r["numbers"].contains("made_under"))
    for (auto& [group, by_seed] : r["numbers"]["made_under"].items())
      for (auto& [seed, variant] : by_seed.items())
        if (variant.is_string()) ++count[variant.get<std::string>()];
  return count;
}

std::string variants_text(const std::map<std::string, int>& count) {
  std::string t;
  for (auto& [variant, n] : count) t += (t.empty() ? "" : ", ") + variant + " (" + std::to_string(n) + ")";
  return t.empty() ? "no preset recorded" : t;
}

std::string seeds_text(const json& r) {
  const std::string s = str(r, "seeds");
  return s.empty() ? "one (the config's)" : s;
}

// The panels' published numbers, one line each ("a: pcf_mse ours 0.2459, MWT11 0.2678 ...").
std::vector<std::string> paper_lines(const json& r) {
  std::vector<std::string> lines;
  if (!r.contains("panels")) return lines;
  for (auto& p : r["panels"]) {
    if (!p.contains("paper") || !p["paper"].is_object() || p["paper"].empty()) continue;
    std::string line = str(p, "name") + ":";
    for (auto it = p["paper"].begin(); it != p["paper"].end(); ++it) {
      line += " " + it.key();
      if (it.value().is_object())
        for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) line += " " + jt.key() + " " + jt.value().dump() + ",";
      else line += " " + it.value().dump() + ",";
    }
    if (!line.empty() && line.back() == ',') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// The report's overview, else its panels' map images (Fig. 3): paths relative to the page.
std::vector<std::pair<std::string, std::string>> pictures(const Item& it, const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> v;
  if (!str(it.report, "figure").empty()) v.push_back({it.dir + "/" + str(it.report, "figure"), "exemplar and outputs (figure.png)"});
  else if (it.report.contains("panels"))
    for (auto& p : it.report["panels"])
      if (p.contains("images"))
        for (auto& img : p["images"])
          if (fs::exists(fs::path(dir) / it.dir / str(img, "file"))) v.push_back({it.dir + "/" + str(img, "file"), str(img, "caption")});
  return v;
}

}  // namespace

size_t write_reproduce_page(const std::string& dir) {
  if (!fs::is_directory(dir)) throw InputError(dir + ": not a directory of reports");
  const std::string html_path = dir + "/index.html", md_path = dir + "/index.md";
  for (const std::string& f : {html_path, md_path})
    if (fs::exists(f) && read_file_text(f).find(kMarker) == std::string::npos)
      throw InputError(f + " exists and is not a reproduction page of ppsynth: not replaced");
  const std::vector<Item> items = read_reports(dir);
  if (items.empty()) throw InputError(dir + ": no reproduction report (DIR/NAME/report.json) to put on a page");

  std::map<std::string, size_t> counts;
  std::vector<std::vector<std::string>> summary;
  bool quick = false;
  std::map<std::string, int> variants;  // over every item's runs (a run two items share counts twice)
  for (const Item& it : items) {
    const json& v = verdict_of(it.report);
    ++counts[v.value("verdict", "?")];
    for (auto& [variant, n] : variant_counts(it.report)) variants[variant] += n;
    quick = quick || it.report.value("quick", false);
    summary.push_back({it.dir, str(it.report, "paper_ref"), str(it.report, "claim"), v.value("verdict", "?"), checks_passed(v),
                       seeds_text(it.report)});
  }
  const auto missing = not_run_rows(items);
  if (!missing.empty()) counts["not run"] += missing.size();  // beside reports whose checks have no numbers
  summary.insert(summary.end(), missing.begin(), missing.end());
  std::stable_sort(summary.begin(), summary.end(), [](const auto& a, const auto& b) { return paper_order(a[0], b[0]); });
  std::string tally;
  for (auto& [verdict, n] : counts) tally += (tally.empty() ? "" : ", ") + verdict + ": " + std::to_string(n);
  const size_t listed = items.size() + missing.size();
  const std::string mode = (quick ? "QUICK (smoke-test settings: the verdicts mean nothing about the paper)" : "full settings") +
                           std::string("; the runs made under the preset variants ") + variants_text(variants) + ", counted per item";

  HtmlReport rep("Huang et al. 2022, reproduced: every item, its verdict by rule");
  rep.add_html(std::string(kMarker) + "\n");
  rep.add_paragraph("Each item of the paper is one config in configs/paper; its rule (the config's \"rule\" block, written "
                    "before the runs) decides the verdict from the numbers gathered over the seeds: reproduced when every "
                    "check passes, partly when some do, not reproduced when none does, incomplete when a check has no "
                    "numbers; not run: no report in this folder yet. Mode: " + mode + ". " + std::to_string(listed) +
                    " items; " + tally + ".");
  const std::vector<std::string> header = {"item", "paper", "claim", "verdict", "checks passed", "seeds"};
  // As add_table, with the verdict as a colored label and the item linking to its section.
  std::string table = "<table><thead><tr>";
  for (auto& h : header) table += "<th>" + html_escape(h) + "</th>";
  table += "</tr></thead><tbody>\n";
  for (auto& row : summary) {
    // By name, not by the verdict: a report whose checks all lack numbers also reads "not run".
    const bool has_section = std::any_of(items.begin(), items.end(), [&](const Item& it) { return it.dir == row[0]; });
    table += "<tr><td>" + (has_section ? "<a href=\"#" + html_escape(row[0]) + "\">" + html_escape(row[0]) + "</a>" : html_escape(row[0])) +
             "</td>";
    for (size_t i = 1; i < row.size(); ++i) table += "<td>" + (i == 3 ? verdict_badge(row[i]) : html_escape(row[i])) + "</td>";
    table += "</tr>\n";
  }
  rep.add_html(table + "</tbody></table>\n");
  std::string md = std::string(kMarker) + "\n# Huang et al. 2022, reproduced: every item, its verdict by rule\n\nMode: " + mode + ". " +
                   std::to_string(listed) + " items; " + tally + ".\n\n" + table_markdown(header, summary) + "\n";

  for (const Item& it : items) {
    const json& r = it.report;
    const json& v = verdict_of(r);
    rep.add_html("<a id=\"" + html_escape(it.dir) + "\"></a>\n");
    rep.add_heading(it.dir + ": " + str(r, "title"));
    rep.add_html("<blockquote style=\"border-left:4px solid #1f77b4;margin:1rem 0;padding:.2rem 1rem;color:#333\"><b>Paper's claim.</b> " +
                 html_escape(str(r, "claim")) + "</blockquote>\n");
    rep.add_key_values({{"paper", str(r, "paper_ref")},
                        {"seeds", seeds_text(r)},
                        {"mode", r.value("quick", false) ? "QUICK" : "full settings"},
                        {"report", it.dir + "/index.html"},
                        {"settings", overrides_text(r)},
                        {"made under", variants_text(variant_counts(r))},
                        {"revision", str(r, "revision")}});
    add_verdict_section(rep, v, 3);
    add_diagnosis_section(rep, r.contains("diagnosis") ? r["diagnosis"] : json(), 4);
    const auto metrics = shown_metrics(r.contains("rule") ? r["rule"] : json());
    const json numbers = r.contains("numbers") ? r["numbers"] : json::object();
    add_numbers_table(rep, numbers, metrics,
                      "Ours and the others: median [min - max] (seeds); 'reference' is the published code's output, drawn once");
    const auto paper = paper_lines(r);
    if (!paper.empty()) {
      std::string text;
      for (auto& l : paper) text += l + "\n";
      rep.add_code_block(text, "the paper's published numbers (its exemplars, its metric code)");
    }
    for (auto& [file, caption] : pictures(it, dir))
      rep.add_html("<figure><img src=\"" + html_escape(file) + "\" style=\"max-width:100%\" alt=\"" + html_escape(caption) +
                   "\"><figcaption>" + html_escape(caption) + "</figcaption></figure>\n");

    md += "\n## " + it.dir + ": " + str(r, "title") + "\n\n> **Paper's claim.** " + str(r, "claim") + "\n\n**Verdict by rule: " +
          v.value("verdict", "?") + "** (seeds: " + seeds_text(r) + "; settings: " + overrides_text(r) +
          "; made under: " + variants_text(variant_counts(r)) + ")\n\n";
    if (!str(v, "statement").empty()) md += "Rule: " + str(v, "statement") + "\n\n";
    std::vector<std::vector<std::string>> checks;
    for (auto& k : v["checks"]) checks.push_back({k.value("check", ""), k.value("state", ""), check_numbers_text(k)});
    if (!checks.empty()) md += table_markdown({"check", "result", "numbers"}, checks) + "\n";
    md += diagnosis_markdown(r.contains("diagnosis") ? r["diagnosis"] : json());
    md += numbers_markdown(numbers, metrics);
    for (auto& [file, caption] : pictures(it, dir)) md += "\n![" + caption + "](" + file + ")\n";
  }
  rep.write(html_path);
  write_text_atomic(md_path, md);
  return items.size();
}

}  // namespace ppsynth
