#pragma once
// Symmetric Chamfer distance between two point sets (domain units, plane distances):
//   C(a, b) = mean_{p in a} min_{q in b} |p - q|  +  mean_{q in b} min_{p in a} |p - q|
// i.e. the SUM of the two directed mean nearest distances (not their average), as in the
// evaluation of the reference reports. Either set empty => InputError.
#include "core/point_set.hpp"

namespace ppsynth {

double chamfer_distance(const PointSet& a, const PointSet& b);
// One direction: mean over a of the distance to the nearest point of b.
double directed_chamfer(const PointSet& a, const PointSet& b);

}  // namespace ppsynth
