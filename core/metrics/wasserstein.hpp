#pragma once
// Wasserstein-1 (earth mover's) distance between two point sets via an exact optimal
// assignment: Hungarian algorithm in the Jonker-Volgenant shortest-augmenting-path form
// with potentials, O(n^2 m) for n <= m (~0.1 s for 300 x 300).
// Cost = Euclidean distance in the plane (no wrap; both sets in the same coordinates).
// Unequal sizes: every point of the smaller set is matched to a distinct point of the larger
// set (the unmatched surplus of the larger set is ignored). Returns the mean matched distance
// over the min(|a|, |b|) pairs, in domain units. Either set empty => InputError.
#include <cstddef>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

double wasserstein_distance(const PointSet& a, const PointSet& b);

// The assignment itself: cost is rows x cols (rows <= cols), row-major; returns for each row
// its column, minimising the total cost. Throws InputError if rows > cols.
std::vector<size_t> optimal_assignment(const std::vector<double>& cost, size_t rows, size_t cols);

}  // namespace ppsynth
