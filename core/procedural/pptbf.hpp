#pragma once
// The Point Process Texture Basis Function (Guehl et al. 2020, supplement #4, Appendix A):
//   PPTBF(x) = sum over the cells k around x (closest first) of
//                (w1_k(x) + w2_k(x)) * F_k(x)          for mixture models 0..3,
//   or the max-operator value of the feature kernels   for mixture models 4, 5.
// Steps: [1] x += ampli[0] * brownnoise(ampli[1] * x * zoom, ampli[2]);
//        [2] m = zoom * R(rotation) (x / rescalex, y)           (model units)
//        [3] feature points around m (pptbf_tiling.hpp), sorted by cell distance
//        [5] windows w1 (closest cell only), w2 (pptbf_window.hpp)
//        [7] feature function and mixture (pptbf_feature.hpp).
// x, y are image coordinates, y up: the unit square is one image / one point exemplar.
#include <memory>
#include <unordered_map>

#include "core/procedural/pptbf_feature.hpp"
#include "core/procedural/pptbf_params.hpp"
#include "core/procedural/pptbf_tiling.hpp"
#include "core/procedural/pptbf_window.hpp"
#include "core/render/image_grid.hpp"

namespace ppsynth {

// Evaluates one parameter set at many positions, caching per-cell data (cell shapes, kernel
// parameters, relaxed points). Values equal those of a fresh evaluator. Not thread-safe:
// one evaluator per thread.
class PptbfEvaluator {
 public:
  explicit PptbfEvaluator(const PptbfParams& params);
  double operator()(double x, double y);
  const PptbfParams& params() const { return prm_; }
  // Steps [1] + [2]: image position -> model position.
  Vec2 to_model(Vec2 image_xy) const;
  // Inverse of step [2] alone (the Brownian deformation [1] is not inverted).
  Vec2 model_to_image(Vec2 model_xy) const;
  pptbf_impl::PointProcess& point_process() { return pp_; }

 private:
  struct KeyHash {
    size_t operator()(const pptbf_impl::CellKey& k) const { return static_cast<size_t>(k.hash()); }
  };
  const pptbf_impl::CellFeature& feature_of(const pptbf_impl::FeaturePoint& fp);
  const pptbf_impl::CellShape& shape_of(const pptbf_impl::FeaturePoint& fp);

  PptbfParams prm_;
  pptbf_impl::PointProcess pp_;
  std::unordered_map<pptbf_impl::CellKey, pptbf_impl::CellFeature, KeyHash> features_;
  std::unordered_map<pptbf_impl::CellKey, pptbf_impl::CellShape, KeyHash> shapes_;
  std::vector<pptbf_impl::FeaturePoint> pts_;  // scratch
  std::vector<int> order_;                // scratch
};

// One value (builds a fresh evaluator: use PptbfEvaluator for many values).
double pptbf(const PptbfParams& params, double x, double y);

// The PPTBF over the image window [x0,x1]x[y0,y1] (default the unit square) at width x
// height pixels (pixel centers; row 0 at the top = y1). threads <= 0: hardware concurrency.
GrayImage render_pptbf(const PptbfParams& params, int width, int height,
                       const Domain& window = Domain{}, int threads = 0);

}  // namespace ppsynth
