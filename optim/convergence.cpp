#include "optim/convergence.hpp"

namespace ppsynth {

bool ConvergenceRule::converged(const std::vector<double>& L, int iteration) const {
  const int n = static_cast<int>(L.size());
  if (iteration % check_every != 0 || n <= window) return false;
  const double init = L.front(), pre = L[n - window], now = L[n - 1];
  // A loss that rose over the whole stage gives a negative ratio: the published code then
  // stops too (the comparison is the same).
  const double denom = init - now;
  if (denom == 0) return true;
  return (pre - now) / denom < threshold;
}

}  // namespace ppsynth
