#pragma once
// The Gabor paper's integer point files (Huang et al. 2022, published code; shipped in
// shared/data/exemplars/gabor-paper/).
//
//   [K id_1 ... id_K]          header, multi-class files only (e.g. "2 1000 2000")
//   CLASS X Y [ATTR ...]       one point a line, all integers
//
// CLASS = 1000*(class+1) by convention (the label); X, Y = coordinate * 10000 in the unit
// square; attributes use the same integer scale (value * 10000). Reading divides by 10000,
// so coordinates are exact multiples of 1e-4 and the domain is [0,1]^2.
// Classes: with a header, class k is the k-th header id (a CLASS not in the header is an
// error); without one, the distinct CLASS values sorted ascending. Ids must fit 32 bits (the
// PointSet stores int labels); an attribute named "radius" must be > 0. Labels are kept in
// PointSet::class_labels so the writer restores them.
// There are no comments in this format, so attribute names come from a rule
// (gabor_attribute_names) or from ReadOptions::attribute_names.
#include <string>
#include <vector>

#include "core/formats/format_options.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

// Integer units per unit-square coordinate (and per attribute unit).
inline constexpr double kGaborIntScale = 10000.0;

// Names of `count` attribute columns of a Gabor file called `source`:
//   1 column:  "radius" when the file name contains "disk" (poisson_n64c2_disk), else "attr0"
//   2 columns: "scale", "depth" (the paper's element patterns, lemon_4c_v2; Fig. 7)
//   otherwise: "attr0", "attr1", ...
std::vector<std::string> gabor_attribute_names(const std::string& source, size_t count);

// Parses the text of a Gabor file (`source` names it in errors and drives the naming rule).
PointSet parse_gabor_int(const std::string& text, const std::string& source, const ReadOptions& opts);

// Prints `ps` in the Gabor format. Positions are first mapped onto the unit square if the
// domain is another rectangle, then rounded to 1e-4 (lossy for arbitrary doubles).
// Labels: the PointSet's class labels when they are K distinct positive integers, else
// 1000*(k+1). The header is written when K > 1, and for one class whose label equals the row's
// field count - 1 (a row "2 X Y" would otherwise read back as the header "2 classes: X, Y").
std::string print_gabor_int(const PointSet& ps);

// True when every line of `text` has the Gabor shape: integer fields only, an optional
// "K id..." header, rows of >= 3 fields whose CLASS is a positive multiple of 1000 and X, Y in
// 0..10000. (Detection, point_io.hpp, scores the first lines instead, so that one damaged
// line does not send the file to another reader.)
bool looks_like_gabor_int(const std::string& text);

}  // namespace ppsynth
