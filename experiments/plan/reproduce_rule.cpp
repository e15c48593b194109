#include "experiments/plan/reproduce_rule.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <set>

#include "core/config/config.hpp"
#include "core/error.hpp"

namespace ppsynth {

namespace {

using json = nlohmann::json;

const std::set<std::string> kTypes = {"better", "within", "not_worse", "threshold"};
const std::set<std::string> kOps = {"<", "<=", ">", ">="};
// Metrics a run's evaluation gives per scope (core/metrics/metric_values.hpp), and the two
// the reproduction adds (overlapping disk pairs; the run's iterations).
const std::set<std::string> kScopedMetrics = {"pcf_mse", "wasserstein", "chamfer", "relative_radius", "min_distance_normalized",
                                              "close_pair_share", "l_sup", "overlap_pairs"};
// run/seconds is the wall time; run/cpu_seconds the CPU time, which other runs on the same
// cores do not inflate (a timing rule judged on a sweep of several runs at once).
const std::set<std::string> kRunMetrics = {"seconds", "cpu_seconds", "iterations"};

// The keys each type of check takes (apply_defaults refuses the others, naming them).
json check_defaults(const std::string& type) {
  json d = {{"type", ""}, {"label", ""}, {"metric", ""}, {"group", ""}};
  if (type == "better") {
    d["than"] = json::array();
    d["min_share"] = nullptr;
    d["higher_is_better"] = false;
    d["toward"] = nullptr;
  } else if (type == "within") {
    d["target"] = nullptr;
    d["tolerance"] = 0.1;
  } else if (type == "not_worse") {
    d["target"] = nullptr;
    d["tolerance"] = 0.0;
    d["higher_is_better"] = false;
  } else {
    d["op"] = "";
    d["value"] = nullptr;
    d["min_share"] = nullptr;
  }
  return d;
}

std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

void check_metric(const std::string& metric, const std::string& kp) {
  static const std::regex scoped(R"(^(all|class [0-9]+|classes [0-9]+-[0-9]+)/([a-z_]+)$)");
  static const std::regex run(R"(^run/([a-z_]+)$)");
  std::smatch m;
  if (std::regex_match(metric, m, scoped) && kScopedMetrics.count(m[2])) return;
  if (std::regex_match(metric, m, run) && kRunMetrics.count(m[1])) return;
  std::string names;
  for (auto& n : kScopedMetrics) names += (names.empty() ? "" : ", ") + n;
  throw config_error(kp, "unknown metric '" + metric + "' (expected \"all/NAME\", \"class N/NAME\" or \"classes N-M/NAME\" with NAME one of " +
                             names + "; or run/seconds, run/cpu_seconds, run/iterations)");
}

void check_group(const std::string& group, const std::map<std::string, std::vector<std::string>>& columns, const std::string& kp) {
  const size_t slash = group.find('/');
  if (slash == std::string::npos) throw config_error(kp, "expected \"panel/column\", got \"" + group + "\"");
  const std::string panel = group.substr(0, slash), column = group.substr(slash + 1);
  const auto it = columns.find(panel);
  if (it == columns.end()) {
    std::string known;
    for (auto& [p, c] : columns) known += (known.empty() ? "" : ", ") + p;
    throw config_error(kp, "no synthesis panel '" + panel + "' (panels: " + known + ")");
  }
  if (std::find(it->second.begin(), it->second.end(), column) == it->second.end()) {
    std::string known;
    for (auto& c : it->second) known += (known.empty() ? "" : ", ") + c;
    throw config_error(kp, "panel '" + panel + "' has no column '" + column + "' (columns: " + known + ")");
  }
}

// A target: a number, "exemplar", or (when groups are allowed) a group.
void check_target(const json& t, bool groups, const std::map<std::string, std::vector<std::string>>& columns, const std::string& kp) {
  if (t.is_number()) return;
  if (t.is_string() && t == "exemplar") return;
  if (groups && t.is_string()) return check_group(t, columns, kp);
  throw config_error(kp, groups ? "expected a number, \"exemplar\" or \"panel/column\"" : "expected a number or \"exemplar\"");
}

double share(const json& j, double fallback, const std::string& kp) {
  if (j.is_null()) return fallback;
  if (!j.is_number()) throw config_error(kp, "expected a share in (0, 1]");
  const double s = j.get<double>();
  if (!(s > 0 && s <= 1)) throw config_error(kp, "expected a share in (0, 1]");
  return s;
}

std::string percent(double share) {
  char b[32];
  std::snprintf(b, sizeof b, "%g %%", 100 * share);
  return b;
}

std::string target_text(const json& t) {
  if (t == "exemplar") return "the exemplar's";
  return t.is_string() ? t.get<std::string>() : t.dump();
}

}  // namespace

ReproduceRule parse_reproduce_rule(const json& rule, const std::map<std::string, std::vector<std::string>>& columns) {
  const json r = apply_defaults({{"statement", ""}, {"kind", "checks"}, {"min_share", 0.8}, {"checks", json::array()}}, rule, "rule");
  ReproduceRule out;
  out.kind = r["kind"];
  if (out.kind != "checks" && out.kind != "pictures" && out.kind != "not_comparable")
    throw config_error("rule.kind", "expected \"checks\", \"pictures\" or \"not_comparable\", got \"" + out.kind + "\"");
  out.statement = r["statement"];
  if (out.statement.empty()) throw config_error("rule.statement", "say in words what the rule asks (the page prints it)");
  out.min_share = share(r["min_share"], 0.8, "rule.min_share");
  if (out.kind != "checks" && !r["checks"].empty()) throw config_error("rule.checks", "a '" + out.kind + "' rule has no checks");
  if (out.kind == "checks" && r["checks"].empty()) throw config_error("rule.checks", "a rule of kind 'checks' needs at least one check");
  for (size_t i = 0; i < r["checks"].size(); ++i) {
    const std::string kp = at("rule.checks", i);
    const json& raw = r["checks"][i];
    if (!raw.is_object()) throw config_error(kp, "expected a check object");
    if (!raw.contains("type") || !raw["type"].is_string() || !kTypes.count(raw["type"]))
      throw config_error(kp + ".type", "expected \"better\", \"within\", \"not_worse\" or \"threshold\"");
    const json c = apply_defaults(check_defaults(raw["type"]), raw, kp);
    RuleCheck k;
    k.type = c["type"];
    k.label = c["label"];
    k.metric = c["metric"];
    check_metric(k.metric, kp + ".metric");
    k.group = c["group"];
    check_group(k.group, columns, kp + ".group");
    if (k.type == "better") {
      if (c["than"].empty()) throw config_error(kp + ".than", "name at least one group to beat");
      for (size_t j = 0; j < c["than"].size(); ++j) {
        if (!c["than"][j].is_string()) throw config_error(at(kp + ".than", j), "expected \"panel/column\"");
        check_group(c["than"][j], columns, at(kp + ".than", j));
        if (c["than"][j] == k.group) throw config_error(at(kp + ".than", j), "a group cannot beat itself");
        k.than.push_back(c["than"][j]);
      }
      k.min_share = share(c["min_share"], out.min_share, kp + ".min_share");
      k.higher_is_better = c["higher_is_better"];
      if (!c["toward"].is_null()) check_target(c["toward"], false, columns, kp + ".toward");
      k.target = c["toward"];
    } else if (k.type == "within" || k.type == "not_worse") {
      if (c["target"].is_null()) throw config_error(kp + ".target", "give the target: a number, \"exemplar\" or \"panel/column\"");
      check_target(c["target"], true, columns, kp + ".target");
      k.target = c["target"];
      k.tolerance = c["tolerance"].get<double>();
      if (!(k.tolerance >= 0)) throw config_error(kp + ".tolerance", "expected a number >= 0 (a share of the target)");
      if (k.type == "not_worse") k.higher_is_better = c["higher_is_better"];
    } else {
      k.op = c["op"];
      if (!kOps.count(k.op)) throw config_error(kp + ".op", "expected \"<\", \"<=\", \">\" or \">=\"");
      if (c["value"].is_null()) throw config_error(kp + ".value", "give the value: a number or \"exemplar\"");
      check_target(c["value"], false, columns, kp + ".value");
      k.value = c["value"];
      k.min_share = share(c["min_share"], out.min_share, kp + ".min_share");
    }
    out.checks.push_back(k);
  }
  return out;
}

std::string describe_check(const RuleCheck& k) {
  std::string s = k.label.empty() ? "" : k.label + ": ";
  if (k.type == "better") {
    std::string than;
    for (auto& t : k.than) than += (than.empty() ? "" : ", ") + t;
    const std::string what = k.target.is_null() ? k.metric : k.metric + " closer to " + target_text(k.target);
    const std::string dir = k.target.is_null() ? (k.higher_is_better ? "higher " : "lower ") : "";
    return s + k.group + " " + dir + what + " than " + than + " (median, and in >= " + percent(k.min_share) + " of the seeds against each)";
  }
  if (k.type == "within")
    return s + k.group + " median " + k.metric + " within " + percent(k.tolerance) + " of " + target_text(k.target);
  if (k.type == "not_worse")
    return s + k.group + " median " + k.metric + (k.higher_is_better ? " at least " : " at most ") +
           (k.tolerance == 0 ? std::string("") : "(1 " + std::string(k.higher_is_better ? "- " : "+ ") + percent(k.tolerance) + ") x ") +
           "that of " + target_text(k.target);
  return s + k.group + " " + k.metric + " " + k.op + " " + target_text(k.value) + " in >= " + percent(k.min_share) + " of the seeds";
}

}  // namespace ppsynth
