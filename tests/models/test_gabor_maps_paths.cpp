// The Gabor maps' two implementations (models/gabor_feature_maps.hpp): the tensor operations
// a CUDA run takes against the CPU kernel, on the CPU, values and gradients; the brute-force
// neighbor search against nanoflann's; and, where this process sees a CUDA device, the same
// on it. Tagged [device]: scripts/gpu_check.sh runs these on the GPU machine.
#include <catch2/catch.hpp>

#include <torch/cuda.h>

#include <algorithm>
#include <iostream>

#include "models/feature_grid.hpp"
#include "models/gabor_feature_maps.hpp"

using namespace ppsynth;

namespace {

torch::Tensor uniform(int64_t n, int64_t cols, uint64_t seed, torch::Dtype dtype) {
  auto g = at::detail::createCPUGenerator(seed);
  return at::rand({n, cols}, g, torch::kFloat64).to(dtype);
}

struct Evaluated {
  torch::Tensor maps, grad;
};

// Maps of `pts` with `o`, and the gradient of <maps, probe> w.r.t. the points, on `device`.
Evaluated evaluate(GaborMapsOptions o, const torch::Tensor& pts, const torch::Tensor& w, const torch::Tensor& jitter,
                   const torch::Tensor& probe, double sigma, const torch::Device& device) {
  GaborFeatureMaps maps(o);
  maps->to(device);
  // A leaf of its own: on the CPU `to` returns `pts` itself, and a gradient asked of it would
  // make the next device's copy a non-leaf with no .grad (seen on CUDA).
  auto p = pts.detach().to(device).requires_grad_(true);
  auto m = maps->forward(p, w.defined() ? w.to(device) : w, sigma, jitter.defined() ? jitter.to(device) : jitter);
  (m * probe.to(device)).sum().backward();
  return {m.detach().cpu(), p.grad().cpu()};
}

// Largest |a - b| over the largest |b|.
double relative_difference(const torch::Tensor& a, const torch::Tensor& b) {
  return (a - b).abs().max().item<double>() / std::max(1e-30, b.abs().max().item<double>());
}

// Every combination the maps take: attributes (none, one, two), spatial only, periodic,
// fewer neighbors than points, grid jitter; `other` evaluated on `device` against the CPU
// kernel on the CPU.
void check_against_kernel(GaborMapsPath other, const torch::Device& device, torch::Dtype dtype, double tolerance) {
  const int n = 23, res = 11;
  auto pts = uniform(n, 2, 1, dtype);
  auto w = uniform(n, 2, 2, dtype) + 0.1;
  auto jitter = (uniform(res * res, 2, 3, dtype) - 0.5) / (res + 1);
  // Every combination as bits of `variant`: attributes (0, 1, 2), spatial only, periodic, k.
  for (int variant = 0; variant < 3 * 8; ++variant) {
    const int A = variant % 3;
    const bool spatial_only = variant / 3 % 2, periodic = variant / 6 % 2;
    const int k = variant / 12 ? n : 6;
    GaborMapsOptions kernel{res, 2.0, k};
    kernel.spatial_only = spatial_only;
    kernel.periodic = periodic;
    GaborMapsOptions tested = kernel;
    kernel.path = GaborMapsPath::cpu_kernel;
    tested.path = other;
    auto wa = A == 0 ? torch::Tensor() : w.narrow(1, 0, A);
    const int C = GaborFeatureMaps(kernel)->channels(A);
    auto probe = uniform(C * res * res, 1, 4, dtype).view({1, C, res, res}) - 0.5;
    for (const auto& j : {torch::Tensor(), jitter}) {
      const auto a = evaluate(kernel, pts, wa, j, probe, 0.2, torch::kCPU);
      const auto b = evaluate(tested, pts, wa, j, probe, 0.2, device);
      INFO("A=" << A << " spatial_only=" << spatial_only << " periodic=" << periodic << " k=" << k
                << " jitter=" << j.defined() << " on " << device);
      CHECK(b.maps.sizes() == a.maps.sizes());
      CHECK(relative_difference(b.maps, a.maps) < tolerance);
      CHECK(a.grad.abs().max().item<double>() > 1e-3);  // a gradient worth comparing
      CHECK(relative_difference(b.grad, a.grad) < tolerance);
    }
  }
  // A rectangle grid (a rectangle output's: rows at the columns' spacing, past y = 1).
  GaborMapsOptions kernel{res, 2.0, 6};
  kernel.rows = 2 * res - 3;
  GaborMapsOptions tested = kernel;
  kernel.path = GaborMapsPath::cpu_kernel;
  tested.path = other;
  auto tall = pts * torch::tensor({{1.0, 1.8}}, dtype);
  auto probe = uniform(10 * kernel.rows * res, 1, 5, dtype).view({1, 10, kernel.rows, res}) - 0.5;
  const auto a = evaluate(kernel, tall, {}, {}, probe, 0.2, torch::kCPU);
  const auto b = evaluate(tested, tall, {}, {}, probe, 0.2, device);
  INFO("rectangle grid on " << device);
  CHECK(b.maps.sizes() == a.maps.sizes());
  CHECK(relative_difference(b.maps, a.maps) < tolerance);
  CHECK(relative_difference(b.grad, a.grad) < tolerance);
}

bool cuda_here() {
  if (torch::cuda::is_available()) return true;
  // Catch2 v2 has no skip: the test passes, saying why it checked nothing.
  WARN("skipped: this process sees no CUDA device (torch::cuda::is_available() is false)");
  std::cout << "skipped (no CUDA device): " << Catch::getResultCapture().getCurrentTestName() << "\n";
  return false;
}

}  // namespace

