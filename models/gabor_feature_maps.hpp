#pragma once
// GaborFeatureMaps: points -> 1 x C x rows x res feature maps (paper Eq. 5, method.md §2;
// rows = res but on a rectangle output's grid, models/feature_grid.hpp).
//
//   h_c(g) = (1/k) * sum over the k nearest points p_i of grid position g:
//              w_i * exp(-|p_i - g|^2 / (2 sigma^2)) * cos(2 pi nu_c . (p_i - g))^gamma_c
//
// Channels: gamma = 0 (spatial map, a Gaussian splat) and gamma = 1 for the 9 frequencies
// nu in {-f, 0, f}^2, f = 1.5 u (u = 1 exemplar, u = 2 output). Attributes (method.md §2):
// none -> 10 unweighted maps; one (disk radius) -> all 10 maps weighted by w = r / max r;
// A >= 2 -> the spatial map unweighted plus 9 frequency maps per attribute (1 + 9A).
// `spatial_only` keeps only gamma = 0 maps (the Fig. 11 ablation, Tu et al.'s features).
//
// Exact gradients w.r.t. the positions come from a custom autograd function with an
// analytic backward, so no k x res^2 x C intermediates are stored (the published code keeps
// several): memory is the output maps plus the res^2 x k neighbor indices.
// Cost: k-NN O(res^2 (log N + k)); forward and backward O(res^2 k C), independent of N
// beyond the search.
//
// Two implementations of the same sum and backward (GaborMapsPath): a CPU kernel (threads
// over grid positions, nanoflann's k-NN), and LibTorch operations that run where the tensors
// are, a CUDA device included (gather the k neighbors, exp and cos on res^2 x k values per
// channel, the backward summed per point, models/per_point_sum.hpp; the k-NN by brute force on that device,
// res^2 x N distances in chunks). tests/models/test_gabor_maps_paths.cpp holds them equal on
// the CPU. PPSYNTH_GABOR_MAPS=tensor_ops makes CPU tensors take the operations too, so the
// whole test suite can run the arithmetic a CUDA run takes on a machine without one. Sigma is given in exemplar units and divided by u (the output is the
// exemplar zoomed out by u). The k neighbors are searched in the plane (not on the torus),
// as in the published code, unless `periodic`: then the domain is the unit torus, each grid
// position sees the nearest image of every point and p - g is the minimum image. The
// optimizer already wraps positions toroidally; periodic OUTPUT maps make the maps agree
// with that, so a point near x = 1 is seen by grid positions near x = 0 and the border
// stops being a place where points lose half their influence (where they park otherwise).
// The "gabor" rasterizer sets the flag per raster: `periodic_output` for the output's,
// `periodic_exemplar` for the exemplar's (read as a tile); docs/lab/method_measurements.md "Border parking".
#include <torch/torch.h>

#include <vector>

#include "models/gabor_channels.hpp"

namespace ppsynth {

// Which implementation evaluates the maps: `automatic` takes the CPU kernel for CPU tensors
// (unless PPSYNTH_GABOR_MAPS=tensor_ops) and the tensor operations for any other device.
enum class GaborMapsPath { automatic, cpu_kernel, tensor_ops };
// Whether PPSYNTH_GABOR_MAPS=tensor_ops asks CPU tensors to take the tensor operations
// (unset or "auto": no); read once per process, InputError naming the variable for any other
// value. configure_runtime (optim/run/runtime.hpp) asks it before a command does anything.
bool gabor_maps_tensor_ops_forced();

struct GaborMapsOptions {
  int res = 128;           // grid positions per axis (the output grid is u * exemplar res)
  double upscale = 1.0;    // u
  int k = 30;              // neighbors per grid position
  // Each position's sum over its neighbors is divided by this; 0: by the neighbors summed,
  // min(k, N). A tile of the output (optim/gabor/stages/random_tiles.hpp) holding fewer points than the
  // exemplar's k takes the exemplar's divisor, so that a point weighs in it what it weighs
  // in the exemplar's maps, whatever the tile's count.
  int divisor = 0;
  double base_frequency = 1.5;
  bool spatial_only = false;
  bool periodic = false;   // unit torus: nearest images, minimum-image offsets
  GaborMapsPath path = GaborMapsPath::automatic;
  int rows = 0;            // grid positions along y at the columns' spacing; 0: res (the square)
};

// The implementation `requested` resolves to for tensors on `device` (an error for the CPU
// kernel on another device); the environment variable is read once, and a value other than
// auto or tensor_ops is an InputError naming it.
GaborMapsPath gabor_maps_path(GaborMapsPath requested, const torch::Device& device);
const char* gabor_maps_path_name(GaborMapsPath path);  // "cpu_kernel", "tensor_ops" (run.json)

class GaborFeatureMapsImpl : public torch::nn::Module {
 public:
  explicit GaborFeatureMapsImpl(GaborMapsOptions options);
  // points: N x 2 (float or double, may require grad); weights: N x A or undefined;
  // sigma in exemplar units; jitter: rows*res x 2 offsets of the grid positions or undefined.
  // Returns 1 x C x rows x res.
  torch::Tensor forward(const torch::Tensor& points, const torch::Tensor& weights, double sigma,
                        const torch::Tensor& jitter = {});
  int channels(int num_attributes) const;
  const GaborMapsOptions& options() const { return opt_; }
  const torch::Tensor& grid() const { return grid_; }

 private:
  GaborMapsOptions opt_;
  torch::Tensor grid_;  // rows*res x 2, row-major, x along columns
};
TORCH_MODULE(GaborFeatureMaps);

// The k nearest points (plane or toroidal distance) of every grid position, nearest first:
// res^2 x k int64 on the points' device. grid_knn: nanoflann on the CPU (CPU tensors);
// grid_knn_tensor_ops: brute force on the points' device. Part of forward(); public for the
// benchmark and the tests.
torch::Tensor grid_knn(const torch::Tensor& points, const torch::Tensor& grid, int k, bool periodic = false);
torch::Tensor grid_knn_tensor_ops(const torch::Tensor& points, const torch::Tensor& grid, int k, bool periodic = false);

// Reference evaluation of Eq. 5 with plain tensor ops (every point a neighbor when k >= N).
// For tests only: O(res^2 N C) memory.
torch::Tensor gabor_maps_reference(const torch::Tensor& points, const torch::Tensor& weights,
                                   const torch::Tensor& grid, double sigma_out, double frequency,
                                   int k, const std::vector<GaborChannel>& channels);

}  // namespace ppsynth
