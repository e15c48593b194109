#pragma once
// Matern cluster process: parents uniform (number ~ Poisson(parent_intensity * area), at
// least 1), each with Poisson(mean_children) children placed uniformly in a disk of `radius`
// around it, wrapped toroidally into the domain. The process is conditioned on n: children
// are generated until there are at least n, then n are kept (a seeded random subset), so the
// output always has exactly n points.
// parent_intensity <= 0 derives it as n / (mean_children * area).
// Registered as "matern_cluster" {parent_intensity, mean_children, radius}.
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {

template <class T>
class ParamTable;

struct MaternClusterOptions {
  double parent_intensity = 0;  // parents per unit area; 0 = n / (mean_children * area)
  double mean_children = 8;
  double radius = 0.05;  // cluster disk radius (domain units)
  static const ParamTable<MaternClusterOptions>& params();  // its keys, defaults and ranges (the .cpp)
};

PointSet matern_cluster_points(size_t n, uint64_t seed, Domain d = {},
                               const MaternClusterOptions& opt = {});

}  // namespace ppsynth
