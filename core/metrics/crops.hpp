#pragma once
// The exemplar-sized-crops protocol: for outputs the paper's quadrants do not fit (a 4 x 1
// rectangle in exemplar units, 10,000 points). N windows of the exemplar's size are placed at
// random in the output; each is cut out, mapped onto the unit square and compared with the
// exemplar exactly as a quadrant patch is (patches.hpp).
//
// Crop size: the exemplar's domain (W_ex x H_ex) scaled by the zoom
//   z = sqrt((N_ex / A_ex) / (N_out / A_out))      (output units per exemplar unit)
// (all classes counted), so a crop holds about as many points as the exemplar: z = 1 for
// outputs in exemplar units, 1/2 for the paper's u = 2 unit square of a unit exemplar. The zoom
// is read from the two sets' densities, so any pair of files can be evaluated, and a run's own
// metrics are eval's on its files; a caller that knows the scale an output was made at
// (OutputShape::zoom(), gather's re-evaluations) may pass it instead.
// Placement: lower-left corners uniform in [x0, x1 - w] x [y0, y1 - h] of the output domain,
// from a 64-bit Mersenne Twister seeded with `seed` (the top 53 bits of each draw: the same
// windows on every platform for a seed). Crops may overlap; a crop that does not fit (the
// output is smaller than the exemplar at that density) is an InputError naming both sizes,
// unless the zoom came from the densities and the crop passes the output by less than that
// zoom's spread from the counts (density_zoom_spread): then the crop is shrunk to fit.
#include <cstdint>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// z above (InputError when either set is empty or a domain has no area).
double density_zoom(const PointSet& exemplar, const PointSet& output);
// The relative spread of that z from the point counts alone: 0.5 sqrt(1/N_ex + 1/N_out).
double density_zoom_spread(const PointSet& exemplar, const PointSet& output);

struct CropPlan {
  double zoom = 1;                 // output units per exemplar unit
  double width = 0, height = 0;    // crop size in output units
  bool zoom_fitted = false;        // the densities' zoom made a crop past the output by less than its spread: shrunk to fit
  std::vector<Domain> windows;     // `count` windows inside the output domain
};

// `count` crops (>= 1) of the exemplar's size at `zoom` (0: the densities'), seeded.
CropPlan plan_crops(const PointSet& exemplar, const PointSet& output, int count, uint64_t seed, double zoom = 0);

}  // namespace ppsynth
