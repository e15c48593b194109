#include "core/metrics/mark_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/second_order.hpp"
#include "core/metrics/stream_order_statistics.hpp"

namespace ppsynth {

double bandwidth_nrd0(const ValueReplay& replay) {
  size_t n = 0;
  double sum = 0, smallest = std::numeric_limits<double>::infinity(), largest = -smallest;
  replay([&](double v) {
    ++n;
    sum += v;
    smallest = std::min(smallest, v);
    largest = std::max(largest, v);
  });
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  const double mean = sum / static_cast<double>(n);
  // R's quantile(x, p, type = 7): between the values of ranks floor(h) and floor(h) + 1.
  std::vector<size_t> ranks;
  std::vector<double> frac;
  for (double p : {0.25, 0.75}) {
    const double h = (static_cast<double>(n) - 1.0) * p;
    const size_t lo = static_cast<size_t>(std::floor(h));
    ranks.push_back(lo);
    ranks.push_back(std::min(lo + 1, n - 1));
    frac.push_back(h - static_cast<double>(lo));
  }
  StreamOrderStatistics quartiles(ranks, n, smallest, largest);
  double ss = 0;
  for (bool first = true; first || !quartiles.done(); first = false) {
    replay([&](double v) {
      if (first) ss += (v - mean) * (v - mean);
      quartiles.see(v);
    });
    quartiles.end_pass();
  }
  const double sd = std::sqrt(ss / static_cast<double>(n - 1));
  const std::vector<double> v = quartiles.values();
  const double iqr = (v[2] + frac[1] * (v[3] - v[2])) - (v[0] + frac[0] * (v[1] - v[0]));
  double lo = std::min(sd, iqr / 1.34);
  // R's fallbacks when the spread is 0: the sd, else |x[1]| (the smallest), else 1.
  if (!(lo > 0)) lo = sd > 0 ? sd : (std::abs(smallest) > 0 ? std::abs(smallest) : 1.0);
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
  const double reach = r.back();
  out.bandwidth = bandwidth_nrd0([&](const std::function<void(double)>& sink) {
    for_each_close_pair(ps, nullptr, reach, [&](size_t, size_t, double d) { sink(d); });
  });
  out.k.assign(R, std::numeric_limits<double>::quiet_NaN());
  if (!(out.bandwidth > 0)) return out;
  const double bw = out.bandwidth, ef = mean * mean;
  std::vector<double> num(R, 0.0), den(R, 0.0);
  for_each_close_pair(ps, nullptr, reach, [&](size_t i, size_t j, double d) {
    const double e = edge_weight(c, w, ps[i], ps[j], d);
    const double f = m[i] * m[j];
    // Only the radii within 10 bw (exp(-50): nothing a double sum keeps beside the peak).
    const auto k0 = static_cast<size_t>(std::lower_bound(r.begin(), r.end(), d - 10 * bw) - r.begin());
    for (size_t k = k0; k < R && r[k] <= d + 10 * bw; ++k) {
      const double t = (r[k] - d) / bw;
      const double g = std::exp(-0.5 * t * t);
      num[k] += g * f * e;
      den[k] += g * e;
    }
  });
  for (size_t k = 0; k < R; ++k)
    if (den[k] > 0) out.k[k] = num[k] / (ef * den[k]);
  return out;
}

}  // namespace ppsynth
