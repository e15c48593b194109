#pragma once
// Five-number summaries of samples (one value per seed): what gather reports and what the
// strip plots draw. Quantiles interpolate linearly between order statistics (NumPy's default,
// R's type 7): quantile({1, 2, 3, 4}, 0.25) = 1.75.
#include <cstddef>
#include <vector>

namespace ppsynth {

// The q-quantile (0 <= q <= 1) of the finite values of v; NaN when there are none.
double quantile(std::vector<double> v, double q);

struct Summary {
  size_t count = 0;       // finite values
  size_t not_finite = 0;  // NaN and infinities, left out
  double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;
};

Summary summarize(const std::vector<double>& values);

}  // namespace ppsynth
