#pragma once
// This project's JSON point files:
//
//   {
//     "format": "ppsynth-points",            optional tag
//     "domain": [x0, y0, x1, y1],            optional, default [0,0,1,1]
//     "periodic": false,                     optional
//     "class_labels": [1000, 2000],          optional: file label of class 0, 1, ...
//     "attributes": ["radius"],              optional: attribute column names
//     "points": [[x, y, class, attr...], ...]
//   }
//
// Each point is [x, y, class, attributes in "attributes" order]; class is the dense id
// 0..K-1 (< the number of class_labels when given). Unknown keys are errors. Doubles are
// written with nlohmann::json's round-trip formatting, one point a line.
// Errors: syntax errors, nesting deeper than kMaxJsonDepth and numbers beyond double name the
// file line (core/config/json_text.hpp); errors in a well-formed document name the element
// ("points[12]", "class_labels[1]") and the line of that element (the writer puts one point
// a line) or of its key. Class labels must fit 32 bits; a "radius" attribute must be > 0.
#include <string>

#include "core/point_set.hpp"

namespace ppsynth {

PointSet parse_json_points(const std::string& text, const std::string& source);
std::string print_json_points(const PointSet& ps);

}  // namespace ppsynth
