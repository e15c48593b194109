#include "experiments/report/reproduce_verdict.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "core/metrics/summary_stats.hpp"

namespace ppsynth {

namespace {

using json = nlohmann::json;

// 4 significant digits: the numbers span 1e-4 (PCF MSE) to 1e3 (seconds).
std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}

// A group's values of one metric: per seed, or one value drawn once (`fixed`).
struct Series {
  std::map<uint64_t, double> by_seed;
  std::optional<double> fixed;
  bool empty() const { return by_seed.empty() && !fixed; }
  double median() const {
    if (fixed) return *fixed;
    std::vector<double> v;
    for (auto& [s, x] : by_seed) v.push_back(x);
    return summarize(v).median;
  }
};

std::string panel_of(const std::string& group) { return group.substr(0, group.find('/')); }

Series series(const ItemNumbers& n, const std::string& group, const std::string& metric) {
  Series s;
  if (auto g = n.per_seed.find(group); g != n.per_seed.end())
    if (auto m = g->second.find(metric); m != g->second.end())
      for (auto& [seed, v] : m->second)
        if (std::isfinite(v)) s.by_seed[seed] = v;
  if (auto g = n.fixed.find(group); s.by_seed.empty() && g != n.fixed.end())
    if (auto m = g->second.find(metric); m != g->second.end() && std::isfinite(m->second)) s.fixed = m->second;
  return s;
}

std::optional<double> exemplar_value(const ItemNumbers& n, const std::string& panel, const std::string& metric) {
  if (auto p = n.exemplar.find(panel); p != n.exemplar.end())
    if (auto m = p->second.find(metric); m != p->second.end() && std::isfinite(m->second)) return m->second;
  return std::nullopt;
}

// A target: a number, the exemplar's value (of `group`'s panel), or another group's median.
std::optional<double> target_value(const ItemNumbers& n, const json& t, const std::string& group, const std::string& metric,
                                   std::string& text) {
  if (t.is_number()) {
    text = num(t.get<double>());
    return t.get<double>();
  }
  if (t == "exemplar") {
    auto v = exemplar_value(n, panel_of(group), metric);
    text = "the exemplar's " + (v ? num(*v) : std::string("(unknown)"));
    return v;
  }
  const Series s = series(n, t.get<std::string>(), metric);
  if (s.empty()) {
    text = t.get<std::string>() + " (no data)";
    return std::nullopt;
  }
  text = t.get<std::string>() + " " + (s.fixed ? num(s.median()) : "median " + num(s.median()) + " (" + std::to_string(s.by_seed.size()) + " seeds)");
  return s.median();
}

// The preset variants a group's runs were made under, in words: "without bf16 units (5)",
// "every processor (3), without bf16 units (2)"; "" when none recorded one.
std::string variants_of(const ItemNumbers& n, const std::string& group) {
  auto g = n.made_under.find(group);
  if (g == n.made_under.end()) return "";
  std::map<std::string, int> count;
  for (auto& [seed, variant] : g->second) ++count[variant];
  std::string out;
  for (auto& [variant, k] : count) out += (out.empty() ? "" : ", ") + variant + " (" + std::to_string(k) + ")";
  return out;
}

// Says, once per check, which compared groups ran under which variant when they differ.
void note_mixed(CheckResult& r, const ItemNumbers& n, const std::string& group, const std::string& other) {
  const std::string a = variants_of(n, group), b = variants_of(n, other);
  if (a.empty() || b.empty() || a == b) return;
  const std::string pair = group + ": " + a + "; " + other + ": " + b;
  if (r.mixed_variants.find(pair) == std::string::npos) r.mixed_variants += (r.mixed_variants.empty() ? "" : " | ") + pair;
}

// |value - target| for each value (a "better ... toward" check compares distances).
Series toward(Series s, double target) {
  for (auto& [seed, v] : s.by_seed) v = std::fabs(v - target);
  if (s.fixed) s.fixed = std::fabs(*s.fixed - target);
  return s;
}

size_t needed(double share, size_t n) { return static_cast<size_t>(std::ceil(share * static_cast<double>(n) - 1e-9)); }

CheckResult judge_better(const RuleCheck& k, const ItemNumbers& n) {
  CheckResult r{describe_check(k), "pass", ""};
  auto fail_no_data = [&](const std::string& what) {
    r.state = "no data";
    r.numbers = "no numbers for " + what;
    return r;
  };
  auto prepare = [&](const std::string& group, Series& s, std::string& why) {
    s = series(n, group, k.metric);
    if (s.empty()) return false;
    if (!k.target.is_null()) {
      std::string text;
      auto t = target_value(n, k.target, group, k.metric, text);
      if (!t) {
        why = "the target of " + group;
        return false;
      }
      s = toward(s, *t);
    }
    return true;
  };
  Series g;
  std::string why;
  if (!prepare(k.group, g, why)) return fail_no_data(why.empty() ? k.group : why);
  const bool up = k.higher_is_better;
  auto beats = [&](double a, double b) { return up ? a > b : a < b; };
  const std::string what = k.target.is_null() ? "" : " (distance to " + (k.target.is_string() ? k.target.get<std::string>() : k.target.dump()) + ")";
  r.numbers = k.group + " median " + num(g.median()) + what;
  for (const std::string& t : k.than) {
    Series o;
    if (!prepare(t, o, why)) return fail_no_data(why.empty() ? t : why);
    size_t wins = 0, pairs = 0;
    if (g.fixed && o.fixed) {
      pairs = 1, wins = beats(*g.fixed, *o.fixed);
    } else if (g.fixed) {  // a value drawn once against every seed of the other
      for (auto& [seed, v] : o.by_seed) ++pairs, wins += beats(*g.fixed, v);
    } else if (o.fixed) {
      for (auto& [seed, v] : g.by_seed) ++pairs, wins += beats(v, *o.fixed);
    } else {
      for (auto& [seed, v] : g.by_seed)
        if (auto it = o.by_seed.find(seed); it != o.by_seed.end()) {
          ++pairs;
          wins += beats(v, it->second);
        }
    }
    if (pairs == 0) return fail_no_data("a seed both " + k.group + " and " + t + " ran");
    note_mixed(r, n, k.group, t);
    const bool median_ok = beats(g.median(), o.median());
    const bool share_ok = wins >= needed(k.min_share, pairs);
    r.numbers += "; " + t + " " + num(o.median()) + (o.fixed ? " (drawn once)" : "") + ": wins " + std::to_string(wins) + "/" +
                 std::to_string(pairs) + (median_ok && share_ok ? "" : median_ok ? " (too few)" : " (median not better)");
    if (!median_ok || !share_ok) r.state = "fail";
  }
  return r;
}

// The check's group series and the value `spec` names (target_value: a number, the exemplar's
// value or another group's median), as judge_target and judge_threshold compare them; r reads
// "no data" when either is missing.
struct Compared {
  Series g;
  double t = 0;
  std::string text;  // how the value reads in the numbers
};
std::optional<Compared> compared(const RuleCheck& k, const ItemNumbers& n, const json& spec, CheckResult& r) {
  Compared c{series(n, k.group, k.metric), 0, ""};
  const std::optional<double> t = target_value(n, spec, k.group, k.metric, c.text);
  if (c.g.empty() || !t) {
    r.state = "no data";
    r.numbers = "no numbers for " + (c.g.empty() ? k.group : c.text);
    return std::nullopt;
  }
  c.t = *t;
  if (spec.is_string() && spec != "exemplar") note_mixed(r, n, k.group, spec.get<std::string>());
  return c;
}

CheckResult judge_target(const RuleCheck& k, const ItemNumbers& n) {
  CheckResult r{describe_check(k), "fail", ""};
  const auto c = compared(k, n, k.target, r);
  if (!c) return r;
  const double m = c->g.median(), t = c->t;
  const std::string seeds = c->g.fixed ? "" : " (" + std::to_string(c->g.by_seed.size()) + " seeds)";
  char b[64];
  if (k.type == "within") {
    const double off = std::fabs(m - t), allowed = k.tolerance * std::fabs(t);
    std::snprintf(b, sizeof b, "%.1f %%", t != 0 ? 100 * off / std::fabs(t) : (off == 0 ? 0.0 : INFINITY));
    r.state = off <= allowed ? "pass" : "fail";
    r.numbers = k.group + " median " + num(m) + seeds + " against " + c->text + ": off by " + b;
  } else {
    const double bound = k.higher_is_better ? (1 - k.tolerance) * t : (1 + k.tolerance) * t;
    r.state = (k.higher_is_better ? m >= bound : m <= bound) ? "pass" : "fail";
    r.numbers = k.group + " median " + num(m) + seeds + " against " + c->text + (k.higher_is_better ? ", bound >= " : ", bound <= ") + num(bound);
  }
  return r;
}

CheckResult judge_threshold(const RuleCheck& k, const ItemNumbers& n) {
  CheckResult r{describe_check(k), "fail", ""};
  const auto c = compared(k, n, k.value, r);
  if (!c) return r;
  const Series& g = c->g;
  const double t = c->t;
  auto meets = [&](double v) {
    return k.op == "<" ? v < t : k.op == "<=" ? v <= t : k.op == ">" ? v > t : v >= t;
  };
  size_t met = 0, total = 0;
  if (g.fixed) total = 1, met = meets(*g.fixed);
  for (auto& [seed, v] : g.by_seed) ++total, met += meets(v);
  r.state = met >= needed(k.min_share, total) ? "pass" : "fail";
  r.numbers = k.group + " median " + num(g.median()) + "; " + std::to_string(met) + "/" + std::to_string(total) + " seeds " + k.op + " " + c->text;
  return r;
}

}  // namespace

