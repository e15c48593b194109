#pragma once
// The output's classes matched to the exemplar's by label, so that every evaluation row
// (per-class metrics, cross rows, second order, verdict) compares a class with the exemplar's
// class of the same label, not with whatever class has the same index in the other file.
//
//   - the output's class of label L takes the id of the exemplar's class of label L;
//   - an output class whose label the exemplar lacks (with points) gets an id after the
//     exemplar's (K, K + 1, ... in ascending label order): "extra";
//   - an exemplar class with points that the output has no point of: "missing".
// One class each: matched whatever their labels (a single-class pattern's label says nothing
// about its points: a Gabor file's 1000 against a plain file's 0 is the same pattern). A file
// that names no class labels (a plain file's bare class column: 0, 1, ...) is matched by index,
// and the match says so.
// evaluate() matches once and hands the matched output to every row; verdict() matches too,
// so it can be called on its own (matching a matched output changes nothing).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

struct ClassMatch {
  PointSet output;            // class ids as described above, class_labels set for every id
  int exemplar_classes = 0;   // K: ids 0..K-1 are the exemplar's
  std::vector<int> missing;   // exemplar ids the output has no point of (the exemplar has)
  std::vector<int> extra;     // output ids >= K (labels the exemplar lacks)
  std::string by = "label";   // or "index (...)", "the only class of each" (above)
};

ClassMatch match_classes(const PointSet& exemplar, const PointSet& output);

// { "by": ClassMatch::by, "missing": [labels], "extra": [labels] }
nlohmann::json class_match_json(const ClassMatch& m);

// "" when every class matches; else one line naming the missing and extra labels.
std::string class_match_warning(const nlohmann::json& match);

}  // namespace ppsynth
