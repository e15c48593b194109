#include "core/metrics/summary_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ppsynth {

namespace {

std::vector<double> finite_sorted(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  std::sort(v.begin(), v.end());
  return v;
}

double sorted_quantile(const std::vector<double>& v, double q) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(pos));
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

}  // namespace

double quantile(std::vector<double> v, double q) { return sorted_quantile(finite_sorted(std::move(v)), q); }

Summary summarize(const std::vector<double>& values) {
  const std::vector<double> v = finite_sorted(values);
  Summary s;
  s.count = v.size();
  s.not_finite = values.size() - v.size();
  if (v.empty()) {
    s.min = s.q1 = s.median = s.q3 = s.max = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  s.min = v.front();
  s.max = v.back();
  s.q1 = sorted_quantile(v, 0.25);
  s.median = sorted_quantile(v, 0.5);
  s.q3 = sorted_quantile(v, 0.75);
  return s;
}

}  // namespace ppsynth
