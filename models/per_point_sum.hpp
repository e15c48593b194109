#pragma once
// The last step of the Gabor maps' backward (models/gabor_maps_tensor_ops.cpp): every grid
// position's k neighbors each hold a gradient, and a point's gradient is the sum of those
// that name it. Two ways to sum, the same numbers to float rounding:
//   scatter  one index_add into the points. On CUDA it adds with atomics, in an order that
//            varies from run to run (other last bits); LibTorch's deterministic replacement,
//            which a deterministic CUDA run gets, sorts and then sums each point's values one
//            after another, several times slower than the whole rest of the maps.
//   gather   the inverse neighbor list: the values sorted by point (a stable sort), each
//            point's run of values gathered into a row of a points x (longest run) table padded
//            with zeros, and the rows summed. No atomics, the same order on every run, and the
//            sums run in parallel over the points and along each row.
// `automatic` gathers on a CUDA device when LibTorch's deterministic algorithms are on (as a
// run with runtime.deterministic sets them), and scatters elsewhere: on the CPU index_add is
// sequential, deterministic and the faster of the two.
#include <torch/torch.h>

namespace ppsynth {

enum class PointSumMethod { automatic, scatter, gather };

// values: M x D; point: M int64 indices in [0, n). Returns n x D, row i the sum of the values
// whose index is i (zero for a point no value names).
torch::Tensor sum_per_point(const torch::Tensor& values, const torch::Tensor& point, int64_t n,
                            PointSumMethod method = PointSumMethod::automatic);

// What `automatic` resolves to for tensors on `device` (reads LibTorch's deterministic flag).
PointSumMethod point_sum_method(const torch::Device& device);

}  // namespace ppsynth
