#pragma once
// Local intensity lambda(x) of a point pattern (thesis Sec. 4.2.2, Appendix A.2.2): the
// classical kernel density estimator with the chapter's normalized 2D Gaussian,
//
//   lambda_hat(x) = sum_i k(x, x_i),   k(x, y) = exp(-||x - y||^2 / s^2) / (pi s^2)
//
// in points per unit area. `s` (the smoothness of the intensity) is the user's choice: it
// disambiguates intensity from correlation (Sec. 4.2.4). Near a non-periodic border the
// kernel mass outside the domain is lost; `edge_correct` divides by the kernel mass inside
// the domain (the usual edge correction), so a uniform pattern gives ~N/A up to the border.
// Periodic domains (ps.domain().periodic or the argument) use minimum-image distances.
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth::pcf2017 {

struct IntensityOptions {
  double sigma = 0;          // kernel width s (domain units); 0 = sigma_rmax * r_max
  double sigma_rmax = 3.0;   // default width in units of r_max of the whole pattern
  bool periodic = false;     // or'ed with the domain's flag
  bool edge_correct = true;
};

// The width actually used for `ps` (resolves sigma == 0).
double intensity_sigma(const PointSet& ps, const IntensityOptions& opt);

// lambda_hat at each query position.
std::vector<double> local_intensity(const PointSet& ps, const std::vector<Vec2>& queries,
                                    const IntensityOptions& opt = {});

// lambda_hat on a width x height grid of cell centers over the domain (row-major, row 0 at
// the domain's y0).
std::vector<double> intensity_map(const PointSet& ps, int width, int height,
                                  const IntensityOptions& opt = {});

}  // namespace ppsynth::pcf2017
