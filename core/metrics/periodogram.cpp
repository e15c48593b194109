#include "core/metrics/periodogram.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "core/metrics/summary_stats.hpp"

namespace ppsynth {

namespace {

// Points per block of phase tables: 2048 x (2F+1) doubles, ~4 MB a table at F = 128.
constexpr size_t kBlock = 2048;
// A ring more than half empty (a lattice, a tiled copy) has median ~0: the denominator is at
// least this fraction of the mean off-DC power, so the ratio stays a readable number.
constexpr double kRingMedianFloor = 1e-3;

double sinc(double t) { return t == 0 ? 1.0 : std::sin(M_PI * t) / (M_PI * t); }

// Runs fn(begin, end) over [0, n) split into `threads` contiguous ranges.
template <class Fn>
void parallel_ranges(int n, int threads, const Fn& fn) {
  threads = std::max(1, std::min(threads, n));
  if (threads == 1) {
    fn(0, n);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    const int b = n * t / threads, e = n * (t + 1) / threads;
    pool.emplace_back([&fn, b, e] { fn(b, e); });
  }
  for (auto& th : pool) th.join();
}

}  // namespace

Periodogram periodogram(const PointSet& ps, const PeriodogramOptions& opt) {
  if (ps.empty()) throw InputError("periodogram: the point set is empty");
  if (opt.frequencies < 1 || opt.frequencies > kMaxPeriodogramFrequencies)
    throw InputError("periodogram: frequencies (--frequencies) must be in 1.." +
                     std::to_string(kMaxPeriodogramFrequencies) + " (got " + std::to_string(opt.frequencies) + ")");
  if (!std::isfinite(opt.step) || opt.step < 0)
    throw InputError("periodogram: the frequency step (--step) must be a finite number >= 0 (0 = 1 / the longer side)");
  const Domain& d = ps.domain();
  const double W = d.width(), H = d.height();
  if (!(W > 0 && H > 0 && std::isfinite(W) && std::isfinite(H)))
    throw InputError("periodogram: the domain needs a positive, finite width and height");
  Periodogram p;
  p.F = opt.frequencies;
  p.step = opt.step > 0 ? opt.step : 1.0 / std::max(W, H);
  p.points = ps.size();
  const int F = p.F, S = p.side(), rows = F + 1;  // rows ky = 0..F; ky < 0 by symmetry
  const size_t n = ps.size();
  std::vector<double> re(static_cast<size_t>(rows) * S, 0.0), im(re.size(), 0.0);
  std::vector<double> cx(kBlock * S), sx(kBlock * S), cy(kBlock * rows), sy(kBlock * rows);
  const int threads = opt.threads > 0 ? opt.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (size_t b0 = 0; b0 < n; b0 += kBlock) {
    const size_t m = std::min(kBlock, n - b0);
    // Phase tables exp(-2 pi i k step u) of the block: k = -F..F along x, 0..F along y.
    for (size_t j = 0; j < m; ++j) {
      const double u = ps[b0 + j].x - d.x0, v = ps[b0 + j].y - d.y0;
      double* cxj = &cx[j * S];
      double* sxj = &sx[j * S];
      for (int k = 0; k <= F; ++k) {
        const double a = -2 * M_PI * (k * p.step) * u;
        cxj[F + k] = cxj[F - k] = std::cos(a);
        sxj[F + k] = std::sin(a);
        sxj[F - k] = -sxj[F + k];
        const double c = -2 * M_PI * (k * p.step) * v;
        cy[j * rows + k] = std::cos(c);
        sy[j * rows + k] = std::sin(c);
      }
    }
    parallel_ranges(rows, threads, [&](int r0, int r1) {
      for (int ky = r0; ky < r1; ++ky) {
        double* ar = &re[static_cast<size_t>(ky) * S];
        double* ai = &im[static_cast<size_t>(ky) * S];
        for (size_t j = 0; j < m; ++j) {
          const double yr = cy[j * rows + ky], yi = sy[j * rows + ky];
          const double* xr = &cx[j * S];
          const double* xi = &sx[j * S];
          for (int kx = 0; kx < S; ++kx) {
            ar[kx] += xr[kx] * yr - xi[kx] * yi;
            ai[kx] += xr[kx] * yi + xi[kx] * yr;
          }
        }
      }
    });
  }
  // The window's transform per axis: exp(-pi i f L) sinc(f L).
  auto window = [&](int k, double L, double& wr, double& wi) {
    const double t = k * p.step * L, s = sinc(t);
    wr = std::cos(M_PI * t) * s;
    wi = -std::sin(M_PI * t) * s;
  };
  const double N = static_cast<double>(n);
  p.power.assign(static_cast<size_t>(S) * S, 0.0);
  for (int ky = 0; ky <= F; ++ky) {
    double wyr, wyi;
    window(ky, H, wyr, wyi);
    for (int kx = -F; kx <= F; ++kx) {
      double wxr, wxi;
      window(kx, W, wxr, wxi);
      const size_t i = static_cast<size_t>(ky) * S + (kx + F);
      const double sr = re[i] - N * (wxr * wyr - wxi * wyi);
      const double si = im[i] - N * (wxr * wyi + wxi * wyr);
      const double pw = (kx == 0 && ky == 0) ? 0.0 : (sr * sr + si * si) / N;
      p.power[static_cast<size_t>(ky + F) * S + (kx + F)] = pw;
      p.power[static_cast<size_t>(F - ky) * S + (F - kx)] = pw;  // P(-f) = P(f)
    }
  }
  return p;
}

SpectrumPeak spectrum_peak(const Periodogram& p) {
  const int F = p.F;
  std::vector<std::vector<double>> rings(static_cast<size_t>(F) + 1);
  for (int ky = -F; ky <= F; ++ky)
    for (int kx = -F; kx <= F; ++kx) {
      const long k = std::lround(std::hypot(kx, ky));
      if (k >= 1 && k <= F) rings[k].push_back(p.at(kx, ky));
    }
  double sum = 0;
  size_t count = 0;
  for (const auto& r : rings)
    for (double v : r) sum += v, ++count;
  const double floor = std::max(kRingMedianFloor * (count ? sum / count : 0.0), 1e-300);
  std::vector<double> median(rings.size(), 0.0);
  for (size_t k = 1; k < rings.size(); ++k) median[k] = std::max(quantile(rings[k], 0.5), floor);
  SpectrumPeak best;
  for (int ky = -F; ky <= F; ++ky)
    for (int kx = -F; kx <= F; ++kx) {
      const long k = std::lround(std::hypot(kx, ky));
      if (k < 1 || k > F) continue;
      const double r = p.at(kx, ky) / median[k];
      if (r > best.ratio) {
        best.ratio = r;
        best.power = p.at(kx, ky);
        best.ring_median = median[k];
        best.fx = kx * p.step;
        best.fy = ky * p.step;
        best.ring = static_cast<int>(k);
      }
    }
  return best;
}

}  // namespace ppsynth
