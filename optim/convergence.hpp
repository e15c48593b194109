#pragma once
// The stopping rule of a sigma stage (paper §5: "the decrease of loss during the most recent
// 100 iterations is smaller than 1%"), as the published code checks it: every `check_every`
// iterations, once more than `window` have run, stop when
//     (L[n - window] - L[n - 1]) / (L[0] - L[n - 1]) < threshold
// with L the per-iteration losses of the stage (n of them). It can first fire at iteration
// 110 with the defaults. A cap on the iterations stops the stage in any case.
#include <vector>

namespace ppsynth {

struct ConvergenceRule {
  int window = 100;
  int check_every = 10;
  double threshold = 0.01;
  // `iteration` is the 0-based index of the iteration that produced losses.back().
  bool converged(const std::vector<double>& losses, int iteration) const;
};

}  // namespace ppsynth
