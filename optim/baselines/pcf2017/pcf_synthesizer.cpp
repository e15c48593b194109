#include "optim/baselines/pcf2017/pcf_synthesizer.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.hpp"

namespace ppsynth::pcf2017 {

namespace {

Vec2 wrap(Vec2 p, const Domain& d) {
  p.x = d.x0 + (p.x - d.x0) - d.width() * std::floor((p.x - d.x0) / d.width());
  p.y = d.y0 + (p.y - d.y0) - d.height() * std::floor((p.y - d.y0) / d.height());
  if (p.x >= d.x1) p.x = d.x0;  // rounding of values just below x0
  if (p.y >= d.y1) p.y = d.y0;
  return p;
}

}  // namespace

DescentResult descend(const PcfEnergy& energy, std::vector<Vec2> x, double rmax,
                      const DescentOptions& opt, const DescentCallback& cb) {
  if (opt.iterations < 0 || !(opt.step > 0) || !(opt.max_step >= opt.step) || !(opt.grow >= 1) ||
      opt.line_search_halvings < 0)
    throw InputError("pcf2017: impossible descent options (need iterations >= 0, 0 < step <= max_step, grow >= 1)");
  const Domain& d = energy.domain();
  for (Vec2& p : x) p = wrap(p, d);
  DescentResult res;
  std::vector<Vec2> grad, trial_grad, trial(x.size());
  double E = energy.evaluate(x, &grad);
  res.energy.push_back(E);
  double delta = opt.step * rmax;
  for (int it = 0; it < opt.iterations; ++it) {
    double gmax = 0;
    for (const Vec2& g : grad) gmax = std::max(gmax, std::hypot(g.x, g.y));
    if (!(gmax > 0)) {
      res.converged = true;
      break;
    }
    bool accepted = false;
    for (int h = 0; h <= opt.line_search_halvings; ++h) {
      const double scale = delta / gmax;
      for (size_t i = 0; i < x.size(); ++i) trial[i] = wrap({x[i].x - scale * grad[i].x, x[i].y - scale * grad[i].y}, d);
      const double Et = energy.evaluate(trial, &trial_grad);
      if (Et < E) {
        x.swap(trial);
        grad.swap(trial_grad);
        E = Et;
        accepted = true;
        break;
      }
      delta *= 0.5;
    }
    if (!accepted) {
      res.converged = true;
      break;
    }
    res.energy.push_back(E);
    delta = std::min(delta * opt.grow, opt.max_step * rmax);
    if (cb) cb(it, E);
  }
  res.points = std::move(x);
  return res;
}

std::vector<Vec2> uniform_points(size_t n, const Domain& domain, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(domain.x0, domain.x1), uy(domain.y0, domain.y1);
  std::vector<Vec2> p(n);
  for (Vec2& q : p) q = {ux(rng), uy(rng)};
  return p;
}

DescentResult synthesize_stationary(const std::vector<double>& target, std::vector<Vec2> init,
                                    const Domain& domain, const PcfParams& params,
                                    const DescentOptions& opt, const DescentCallback& cb) {
  Domain torus = domain;
  torus.periodic = true;
  PcfEnergy energy(torus, {whole_domain_neighborhood(init.size(), torus, target)}, params);
  return descend(energy, std::move(init), rmax_for(double(init.size()), torus.area()), opt, cb);
}

namespace {

// Mean of the density over the domain and its maximum, on a 64 x 64 grid of cell centers.
std::pair<double, double> density_mean_max(const ScalarMap& density, const Domain& d) {
  const int G = 64;
  double sum = 0, mx = 0;
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      const double v = density({d.x0 + (i + 0.5) * d.width() / G, d.y0 + (j + 0.5) * d.height() / G});
      if (!(v > 0) || !std::isfinite(v)) throw InputError("pcf2017: the density map must be positive and finite");
      sum += v;
      mx = std::max(mx, v);
    }
  return {sum / (G * G), mx};
}

}  // namespace

std::vector<Neighborhood> adaptive_neighborhoods(const AdaptiveTarget& t, size_t n, const Domain& domain) {
  if (!t.density) throw InputError("pcf2017: adaptive target without a density map");
  if (t.basis.empty() || t.basis.size() != t.weights.size())
    throw InputError("pcf2017: adaptive target needs one weight map per basis PCF");
  if (!(t.neighborhood_points > 1)) throw InputError("pcf2017: neighborhood_points must be > 1");
  const auto [mean, mx] = density_mean_max(t.density, domain);
  const double scale = double(n) / (mean * domain.area());  // lambda = scale * density
  const double r_min = std::sqrt(t.neighborhood_points / (M_PI * scale * mx));
  const double T = r_min / 2;
  const int nx = std::max(1, int(std::ceil(domain.width() / T))), ny = std::max(1, int(std::ceil(domain.height() / T)));
  std::vector<Neighborhood> hoods;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 c{domain.x0 + (i + 0.5) * domain.width() / nx, domain.y0 + (j + 0.5) * domain.height() / ny};
      const double lambda = scale * t.density(c);
      const double R = std::sqrt(t.neighborhood_points / (M_PI * lambda));
      std::vector<double> w(t.basis.size());
      double wsum = 0;
      for (size_t l = 0; l < w.size(); ++l) {
        w[l] = t.weights[l](c);
        if (!(w[l] >= 0) || !std::isfinite(w[l])) throw InputError("pcf2017: weight maps must be finite and >= 0");
        wsum += w[l];
      }
      if (!(wsum > 0)) throw InputError("pcf2017: the weight maps sum to 0 at a neighborhood center");
      std::vector<double> target(t.basis[0].size(), 0.0);
      for (size_t l = 0; l < w.size(); ++l) {
        if (t.basis[l].size() != target.size()) throw InputError("pcf2017: basis PCFs differ in length");
        for (size_t b = 0; b < target.size(); ++b) target[b] += w[l] / wsum * t.basis[l][b];
      }
      hoods.push_back(disk_neighborhood(c, R, lambda, std::move(target)));
    }
  return hoods;
}

std::vector<Vec2> density_points(const ScalarMap& density, size_t n, const Domain& domain, uint64_t seed) {
  const double mx = density_mean_max(density, domain).second;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(domain.x0, domain.x1), uy(domain.y0, domain.y1), u01(0, 1);
  std::vector<Vec2> p;
  p.reserve(n);
  while (p.size() < n) {
    const Vec2 q{ux(rng), uy(rng)};
    if (u01(rng) * mx <= density(q)) p.push_back(q);
  }
  return p;
}

DescentResult synthesize_adaptive(const AdaptiveTarget& target, size_t n, const Domain& domain,
                                  uint64_t seed, const PcfParams& params,
                                  const DescentOptions& opt, const DescentCallback& cb) {
  Domain torus = domain;
  torus.periodic = true;
  PcfEnergy energy(torus, adaptive_neighborhoods(target, n, torus), params);
  // Step unit: r_max of the densest region (the smallest spacing).
  const double mx = density_mean_max(target.density, torus).second;
  const double mean = density_mean_max(target.density, torus).first;
  const double rmax = rmax_for_intensity(double(n) / torus.area() * mx / mean);
  return descend(energy, density_points(target.density, n, torus, seed), rmax, opt, cb);
}

}  // namespace ppsynth::pcf2017