ItemVerdict judge_item(const ReproduceRule& rule, const ItemNumbers& numbers) {
  ItemVerdict v;
  v.statement = rule.statement;
  if (rule.kind.empty()) return v.verdict = "no rule", v;
  if (rule.kind == "pictures") return v.verdict = "pictures", v;
  if (rule.kind == "not_comparable") return v.verdict = "not comparable", v;
  size_t pass = 0, fail = 0, missing = 0;
  for (const RuleCheck& k : rule.checks) {
    v.checks.push_back(k.type == "better" ? judge_better(k, numbers) : k.type == "threshold" ? judge_threshold(k, numbers) : judge_target(k, numbers));
    const std::string& s = v.checks.back().state;
    (s == "pass" ? pass : s == "fail" ? fail : missing)++;
  }
  v.verdict = missing == v.checks.size() ? "not run"
              : missing > 0              ? "incomplete"
              : fail == 0                ? "reproduced"
              : pass == 0                ? "not reproduced"
                                         : "partly";
  return v;
}

json verdict_json(const ItemVerdict& v) {
  json j = {{"verdict", v.verdict}, {"statement", v.statement}, {"checks", json::array()}};
  for (auto& c : v.checks) {
    j["checks"].push_back({{"check", c.text}, {"state", c.state}, {"numbers", c.numbers}});
    if (!c.mixed_variants.empty()) j["checks"].back()["mixed_variants"] = c.mixed_variants;
  }
  return j;
}

