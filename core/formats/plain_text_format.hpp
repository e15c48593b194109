#pragma once
// This project's plain point text: whitespace-separated numbers, one point a line, with
// `#` comment lines that describe the columns.
//
//   # ppsynth points                     (any other comment is free text)
//   # domain 0 0 1 1 [periodic]          x0 y0 x1 y1; default: the unit square, not periodic
//   # class_labels 1000 2000             file label of class 0, 1, ... (optional)
//   # x y class radius                   the column names; must precede the first point
//                                        (a token starting with '(' begins a free remark)
//   0.25 0.5 0 0.01
//
// Columns: "x" and "y" first; a column named "class" holds the dense class id 0..K-1 (an
// integer; with class_labels it must be < the number of labels); every other name is an
// attribute. Without a column header, 2 columns are `x y` and 3 are `x y class`; other
// counts need the header. Every row must have the header's (or the first row's) column
// count; a point outside the domain is an error. Class labels must fit 32 bits; a "radius"
// column must be > 0. The writer prints %.17g, so doubles read
// back bit-exactly; it writes the class column when K > 1 or class labels are set.
#include <string>

#include "core/point_set.hpp"

namespace ppsynth {

PointSet parse_plain_text(const std::string& text, const std::string& source);
std::string print_plain_text(const PointSet& ps);

}  // namespace ppsynth
