#pragma once
// The rule of a paper item (a figure config's "rule" block), written down before the runs: how
// the gathered numbers decide "reproduced", "partly" or "not reproduced"
// (experiments/report/reproduce_verdict.hpp applies it). Schema (unknown keys are errors naming
// the key path, e.g. "rule.checks[1].thn"):
//
//   "rule": {
//     "statement": "what 'reproduced' means here, in one or two sentences",
//     "kind": "checks" | "pictures" | "not_comparable",   pictures: judged by eye, reported so
//     "min_share": 0.8,          default share of seeds a per-seed comparison must win
//     "checks": [                every check passes: reproduced; some: partly; none: not
//       {"type": "better", "metric": "all/pcf_mse", "group": "a/ours", "than": ["a/pcf2017"],
//        "min_share": 0.8, "higher_is_better": false, "toward": null | "exemplar" | number},
//          group's median beats each of `than`'s, and it wins in >= min_share of the seeds both
//          ran (paired by seed; a group without seeds, the published output, against every
//          seed). "toward": compare the distance |value - target| instead of the value.
//       {"type": "within", "metric", "group", "target": "exemplar" | number | "panel/column",
//        "tolerance": 0.1}       |median - target| <= tolerance x |target|
//       {"type": "not_worse", "metric", "group", "target", "tolerance": 0.25, "higher_is_better"}
//                                the median at most (1 + tolerance) x the target (lower better)
//       {"type": "threshold", "metric", "group", "op": "<" | "<=" | ">" | ">=",
//        "value": number | "exemplar", "min_share"}   the seeds meeting it, a share >= min_share
//     ] }
//
// Groups are "panel/column": a synthesized column of the panel, "init" (the initialization
// its "ours" started from, per seed) or "reference" (the panel's published output, one draw).
// Metrics are "<scope>/<name>" as gather names them (scope "all", "class N", "classes N-M";
// names pcf_mse, wasserstein, chamfer, relative_radius, min_distance_normalized,
// close_pair_share, l_sup, overlap_pairs) or "run/seconds", "run/iterations". A target or
// value "exemplar" is the exemplar's own value of the metric (relative_radius, overlap_pairs).
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

struct RuleCheck {
  std::string type, label, metric, group;
  std::vector<std::string> than;  // better
  nlohmann::json target;          // within / not_worse: number, "exemplar" or a group; better: "toward"
  double tolerance = 0;
  double min_share = 0.8;
  bool higher_is_better = false;
  std::string op;                 // threshold
  nlohmann::json value;           // threshold: number or "exemplar"
};

struct ReproduceRule {
  std::string kind;  // "" = the config states no rule; checks | pictures | not_comparable
  std::string statement;
  double min_share = 0.8;
  std::vector<RuleCheck> checks;
};

// Reads and checks a "rule" block; `columns` holds, per synthesis panel, the columns a group
// may name (its synthesized columns, "init" with "ours", "reference" with a published output).
// InputError naming the key path ("rule.checks[0].group").
ReproduceRule parse_reproduce_rule(const nlohmann::json& rule, const std::map<std::string, std::vector<std::string>>& columns);

// The check in words, e.g. "a/ours lower all/pcf_mse than a/pcf2017, a/roveri2015 (median, and in
// >= 80 % of the seeds each)": what the page prints beside its numbers.
std::string describe_check(const RuleCheck& check);

}  // namespace ppsynth