json numbers_json(const ItemNumbers& n) {
  json j = {{"groups", json::object()}, {"exemplar", json::object()}};
  for (auto& [group, metrics] : n.per_seed)
    for (auto& [metric, by_seed] : metrics) {
      std::vector<double> values;
      std::vector<uint64_t> seeds;
      for (auto& [s, x] : by_seed) seeds.push_back(s), values.push_back(x);
      const Summary s = summarize(values);
      j["groups"][group][metric] = {{"seeds", seeds}, {"values", values}, {"n", s.count}, {"median", s.median},
                                    {"q1", s.q1}, {"q3", s.q3}, {"min", s.min}, {"max", s.max}};
    }
  for (auto& [group, metrics] : n.fixed)
    for (auto& [metric, x] : metrics)
      j["groups"][group][metric] = {{"fixed", true}, {"n", 1}, {"median", x}, {"min", x}, {"max", x}, {"q1", x}, {"q3", x}};
  for (auto& [panel, metrics] : n.exemplar)
    for (auto& [metric, x] : metrics) j["exemplar"][panel][metric] = x;
  for (auto& [group, by_seed] : n.made_under)
    for (auto& [seed, variant] : by_seed) j["made_under"][group][std::to_string(seed)] = variant;
  return j;
}

}  // namespace ppsynth
