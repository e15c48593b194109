#pragma once
// The verdict of a paper item by its rule (experiments/plan/reproduce_rule.hpp), from the
// numbers gathered over seeds: each check passes, fails, or has no data; the item is
// "reproduced" when every check passes, "not reproduced" when none does, "partly" between,
// "incomplete" when a check has no data (a panel not run), "not run" when none has any; a
// pictures rule is "pictures", a not_comparable one "not comparable". Mechanical: the same
// numbers give the same verdict, and each check says the numbers that decided it.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/plan/reproduce_rule.hpp"

namespace ppsynth {

// What a reproduction gathered for one item.
struct ItemNumbers {
  // "panel/column" -> metric ("all/pcf_mse", "run/seconds", ...) -> seed -> value
  std::map<std::string, std::map<std::string, std::map<uint64_t, double>>> per_seed;
  // Groups drawn once, without a seed of ours (the published code's output): -> metric -> value
  std::map<std::string, std::map<std::string, double>> fixed;
  // Per panel, the exemplar's own value of a metric ("all/relative_radius", "all/overlap_pairs")
  std::map<std::string, std::map<std::string, double>> exemplar;
  // "panel/column" -> seed -> the preset variant its run was made under (run.json
  // preset.variant); runs without a preset are not listed. A reused run may come from a machine
  // of the other kind: a check between groups made under different variants compares two
  // networks (64 float32 filters against 120 bf16 ones), and says so.
  std::map<std::string, std::map<uint64_t, std::string>> made_under;
};

struct CheckResult {
  std::string text;     // describe_check()
  std::string state;    // pass | fail | no data
  std::string numbers;  // the numbers that decided it, in words
  // Non-empty when the groups it compares were made under different preset variants (in
  // words: which group under which); the state stands, but it is not like for like.
  std::string mixed_variants;
};

struct ItemVerdict {
  std::string verdict;  // reproduced | partly | not reproduced | incomplete | not run | pictures | not comparable | no rule
  std::string statement;
  std::vector<CheckResult> checks;
};

ItemVerdict judge_item(const ReproduceRule& rule, const ItemNumbers& numbers);

nlohmann::json verdict_json(const ItemVerdict& v);
// Per group and metric: seeds, values, median, quartiles, min, max ("fixed": true for a group
// drawn once); per panel the exemplar's values under "exemplar"; per group and seed the preset
// variant its run was made under, under "made_under".
nlohmann::json numbers_json(const ItemNumbers& n);

}  // namespace ppsynth
