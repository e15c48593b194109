#pragma once
// Point-Synthesis exemplars (Tu, Lischinski, Huang, "Point Pattern Synthesis via Irregular
// Convolution", SGP 2019; shipped in shared/data/exemplars/point-synthesis/, see INDEX.md).
//
//   x y c2 c3 [c4]        one point a line, space separated, no header, no comments
//
// x, y are pixel-like units (about 0..1024); the reader rescales them onto the unit square:
// per-axis min-max (as published; default) or uniformly (ReadOptions::scaling, see
// format_options.hpp). Degenerate extents (all x or all y equal) are an error.
// c2 is the class: an integer category id; a constant column (including all 0) is one
// class, otherwise the distinct values, ascending, become classes 0..K-1 and are kept as
// class labels (they must fit 32 bits). Every further column is an attribute named "c3", "c4", ... (kept as read).
// Coincident points occur in the shipped files; read_points reports them, nothing rejects.
#include <string>

#include "core/formats/format_options.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

PointSet parse_point_synthesis(const std::string& text, const std::string& source, const ReadOptions& opts);

// Prints `x y c2 c3...`: positions in domain units (the reader's rescaling makes the unit
// irrelevant; a file of points spanning the unit square reads back exactly), c2 = the class
// label, then the attributes. A point set without attributes gets a constant c3 = 1 column
// (the published 4-column layout), which reads back as attribute "c3".
std::string print_point_synthesis(const PointSet& ps);

}  // namespace ppsynth
