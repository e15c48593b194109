#include "optim/baselines/pcf2017/local_pcf.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "core/error.hpp"

namespace ppsynth::pcf2017 {

double curve_mse(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) throw InputError("curve_mse: curves differ in length");
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return s / double(a.size());
}

double disk_autocorrelation(double R, double t) {
  if (t >= 2 * R) return 0.0;
  return 2 * R * R * std::acos(t / (2 * R)) - 0.5 * t * std::sqrt(4 * R * R - t * t);
}

namespace {

// Minimum-image difference on a periodic domain (identity otherwise).
Vec2 diff(const Domain& d, bool periodic, Vec2 a, Vec2 b) {
  double dx = a.x - b.x, dy = a.y - b.y;
  if (periodic) {
    dx -= d.width() * std::round(dx / d.width());
    dy -= d.height() * std::round(dy / d.height());
  }
  return {dx, dy};
}

// Accumulates sum_{ordered pairs} k_s(r_b - d_ij) / a(h_ij) into `acc` (absolute radii `r`).
void accumulate_pair(double dist, double weight, const std::vector<double>& r, double s,
                     double cutoff, std::vector<double>& acc) {
  const double step = r.size() > 1 ? r[1] - r[0] : 1.0;
  const long lo = std::max(0L, long(std::floor((dist - cutoff - r[0]) / step)));
  const long hi = std::min(long(r.size()) - 1, long(std::ceil((dist + cutoff - r[0]) / step)));
  for (long b = lo; b <= hi; ++b) acc[b] += weight * kernel(r[b] - dist, s);
}

PcfCurve finish(std::vector<double> acc, std::vector<double> rel, double rmax, double lambda2) {
  PcfCurve c;
  c.r_max = rmax;
  c.rel = std::move(rel);
  c.r.resize(c.rel.size());
  c.g.resize(c.rel.size());
  for (size_t b = 0; b < c.rel.size(); ++b) {
    c.r[b] = c.rel[b] * rmax;
    c.g[b] = acc[b] / (lambda2 * 2 * M_PI * c.r[b]);
  }
  return c;
}

void check_params(const PcfParams& p) {
  if (p.bins < 2 || !(p.r_a > 0) || !(p.r_b > p.r_a) || !(p.sigma_factor > 0) || !(p.kernel_cutoff > 0))
    throw InputError("pcf2017: impossible PCF parameters (need bins >= 2, 0 < r_a < r_b, sigma_factor > 0)");
}

}  // namespace

PcfCurve pattern_pcf(const PointSet& ps, const PcfParams& params, bool periodic) {
  check_params(params);
  if (ps.size() < 2) throw InputError("pattern PCF: need at least 2 points");
  const Domain& d = ps.domain();
  periodic = periodic || d.periodic;
  const double n = double(ps.size()), A = d.area();
  const double rmax = rmax_for(n, A), s = params.sigma_factor * rmax;
  const double cutoff = params.kernel_cutoff * s;
  const std::vector<double> rel = relative_radii(params);
  std::vector<double> r(rel.size());
  for (size_t b = 0; b < r.size(); ++b) r[b] = rel[b] * rmax;
  const double reach = r.back() + cutoff;
  std::vector<double> acc(r.size(), 0.0);
  const auto& p = ps.positions();
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) {
      const Vec2 h = diff(d, periodic, p[i], p[j]);
      const double t = std::hypot(h.x, h.y);
      if (t > reach) continue;
      const double a = periodic ? A : (d.width() - std::abs(h.x)) * (d.height() - std::abs(h.y));
      if (a <= 0) continue;
      accumulate_pair(t, 2.0 / a, r, s, cutoff, acc);  // (i,j) and (j,i)
    }
  return finish(std::move(acc), rel, rmax, n * (n - 1) / (A * A));
}

