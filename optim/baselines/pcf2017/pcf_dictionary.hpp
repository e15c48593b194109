#pragma once
// The PCF dictionary of thesis Sec. 4.2.3: local PCFs g_k (vectors of `bins` samples, from
// local_pcf.hpp at measurement points c_k) are summarized by
//   1. PCA: mean + principal components, keeping the fewest components that explain
//      `variance_kept` (99 %) of the variance;
//   2. basis PCFs g_l: the two samples at the ends of the first component, then, while
//      max_k ||e_k|| > error_threshold, the sample farthest from the current reconstruction;
//   3. weights (Eq. 4.2):  min_w || g_k - sum_l w_kl g_l ||^2  s.t. sum_l w_kl = 1, w_kl >= 0
//      (a small QP, solved by projected gradient on the simplex).
//
// The symmetric eigen-decomposition is a compact cyclic Jacobi solver (jacobi_eigen): this
// library is torch-free on purpose and none of the allowed Debian dependencies (nlohmann,
// spdlog, nanoflann, the command-line parser, cairo) provides one; LibTorch's torch.linalg.eigh is not linked here.
#include <cstddef>
#include <vector>

namespace ppsynth::pcf2017 {

using std::size_t;
using Matrix = std::vector<std::vector<double>>;  // row-major, rows = samples

// Eigen-decomposition of a symmetric matrix: eigenvalues descending, vectors[i] is the unit
// eigenvector of values[i]. Throws InputError if `a` is not square.
struct Eigen {
  std::vector<double> values;
  Matrix vectors;
};
Eigen jacobi_eigen(Matrix a, int max_sweeps = 100, double tol = 1e-12);

struct Pca {
  std::vector<double> mean;
  Matrix components;               // unit vectors, most variance first
  std::vector<double> variances;   // eigenvalues of the kept components
  double total_variance = 0;
  Matrix scores;                   // per sample: projections on the kept components
};
Pca pca(const Matrix& samples, double variance_kept = 0.99);

struct DictionaryOptions {
  double variance_kept = 0.99;
  double error_threshold = 0;   // eps_g on ||e_k|| (L2 over samples); 0 = 0.1 * sqrt(bins)
  int max_basis = 6;
  int qp_iterations = 500;
};

struct PcfDictionary {
  Pca pca;
  std::vector<size_t> basis_index;   // which samples became basis PCFs
  Matrix basis;                      // g_l
  Matrix weights;                    // w_kl (one row per sample, sums to 1, >= 0)
  std::vector<double> residual;      // ||e_k||
};
PcfDictionary build_dictionary(const Matrix& samples, const DictionaryOptions& opt = {});

// The simplex-constrained least squares of Eq. 4.2 for one vector.
std::vector<double> simplex_weights(const std::vector<double>& g, const Matrix& basis, int iterations = 500);

}  // namespace ppsynth::pcf2017