TEST_CASE("Gabor maps by tensor operations equal the CPU kernel, values and gradients", "[models][gabor][device]") {
  check_against_kernel(GaborMapsPath::tensor_ops, torch::kCPU, torch::kFloat64, 1e-11);
  check_against_kernel(GaborMapsPath::tensor_ops, torch::kCPU, torch::kFloat32, 1e-4);
}

TEST_CASE("Brute-force k-NN on the tensors' device finds nanoflann's neighbors", "[models][gabor][device]") {
  auto pts = uniform(40, 2, 7, torch::kFloat64);
  auto grid = torch::from_blob(FeatureGrid{13}.positions().data(), {13 * 13, 2}, torch::kFloat32).to(torch::kFloat64);
  for (bool periodic : {false, true})
    for (int k : {1, 7, 40}) {
      auto a = grid_knn(pts, grid, k, periodic), b = grid_knn_tensor_ops(pts, grid, k, periodic);
      INFO("periodic=" << periodic << " k=" << k);
      REQUIRE(b.sizes() == a.sizes());
      // Nearest first in both (no two distances tie for random points).
      CHECK(torch::equal(a, b));
    }
  // Chunked over the grid when the grid x points distances exceed a chunk: the same answer.
  auto many = uniform(3000, 2, 8, torch::kFloat64);
  auto fine = torch::from_blob(FeatureGrid{96}.positions().data(), {96 * 96, 2}, torch::kFloat32).to(torch::kFloat64);
  CHECK(torch::equal(grid_knn(many, fine, 5), grid_knn_tensor_ops(many, fine, 5)));
}

TEST_CASE("The automatic path takes the CPU kernel for CPU tensors unless PPSYNTH_GABOR_MAPS says tensor_ops",
          "[models][gabor][device]") {
  const char* env = std::getenv("PPSYNTH_GABOR_MAPS");
  const bool forced = env && std::string(env) == "tensor_ops";
  CHECK(gabor_maps_path(GaborMapsPath::automatic, torch::kCPU) == (forced ? GaborMapsPath::tensor_ops : GaborMapsPath::cpu_kernel));
  CHECK(gabor_maps_path(GaborMapsPath::automatic, torch::Device("cuda:0")) == GaborMapsPath::tensor_ops);
  CHECK(gabor_maps_path(GaborMapsPath::tensor_ops, torch::kCPU) == GaborMapsPath::tensor_ops);
  CHECK_THROWS_WITH(gabor_maps_path(GaborMapsPath::cpu_kernel, torch::Device("cuda:0")),
                    Catch::Contains("CPU kernel cannot run on cuda:0"));
  CHECK(std::string(gabor_maps_path_name(GaborMapsPath::cpu_kernel)) == "cpu_kernel");
  CHECK(std::string(gabor_maps_path_name(GaborMapsPath::tensor_ops)) == "tensor_ops");
}

TEST_CASE("On CUDA, the Gabor maps equal the CPU kernel's, values and gradients", "[models][gabor][device][cuda]") {
  if (!cuda_here()) return;
  check_against_kernel(GaborMapsPath::automatic, torch::Device("cuda:0"), torch::kFloat64, 1e-10);
  check_against_kernel(GaborMapsPath::automatic, torch::Device("cuda:0"), torch::kFloat32, 1e-4);
}
