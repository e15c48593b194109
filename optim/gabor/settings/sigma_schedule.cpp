#include "optim/gabor/settings/sigma_schedule.hpp"

#include "core/error.hpp"

namespace ppsynth {

std::vector<double> sigma_schedule(double d, double c1, double c2, int count) {
  if (!(d > 0)) throw InputError("sigma schedule: the exemplar's mean nearest-neighbor distance is not positive");
  const double s1 = d / c1, s2 = d / c2;
  std::vector<double> s;
  for (int i = 0; i < count; ++i) s.push_back(count == 1 ? s1 : s1 + (s2 - s1) * i / (count - 1));
  return s;
}

}  // namespace ppsynth
