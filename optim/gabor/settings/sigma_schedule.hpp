#pragma once
// The scale schedule (paper §4.3, method.md §5): sigma_1 = d / c1 (coarse) down to
// sigma_2 = d / c2 (fine), `count` values evenly spaced, optimized in that order.
// d = mean nearest-neighbor distance of the exemplar. Paper: c1 = 0.8 +- 0.2, c2 = 2.8 +- 0.2.
// c1, c2 > 0 and count >= 1 as method.c1, c2 and num_sigmas are bounded (gabor_options.cpp).
#include <vector>

namespace ppsynth {
std::vector<double> sigma_schedule(double d, double c1, double c2, int count = 4);
}  // namespace ppsynth
