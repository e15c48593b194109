#include "core/metrics/pcf.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

constexpr int kReanchor = 16;

void check_options(const PcfOptions& o) {
  if (o.bins < 2 || o.bins > kMaxBins)
    throw InputError("pcf: bins must be in 2.." + std::to_string(kMaxBins) + " (got " + std::to_string(o.bins) + ")");
  if (!(o.sigma_factor > 0) || !std::isfinite(o.sigma_factor))
    throw InputError("pcf: sigma_factor must be positive and finite");
  if (!(o.r_max_factor > o.r_min_factor) || !(o.r_min_factor >= 0) || !std::isfinite(o.r_max_factor))
    throw InputError("pcf: need 0 <= r_min_factor < r_max_factor (finite)");
  if (!(o.r_max >= 0) || !std::isfinite(o.r_max)) throw InputError("pcf: r_max must be >= 0");
}

// Shared estimator: pairs (i in a, j in b, i != j when `same`), normalized by `lambda2`.
Curve estimate(const PointSet& a, const PointSet& b, bool same, double r_max, double lambda2,
               const PcfOptions& o) {
  const Domain& dom = a.domain();
  const bool periodic = o.periodic || dom.periodic;
  const double W = dom.width(), H = dom.height(), A = dom.area();
  Curve c;
  c.r.resize(o.bins);
  c.g.assign(o.bins, 0.0);
  const double r0 = o.r_min_factor, r1 = o.r_max_factor;
  for (int k = 0; k < o.bins; ++k) c.r[k] = r0 + (r1 - r0) * k / (o.bins - 1);
  if (a.empty() || b.empty() || !(lambda2 > 0) || !std::isfinite(r_max)) return c;

  const double sigma = o.sigma_factor * r_max;
  const double cutoff = r1 * r_max + 4 * sigma;
  const double knorm = 1.0 / (std::sqrt(M_PI) * sigma);
  // Bin k sits at r_k = c.r[k] * r_max; a pair at distance h feeds the bins with
  // |r_k - h| <= 4 sigma only: a contiguous run found from h (one bin of slack on each side,
  // the exact test u^2 <= 16 decides). Along the run u_k = (r_k - h) / sigma grows by
  // delta = step / sigma, so exp(-u_{k+1}^2) = exp(-u_k^2) * q_k with q_{k+1} = q_k *
  // exp(-2 delta^2): two exp() per pair instead of one per bin (relative error of the
  // product below 1e-14: the run restarts from exp() every kReanchor bins; the estimator
  // is unchanged).
  const double step = (r1 - r0) / (o.bins - 1) * r_max;
  const double delta = step / sigma, q_step = std::exp(-2 * delta * delta);
  const size_t n_a = a.size();
  // From a million points a PCF runs long enough to look hung without a line per 10 %
  // (docs/lab/performance/README.md, "Evaluation on large inputs").
  const bool report = n_a >= 1000000;
  size_t next_report = n_a / 10;
  NeighborIndex index(b.positions(), dom, periodic);
  std::vector<double> dist;
  for (size_t i = 0; i < n_a; ++i) {
    if (report && i == next_report) {
      spdlog::info("pcf: {}% of {} points", 100 * i / n_a, n_a);
      next_report += n_a / 10;
    }
    const Vec2 p = a[i];
    auto js = index.radius(p, cutoff, &dist);
    for (size_t t = 0; t < js.size(); ++t) {
      const size_t j = js[t];
      if (same && j == i) continue;
      const double h = dist[t];
      double weight;
      if (periodic) {
        weight = 1.0 / A;
      } else {
        const double ax = W - std::abs(b[j].x - p.x), ay = H - std::abs(b[j].y - p.y);
        if (ax <= 0 || ay <= 0) continue;
        weight = 1.0 / (ax * ay);
      }
      const double kf_lo = std::floor(((h - 4 * sigma) / r_max - r0) * (o.bins - 1) / (r1 - r0)) - 1;
      const double kf_hi = std::ceil(((h + 4 * sigma) / r_max - r0) * (o.bins - 1) / (r1 - r0)) + 1;
      if (!(kf_hi >= 0) || !(kf_lo <= o.bins - 1)) continue;
      const int k_lo = kf_lo < 0 ? 0 : static_cast<int>(kf_lo);
      const int k_hi = kf_hi > o.bins - 1 ? o.bins - 1 : static_cast<int>(kf_hi);
      const double wk = weight * knorm;
      bool started = false;
      int since = 0;
      double e = 0, q = 0;
      for (int k = k_lo; k <= k_hi; ++k) {
        const double u = (c.r[k] * r_max - h) / sigma;
        if (u * u > 16) {
          if (started) break;  // past the run
          continue;
        }
        if (!started || ++since == kReanchor) {
          e = std::exp(-u * u);
          q = std::exp(-delta * (2 * u + delta));
          started = true;
          since = 0;
        } else {
          e *= q;
          q *= q_step;
        }
        c.g[k] += wk * e;
      }
    }
  }
  for (int k = 0; k < o.bins; ++k) {
    const double r = c.r[k] * r_max;
    c.g[k] /= lambda2 * 2 * M_PI * r;
  }
  return c;
}

}  // namespace

double pcf_unit(size_t n, double area) { return 2.0 * packing_radius(n, area); }

Curve pcf(const PointSet& ps, const PcfOptions& opt) {
  check_options(opt);
  const double A = ps.domain().area();
  const double n = static_cast<double>(ps.size());
  const double r_max = opt.r_max > 0 ? opt.r_max : pcf_unit(ps.size(), A);
  const double lambda2 = n * (n - 1) / (A * A);
  return estimate(ps, ps, true, r_max, lambda2, opt);
}

Curve cross_pcf(const PointSet& a, const PointSet& b, const PcfOptions& opt) {
  check_options(opt);
  const double A = a.domain().area();
  const double r_max = opt.r_max > 0 ? opt.r_max : pcf_unit(a.size() + b.size(), A);
  const double lambda2 = static_cast<double>(a.size()) * b.size() / (A * A);
  return estimate(a, b, false, r_max, lambda2, opt);
}

double curve_mse(const Curve& a, const Curve& b) {
  if (a.g.size() != b.g.size() || a.g.empty())
    throw InputError("curve_mse: curves have different (or no) radii");
  double s = 0;
  for (size_t k = 0; k < a.g.size(); ++k) s += (a.g[k] - b.g[k]) * (a.g[k] - b.g[k]);
  return s / a.g.size();
}

Curve mean_curve(const std::vector<Curve>& curves) {
  if (curves.empty()) throw InputError("mean_curve: no curves");
  Curve m = curves.front();
  for (size_t c = 1; c < curves.size(); ++c) {
    if (curves[c].g.size() != m.g.size()) throw InputError("mean_curve: curves have different radii");
    for (size_t k = 0; k < m.g.size(); ++k) m.g[k] += curves[c].g[k];
  }
  for (double& v : m.g) v /= curves.size();
  return m;
}

}  // namespace ppsynth