std::vector<PcfCurve> local_pcfs(const PointSet& ps, const std::vector<Vec2>& queries,
                                 const LocalPcfOptions& opt) {
  check_params(opt.pcf);
  if (ps.size() < 2) throw InputError("local PCF: need at least 2 points");
  if (opt.radius <= 0 && !(opt.neighborhood_points > 1))
    throw InputError("local PCF: neighborhood_points must be > 1 (or give a radius)");
  const Domain& d = ps.domain();
  const bool periodic = opt.periodic || d.periodic;
  IntensityOptions iopt = opt.intensity;
  iopt.periodic = iopt.periodic || periodic;
  const std::vector<double> lambdas = local_intensity(ps, queries, iopt);
  const std::vector<double> rel = relative_radii(opt.pcf);
  const auto& p = ps.positions();
  std::vector<PcfCurve> out;
  out.reserve(queries.size());
  for (size_t q = 0; q < queries.size(); ++q) {
    const Vec2 x = queries[q];
    const double lambda_kernel = lambdas[q];
    if (!(lambda_kernel > 0)) throw InputError("local PCF: zero intensity at a query position");
    const double R = opt.radius > 0 ? opt.radius : std::sqrt(opt.neighborhood_points / (M_PI * lambda_kernel));

    // Points of N_x (positions relative to x, unwrapped).
    std::vector<Vec2> local;
    for (const Vec2& pt : p) {
      const Vec2 h = diff(d, periodic, pt, x);
      if (h.x * h.x + h.y * h.y <= R * R) local.push_back(h);
    }
    // Window autocorrelation a(h): exact for an unclipped disk, numeric when clipped.
    const bool clipped = !periodic && (x.x - R < d.x0 || x.x + R > d.x1 || x.y - R < d.y0 || x.y + R > d.y1);
    if (periodic && 2 * R > std::min(d.width(), d.height()))
      throw InputError("local PCF: neighborhood diameter exceeds the periodic domain");
    std::function<double(Vec2)> autocorr;
    if (!clipped) {
      autocorr = [R](Vec2 h) { return disk_autocorrelation(R, std::hypot(h.x, h.y)); };
    } else {
      const int G = std::max(8, opt.window_samples);
      const double cell = 2 * R / G;
      auto inside = [&](Vec2 y) {  // y relative to x
        return y.x * y.x + y.y * y.y <= R * R && x.x + y.x >= d.x0 && x.x + y.x <= d.x1 &&
               x.y + y.y >= d.y0 && x.y + y.y <= d.y1;
      };
      auto samples = std::make_shared<std::vector<Vec2>>();
      for (int a = 0; a < G; ++a)
        for (int b = 0; b < G; ++b) {
          Vec2 y{-R + (a + 0.5) * cell, -R + (b + 0.5) * cell};
          if (inside(y)) samples->push_back(y);
        }
      autocorr = [samples, inside, cell](Vec2 h) {
        size_t c = 0;
        for (const Vec2& y : *samples) c += inside({y.x + h.x, y.y + h.y});
        return double(c) * cell * cell;
      };
    }
    // Intensity of the window: kernel estimate, or k / |N_x| with lambda^2 = k (k - 1) / |N_x|^2.
    double lambda = lambda_kernel, lambda2 = lambda_kernel * lambda_kernel;
    if (opt.lambda_from_count) {
      const double area = autocorr({0, 0}), k = double(local.size());
      if (local.size() < 2 || !(area > 0)) throw InputError("local PCF: fewer than 2 points in a neighborhood");
      lambda = k / area;
      lambda2 = k * (k - 1) / (area * area);
    }
    const double rmax = rmax_for_intensity(lambda), s = opt.pcf.sigma_factor * rmax;
    const double cutoff = opt.pcf.kernel_cutoff * s;
    std::vector<double> r(rel.size());
    for (size_t b = 0; b < r.size(); ++b) r[b] = rel[b] * rmax;
    const double reach = r.back() + cutoff;
    std::vector<double> acc(r.size(), 0.0);
    for (size_t i = 0; i < local.size(); ++i)
      for (size_t j = i + 1; j < local.size(); ++j) {
        const Vec2 h{local[i].x - local[j].x, local[i].y - local[j].y};
        const double t = std::hypot(h.x, h.y);
        if (t > reach) continue;
        const double a = autocorr(h);
        if (a <= 0) continue;
        accumulate_pair(t, 2.0 / a, r, s, cutoff, acc);
      }
    out.push_back(finish(std::move(acc), rel, rmax, lambda2));
  }
  return out;
}

PcfCurve local_pcf(const PointSet& ps, Vec2 x, const LocalPcfOptions& opt) {
  return local_pcfs(ps, {x}, opt).front();
}

}  // namespace ppsynth::pcf2017
