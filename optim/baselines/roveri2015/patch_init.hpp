#pragma once
// Random-patch-copy initialization (Ma et al. 2011, used by thesis Fig. 3.4 and by the
// paper's comparison, Sec. 5.1: "Roveri et al. also use random-patch copy initialization"):
// the output domain is tiled with nx x ny equal cells of side ~patch_side, and each cell
// receives the points (with classes and attributes) of a window of the same size taken at a
// uniformly random place inside the exemplar. Half-open windows, so the expected number of
// points is the exemplar's density times the output area (S M for an S-times larger domain).
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth::roveri2015 {

// patch_side in exemplar units (clamped to the exemplar's smaller side); the result lives
// on `out_domain` with the exemplar's attribute columns and class labels.
PointSet random_patch_copy(const PointSet& exemplar, const Domain& out_domain, double patch_side, uint64_t seed);

}  // namespace ppsynth::roveri2015
