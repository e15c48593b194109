#pragma once
// Wasserstein-1 (earth mover's) distance between two point sets via an exact optimal
// assignment: Hungarian algorithm in the Jonker-Volgenant shortest-augmenting-path form
// with potentials, O(n^2 m) for n <= m.
// Cost = Euclidean distance in the plane (no wrap; both sets in the same coordinates).
// Unequal sizes: every point of the smaller set is matched to a distinct point of the larger
// set (the unmatched surplus of the larger set is ignored). Returns the mean matched distance
// over the min(|a|, |b|) pairs, in domain units. Either set empty => InputError.
//
// Size limit. The assignment needs the |a| x |b| cost matrix (8 bytes a pair: 100,000 points
// would need 80 GB) and O(n^2 m) time, which grows past what a user waits for well before
// memory runs out (docs/lab/performance/README.md, "Numbers that were in code comments").
// wasserstein_distance refuses (InputError) beyond `max_pairs` = |a| |b| (default
// kWassersteinExactPairs = 4e6, e.g. 2,000 x 2,000: 32 MB).
// wasserstein_estimate is what the evaluation uses: the exact value up to the limit; beyond
// it, the exact assignment between uniform random subsamples of both sets (fixed seed, so
// reproducible), sizes chosen as large as the limit allows with the sets' size ratio kept
// (sample_a x sample_b <= max_pairs). The subsample value is the same kind of number but
// NOT the same number: matched distances grow as the samples thin out (roughly like
// 1/sqrt(sample size) for two samples of one distribution), so an estimate is comparable
// only with estimates of the same sample sizes, never with exact values. Callers report it
// under its own name with its sample sizes (evaluation.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

inline constexpr size_t kWassersteinExactPairs = 4000000;

double wasserstein_distance(const PointSet& a, const PointSet& b, size_t max_pairs = kWassersteinExactPairs);

struct WassersteinResult {
  double value = 0;
  bool exact = true;               // false: subsample estimate
  size_t sample_a = 0, sample_b = 0;  // points of a and b that entered the assignment
};
WassersteinResult wasserstein_estimate(const PointSet& a, const PointSet& b,
                                       size_t max_pairs = kWassersteinExactPairs, uint64_t seed = 1);

// The assignment itself: cost is rows x cols (rows <= cols), row-major; returns for each row
// its column, minimizing the total cost. Throws InputError if rows > cols.
std::vector<size_t> optimal_assignment(const std::vector<double>& cost, size_t rows, size_t cols);

}  // namespace ppsynth
