#pragma once
// Point exemplars from a PPTBF, in the unit square (image coordinates, y up):
//  (a) pptbf_process_points: the PPTBF's own point process, i.e. the feature points p of
//      every cell whose model position maps into the unit square under the inverse of
//      step [2] (zoom, rotation, rescalex). The Brownian deformation [1] is not inverted,
//      so with ampli[0] > 0 the points are those of the undeformed pattern.
//  (b) pptbf_threshold_points: dart throwing (std::mt19937_64(seed)) of uniform candidates
//      accepted where pptbf(x, y) > threshold and no accepted point is closer than
//      min_dist: a structured Poisson-disk exemplar (unlimited supply by varying seeds).
#include <cstdint>

#include "core/point_set.hpp"
#include "core/procedural/pptbf_params.hpp"

namespace ppsynth {

PointSet pptbf_process_points(const PptbfParams& params);

struct ThresholdSampling {
  int n = 1000;                 // target number of points
  double threshold = 0.5;       // accept where pptbf > threshold
  double min_dist = 0.0;        // minimum distance between points (unit-square units)
  long long max_attempts = 0;   // candidates to try; <= 0 means 500 * n
  std::uint64_t seed = 1;       // dart-throwing seed (the PPTBF has its own params.seed)
};
// Returns up to n points (fewer when the attempts run out: check size()).
PointSet pptbf_threshold_points(const PptbfParams& params, const ThresholdSampling& s);

// The q-quantile (0..1) of the PPTBF over a res x res render of the unit square: a
// threshold for which about (1 - q) of the area is accepted.
double pptbf_quantile(const PptbfParams& params, double q, int res = 128);

}  // namespace ppsynth
