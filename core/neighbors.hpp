#pragma once
// NeighborIndex: k-nearest and fixed-radius neighbor queries on a set of 2-D points, backed
// by a nanoflann k-d tree (KDTreeSingleIndexAdaptor with L2_Simple_Adaptor; the library
// works in squared distances, this class returns plain Euclidean distances).
//
// Toroidal mode (periodic = true, or domain.periodic): the tree holds 9 copies of the points
// (the point set shifted by -W,0,+W in x and -H,0,+H in y). For a query wrapped into the
// domain, the toroidal distance to a point is the minimum over its 9 images, so a query
// returns the nearest image of each point and duplicates (other images of the same point) are
// dropped. Chosen over "replicate a border band" because it is exact for any k and any radius
// up to the domain size, at the cost of 9x memory (irrelevant for a few thousand points).
// Toroidal radii larger than min(W,H)/2 are still answered correctly (nearest image).
#include <cstddef>
#include <memory>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

class NeighborIndex {
 public:
  // Builds the index over `pts` (copied). `domain` is only used in toroidal mode.
  NeighborIndex(const std::vector<Vec2>& pts, Domain domain = {}, bool periodic = false);
  ~NeighborIndex();
  NeighborIndex(NeighborIndex&&) noexcept;
  NeighborIndex& operator=(NeighborIndex&&) noexcept;

  size_t size() const;
  bool periodic() const;

  // The min(k, size()) nearest points to q, sorted by increasing distance (tie order
  // unspecified); `dist` (optional) receives their distances.
  std::vector<size_t> knn(Vec2 q, size_t k, std::vector<double>* dist = nullptr) const;
  // Allocation-free k-NN into caller buffers (k entries each): indices and SQUARED
  // distances, sorted; returns how many were found. Plane (non-periodic) indices only; for
  // hot loops such as the Gabor maps (one query per grid position every iteration).
  size_t knn_into(Vec2 q, size_t k, size_t* idx, double* dist2) const;
  // All points within distance r of q (inclusive), sorted by increasing distance.
  std::vector<size_t> radius(Vec2 q, double r, std::vector<double>* dist = nullptr) const;
  // Nearest point to point i other than i itself (size() must be >= 2, else InputError).
  size_t nearest_other(size_t i, double* dist = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Euclidean distance between a and b; toroidal (minimum image) in `d` when `periodic`.
double point_distance(Vec2 a, Vec2 b, const Domain& d = {}, bool periodic = false);

}  // namespace ppsynth
