#pragma once
// Functional representation of thesis Eq. 3.4: a point set {(x_i, a_i)} becomes the
// vector-valued function
//
//   f(x) = sum_i a_i g(x - x_i, sigma),     g(x, sigma) = exp(-|x|^2 / sigma^2),
//
// so positions AND attributes shape one smooth function (Section 3.3.3, "Attributes": the
// attributes scale the Gaussians instead of being extra coordinates).
//
// Channels a_i (ChannelEncoder): for a K-class pattern, one channel per class holding the
// one-hot class indicator (weight 1): points of different classes then never cancel each
// other (a_i . a_j = 0), and K = 1 gives a_i = 1, the plain point-density function. Each
// attribute column of the exemplar that varies adds one channel carrying the attribute
// standardized by the exemplar's mean and standard deviation, times `attribute_weight`
// (constant columns add no channel and are copied through). Classes are discrete attributes:
// they are optimized as continuous channel values and snapped back to the nearest one-hot
// vector (Section 3.3.4, "If the attributes are discrete, we snap to the closest discrete
// value after each optimization step").
#include <cstddef>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth::roveri2015 {

class ChannelEncoder {
 public:
  // Learns the channel layout (K classes, varying attributes, their mean/std) from `exemplar`.
  ChannelEncoder(const PointSet& exemplar, double attribute_weight);
  int classes() const { return classes_; }
  int channels() const { return classes_ + int(active_.size()); }
  size_t raw_attributes() const { return mean_.size(); }
  // Channel vector (channels() values) of a point with class `cls` and raw attributes `attrs`
  // (raw_attributes() values; may be null when there are none).
  void encode(int cls, const double* attrs, double* out) const;
  // Class = argmax of the class channels; varying attributes un-standardized; constant
  // attributes = the exemplar's value.
  int decode_class(const double* ch) const;
  void decode_attributes(const double* ch, double* attrs) const;
  // Sets the class channels to the one-hot vector of their argmax (the snap of Sec. 3.3.4).
  void snap(double* ch) const;

 private:
  int classes_ = 1;
  double weight_ = 0.5;
  std::vector<size_t> active_;   // raw attribute index of each attribute channel
  std::vector<double> mean_, std_;
};

// Samples of Eq. 3.4: positions x_i and their channel vectors a_i (row-major, D per point).
struct FunctionalSet {
  int D = 1;
  std::vector<Vec2> x;
  std::vector<double> a;
  size_t size() const { return x.size(); }
  const double* attr(size_t i) const { return a.data() + i * size_t(D); }
  double* attr(size_t i) { return a.data() + i * size_t(D); }
  void add(Vec2 p, const double* ch) {
    x.push_back(p);
    a.insert(a.end(), ch, ch + D);
  }
  void erase(size_t i) {
    x.erase(x.begin() + long(i));
    a.erase(a.begin() + long(i) * D, a.begin() + long(i + 1) * D);
  }
};

// Encodes every point of `ps` (positions as stored).
FunctionalSet encode_points(const PointSet& ps, const ChannelEncoder& enc);
// Decodes back into a PointSet on `domain` with the exemplar's attribute names and labels.
PointSet decode_points(const FunctionalSet& fs, const ChannelEncoder& enc, const PointSet& exemplar,
                       const Domain& domain);

// g(x, sigma) = exp(-|x|^2 / sigma^2).
double gaussian(Vec2 x, double sigma);
// f(y) of Eq. 3.4 (D values into `out`), direct sum over all samples.
void evaluate_function(const FunctionalSet& fs, double sigma, Vec2 y, double* out);

}  // namespace ppsynth::roveri2015
