#pragma once
// Uniform random points (binomial / Poisson process conditioned on n): white noise.
// Registered as "uniform".
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {
PointSet uniform_points(size_t n, uint64_t seed, Domain d = {});
}  // namespace ppsynth
