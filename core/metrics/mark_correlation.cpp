#include "core/metrics/mark_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/second_order.hpp"

namespace ppsynth {

namespace {
// R's quantile(x, p, type = 7) of sorted x.
double quantile7(const std::vector<double>& sorted, double p) {
  const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
  const size_t lo = static_cast<size_t>(std::floor(h));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}
}  // namespace

double bandwidth_nrd0(std::vector<double> x) {
  const size_t n = x.size();
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / static_cast<double>(n - 1));
  std::sort(x.begin(), x.end());
  const double iqr = quantile7(x, 0.75) - quantile7(x, 0.25);
  double lo = std::min(sd, iqr / 1.34);
  // R's fallbacks when the spread is 0: the sd, else |x[1]|, else 1.
  if (!(lo > 0)) lo = sd > 0 ? sd : (std::abs(x.front()) > 0 ? std::abs(x.front()) : 1.0);
  return 0.9 * lo * std::pow(static_cast<double>(n), -0.2);
}

MarkCorrelation mark_correlation(const PointSet& ps, size_t attribute, EdgeCorrection c, std::vector<double> r) {
  if (attribute >= ps.num_attributes()) throw InputError("mark_correlation: no attribute column " + std::to_string(attribute));
  const std::string& name = ps.attribute_names()[attribute];
  const std::vector<double>& m = ps.attribute_column(attribute);
  double mean = 0;
  for (double v : m) {
    if (v < 0) throw InputError("mark correlation of '" + name + "': negative marks (k_mm is normalized by the mean mark)");
    mean += v;
  }
  if (!m.empty()) mean /= static_cast<double>(m.size());
  if (!(mean > 0)) throw InputError("mark correlation of '" + name + "': the mean mark is 0, nothing to normalize by");
  const Domain& w = ps.domain();
  if (r.empty()) r = spatstat_r_grid(w, static_cast<double>(ps.size()) / w.area());
  MarkCorrelation out;
  out.r = r;
  const size_t R = r.size();
  const std::vector<ClosePair> pairs = close_pairs(ps, nullptr, r.back());
  std::vector<double> d;
  d.reserve(pairs.size());
  for (const auto& p : pairs) d.push_back(p.d);
  out.bandwidth = bandwidth_nrd0(d);
  out.k.assign(R, std::numeric_limits<double>::quiet_NaN());
  if (!(out.bandwidth > 0)) return out;
  const double bw = out.bandwidth, ef = mean * mean;
  std::vector<double> num(R, 0.0), den(R, 0.0);
  for (const auto& p : pairs) {
    const double e = edge_weight(c, w, ps[p.i], ps[p.j], p.d);
    const double f = m[p.i] * m[p.j];
    // Only the radii within 10 bw (exp(-50): nothing a double sum keeps beside the peak).
    const auto k0 = static_cast<size_t>(std::lower_bound(r.begin(), r.end(), p.d - 10 * bw) - r.begin());
    for (size_t k = k0; k < R && r[k] <= p.d + 10 * bw; ++k) {
      const double t = (r[k] - p.d) / bw;
      const double g = std::exp(-0.5 * t * t);
      num[k] += g * f * e;
      den[k] += g * e;
    }
  }
  for (size_t k = 0; k < R; ++k)
    if (den[k] > 0) out.k[k] = num[k] / (ef * den[k]);
  return out;
}

}  // namespace ppsynth
