#pragma once
// Nearest-neighbor statistics of a point set (all classes together; pass
// ps.subset_class(k) for one class). Distances are in domain units; `periodic` measures them
// on the torus formed by ps.domain() (minimum image), otherwise in the plane.
//
// relative_radius (Lagae & Dutre 2008): rho = (d_min / 2) / r_max, where d_min is the
// smallest toroidal distance between two points and r_max = sqrt(A / (2 sqrt(3) N)) is the
// largest disk radius N equal non-overlapping disks can have on the torus of area A
// (hexagonal packing; on the unit torus r_max = sqrt(1 / (2 sqrt(3) N))). Dimensionless:
// 1 for a perfect hexagonal lattice, ~0.75 for good blue noise, ~0 for white noise.
// Fewer than 2 points throw InputError.
// Cost: one k-d tree k-NN query per point, O(N log N) (torus: 9 images in the tree).
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// Smallest and mean nearest-neighbor distance in one pass (what min_nn_distance and
// mean_nn_distance return).
struct NnStats {
  double min = 0, mean = 0;
};
NnStats nn_stats(const PointSet& ps, bool periodic = false);

// Each point's distance to its nearest other point, in the set's order.
std::vector<double> nearest_neighbor_distances(const PointSet& ps, bool periodic = false);

double mean_nn_distance(const PointSet& ps, bool periodic = false);
double min_nn_distance(const PointSet& ps, bool periodic = false);
double relative_radius(const PointSet& ps);

// r_max = sqrt(area / (2 sqrt(3) n)): hexagonal-packing disk radius of n points (domain units).
double packing_radius(size_t n, double area = 1.0);

}  // namespace ppsynth
