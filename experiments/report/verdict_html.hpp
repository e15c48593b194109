#pragma once
// How a paper item's verdict and its numbers over seeds read on a page: the verdict, the rule
// in words, each check with the numbers that decided it; a table of median [min - max] (seeds)
// per group and metric. Shared by a figure's report (report_writer.hpp) and the page over all
// items (reproduce_page.hpp); both read the JSON of report.json.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/report/html_report.hpp"
#include "experiments/plan/reproduce_rule.hpp"

namespace ppsynth {

// PCF MSE, then every metric the rule reads, in rule order.
std::vector<std::string> shown_metrics(const ReproduceRule& rule);
// The same from a report.json's "rule" block (the checks' "metric" keys).
std::vector<std::string> shown_metrics(const nlohmann::json& rule);

// "median [min - max] (n)" of a group's metric in numbers_json()'s "groups"; "" when absent.
std::string spread_cell(const nlohmann::json& groups, const std::string& group, const std::string& metric);

// The verdict as a colored label (HTML): green reproduced, orange partly, red not reproduced.
std::string verdict_badge(const std::string& verdict);
// A check's numbers in words (verdict_json's "numbers"), and when its groups ran under
// different preset variants, that it is not like for like and which ran under which.
std::string check_numbers_text(const nlohmann::json& check);
// verdict_json()'s object: the verdict, the statement, the checks table.
void add_verdict_section(HtmlReport& rep, const nlohmann::json& verdict, int level = 2);
// A config's "diagnosis" (reproduce_config.hpp; written after the runs): why the verdict falls
// short, the published code's number, the lab page; nothing when it holds no text.
void add_diagnosis_section(HtmlReport& rep, const nlohmann::json& diagnosis, int level = 2);
std::string diagnosis_markdown(const nlohmann::json& diagnosis);
// numbers_json()'s object as a table (rows: groups with any of `metrics`).
void add_numbers_table(HtmlReport& rep, const nlohmann::json& numbers, const std::vector<std::string>& metrics,
                       const std::string& caption);
// The same table as Markdown rows.
std::string numbers_markdown(const nlohmann::json& numbers, const std::vector<std::string>& metrics);

// Every config's rule as a Markdown table (item, paper, rule, checks): `ppsynth reproduce
// --rules`, the generated section of docs/howto/reproduce_a_figure.md.
std::string rules_markdown(const std::vector<std::string>& config_files);

}  // namespace ppsynth
