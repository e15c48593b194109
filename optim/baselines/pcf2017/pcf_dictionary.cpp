#include "optim/baselines/pcf2017/pcf_dictionary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace ppsynth::pcf2017 {

Eigen jacobi_eigen(Matrix a, int max_sweeps, double tol) {
  const size_t n = a.size();
  for (const auto& row : a)
    if (row.size() != n) throw InputError("jacobi_eigen: matrix is not square");
  Matrix v(n, std::vector<double>(n, 0.0));
  for (size_t i = 0; i < n; ++i) v[i][i] = 1.0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    double off = 0, diag = 0;
    for (size_t i = 0; i < n; ++i) {
      diag += a[i][i] * a[i][i];
      for (size_t j = i + 1; j < n; ++j) off += a[i][j] * a[i][j];
    }
    if (off <= tol * tol * std::max(diag, 1e-300)) break;
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q) {
        if (std::abs(a[p][q]) < 1e-300) continue;
        // Rotation that zeroes a[p][q] (Golub & Van Loan, symmetric Schur).
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (size_t k = 0; k < n; ++k) {  // columns p, q
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (size_t k = 0; k < n; ++k) {  // rows p, q
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (size_t k = 0; k < n; ++k) {  // accumulate V = V J (eigenvectors are columns)
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return a[i][i] > a[j][j]; });
  Eigen e;
  for (size_t i : order) {
    e.values.push_back(a[i][i]);
    std::vector<double> col(n);
    for (size_t k = 0; k < n; ++k) col[k] = v[k][i];
    e.vectors.push_back(std::move(col));
  }
  return e;
}

Pca pca(const Matrix& samples, double variance_kept) {
  if (samples.empty()) throw InputError("pca: no samples");
  const size_t m = samples.size(), d = samples[0].size();
  for (const auto& s : samples)
    if (s.size() != d) throw InputError("pca: samples differ in length");
  if (!(variance_kept > 0 && variance_kept <= 1)) throw InputError("pca: variance_kept must be in (0, 1]");
  Pca out;
  out.mean.assign(d, 0.0);
  for (const auto& s : samples)
    for (size_t i = 0; i < d; ++i) out.mean[i] += s[i] / double(m);
  Matrix cov(d, std::vector<double>(d, 0.0));
  for (const auto& s : samples)
    for (size_t i = 0; i < d; ++i) {
      const double ci = s[i] - out.mean[i];
      for (size_t j = i; j < d; ++j) cov[i][j] += ci * (s[j] - out.mean[j]) / double(m);
    }
  for (size_t i = 0; i < d; ++i)
    for (size_t j = 0; j < i; ++j) cov[i][j] = cov[j][i];
  Eigen e = jacobi_eigen(cov);
  for (double v : e.values) out.total_variance += std::max(v, 0.0);
  double acc = 0;
  for (size_t c = 0; c < e.values.size() && out.total_variance > 0; ++c) {
    out.components.push_back(e.vectors[c]);
    out.variances.push_back(std::max(e.values[c], 0.0));
    acc += std::max(e.values[c], 0.0);
    if (acc >= variance_kept * out.total_variance) break;
  }
  for (const auto& s : samples) {
    std::vector<double> sc;
    for (const auto& comp : out.components) {
      double p = 0;
      for (size_t i = 0; i < d; ++i) p += (s[i] - out.mean[i]) * comp[i];
      sc.push_back(p);
    }
    out.scores.push_back(std::move(sc));
  }
  return out;
}

namespace {

// Euclidean projection onto {w >= 0, sum w = 1} (sort-based, Held et al.).
void project_simplex(std::vector<double>& w) {
  std::vector<double> u = w;
  std::sort(u.begin(), u.end(), std::greater<double>());
  double cum = 0, theta = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    cum += u[i];
    const double t = (cum - 1.0) / double(i + 1);
    if (u[i] - t > 0) theta = t;
  }
  for (double& x : w) x = std::max(x - theta, 0.0);
}

double norm_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

}  // namespace

std::vector<double> simplex_weights(const std::vector<double>& g, const Matrix& basis, int iterations) {
  const size_t L = basis.size();
  if (L == 0) throw InputError("simplex_weights: empty basis");
  // Normal equations of ||g - B^T w||^2: G w - c, with G = B B^T, c = B g.
  Matrix G(L, std::vector<double>(L, 0.0));
  std::vector<double> c(L, 0.0);
  double trace = 0;
  for (size_t a = 0; a < L; ++a) {
    for (size_t b = 0; b < L; ++b)
      for (size_t i = 0; i < g.size(); ++i) G[a][b] += basis[a][i] * basis[b][i];
    for (size_t i = 0; i < g.size(); ++i) c[a] += basis[a][i] * g[i];
    trace += G[a][a];
  }
  const double step = 1.0 / std::max(trace, 1e-300);  // 1 / (upper bound of the Lipschitz constant)
  std::vector<double> w(L, 1.0 / double(L));
  for (int it = 0; it < iterations; ++it) {
    std::vector<double> next = w;
    for (size_t a = 0; a < L; ++a) {
      double grad = -c[a];
      for (size_t b = 0; b < L; ++b) grad += G[a][b] * w[b];
      next[a] -= step * grad;
    }
    project_simplex(next);
    w.swap(next);
  }
  return w;
}

PcfDictionary build_dictionary(const Matrix& samples, const DictionaryOptions& opt) {
  PcfDictionary dict;
  dict.pca = pca(samples, opt.variance_kept);
  const size_t m = samples.size(), d = samples[0].size();
  const double eps = opt.error_threshold > 0 ? opt.error_threshold : 0.1 * std::sqrt(double(d));
  // The two ends of the first principal component (one sample when the PCA is degenerate).
  size_t lo = 0, hi = 0;
  if (!dict.pca.components.empty())
    for (size_t k = 0; k < m; ++k) {
      if (dict.pca.scores[k][0] < dict.pca.scores[lo][0]) lo = k;
      if (dict.pca.scores[k][0] > dict.pca.scores[hi][0]) hi = k;
    }
  dict.basis_index.push_back(lo);
  if (hi != lo && norm_diff(samples[lo], samples[hi]) > eps) dict.basis_index.push_back(hi);
  while (true) {
    dict.basis.clear();
    for (size_t i : dict.basis_index) dict.basis.push_back(samples[i]);
    dict.weights.assign(m, {});
    dict.residual.assign(m, 0.0);
    size_t worst = 0;
    for (size_t k = 0; k < m; ++k) {
      dict.weights[k] = simplex_weights(samples[k], dict.basis, opt.qp_iterations);
      std::vector<double> rec(d, 0.0);
      for (size_t l = 0; l < dict.basis.size(); ++l)
        for (size_t i = 0; i < d; ++i) rec[i] += dict.weights[k][l] * dict.basis[l][i];
      dict.residual[k] = norm_diff(samples[k], rec);
      if (dict.residual[k] > dict.residual[worst]) worst = k;
    }
    if (dict.residual[worst] <= eps || int(dict.basis_index.size()) >= opt.max_basis ||
        std::find(dict.basis_index.begin(), dict.basis_index.end(), worst) != dict.basis_index.end())
      break;
    dict.basis_index.push_back(worst);
  }
  return dict;
}

}  // namespace ppsynth::pcf2017
