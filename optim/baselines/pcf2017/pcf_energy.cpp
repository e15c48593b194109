#include "optim/baselines/pcf2017/pcf_energy.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace ppsynth::pcf2017 {

Neighborhood whole_domain_neighborhood(size_t n, const Domain& domain, std::vector<double> target) {
  if (n < 2) throw InputError("pcf2017: need at least 2 points");
  Neighborhood h;
  h.center = {0.5 * (domain.x0 + domain.x1), 0.5 * (domain.y0 + domain.y1)};
  h.radius = 0;
  h.lambda = double(n) / domain.area();
  h.norm = double(n) * double(n - 1) / domain.area();
  h.target = std::move(target);
  return h;
}

Neighborhood disk_neighborhood(Vec2 center, double radius, double lambda, std::vector<double> target) {
  if (!(radius > 0) || !(lambda > 0)) throw InputError("pcf2017: neighborhood radius and intensity must be > 0");
  Neighborhood h;
  h.center = center;
  h.radius = radius;
  h.lambda = lambda;
  h.norm = lambda * lambda * M_PI * radius * radius;
  h.target = std::move(target);
  return h;
}

namespace {

// Calls f(b, k_s(r_b - d), k_s'(r_b - d)) for the bins within the cutoff of d, with r_b =
// r0 + b * dr. exp() is evaluated twice per call; successive bins use the exact recurrence
// exp(-(t+dr)^2/s^2) = exp(-t^2/s^2) exp(-2 t dr/s^2) exp(-dr^2/s^2).
template <class F>
void for_kernel_bins(double d, double r0, double dr, int bins, double s, double cutoff, F&& f) {
  const int lo = std::max(0, int(std::floor((d - cutoff - r0) / dr)));
  const int hi = std::min(bins - 1, int(std::ceil((d + cutoff - r0) / dr)));
  if (lo > hi) return;
  const double inv_s2 = 1.0 / (s * s), norm = 1.0 / (std::sqrt(M_PI) * s);
  double t = r0 + lo * dr - d;
  double e = std::exp(-t * t * inv_s2) * norm;
  double m = std::exp(-2.0 * t * dr * inv_s2);
  const double c = std::exp(-dr * dr * inv_s2);
  const double c2 = c * c;
  for (int b = lo; b <= hi; ++b) {
    f(b, e, -2.0 * t * inv_s2 * e);
    e *= m * c;
    m *= c2;
    t += dr;
  }
}

struct Pair {
  size_t i, j;
  double d, ux, uy;
};

}  // namespace

PcfEnergy::PcfEnergy(Domain domain, std::vector<Neighborhood> hoods, PcfParams params)
    : domain_(domain), hoods_(std::move(hoods)), params_(params), rel_(relative_radii(params)) {
  domain_.periodic = true;
  if (params_.bins < 2 || !(params_.r_a > 0) || !(params_.r_b > params_.r_a) || !(params_.sigma_factor > 0))
    throw InputError("pcf2017: impossible PCF parameters");
  if (hoods_.empty()) throw InputError("pcf2017: no neighborhoods");
  const double half = 0.5 * std::min(domain_.width(), domain_.height());
  for (size_t k = 0; k < hoods_.size(); ++k) {
    const Neighborhood& h = hoods_[k];
    if (h.target.size() != rel_.size())
      throw InputError("pcf2017: neighborhood " + std::to_string(k) + " target has " +
                       std::to_string(h.target.size()) + " samples, expected " + std::to_string(rel_.size()));
    if (!(h.lambda > 0) || !(h.norm > 0)) throw InputError("pcf2017: neighborhood intensity must be > 0");
    const double rmax = rmax_for_intensity(h.lambda);
    const double reach = params_.r_b * rmax + params_.kernel_cutoff * params_.sigma_factor * rmax;
    if (reach > half || h.radius > half)
      throw InputError("pcf2017: too few points for the periodic domain (PCF reach " + std::to_string(reach) +
                       " exceeds half the domain); use more points");
  }
}

double PcfEnergy::evaluate(const std::vector<Vec2>& x, std::vector<Vec2>* grad,
                           std::vector<std::vector<double>>* curves) const {
  const size_t n = x.size();
  if (grad) grad->assign(n, Vec2{0, 0});
  if (curves) curves->assign(hoods_.size(), {});
  const double W = domain_.width(), H = domain_.height();
  const int bins = params_.bins;
  const double drel = relative_step(params_);
  // Every unordered pair within the largest reach, once per evaluation (O(N^2) distance
  // tests: negligible next to the kernel sums for the few thousand points this baseline
  // handles).
  double max_reach = 0;
  for (const Neighborhood& h : hoods_) {
    const double rmax = rmax_for_intensity(h.lambda);
    max_reach = std::max(max_reach, rel_.back() * rmax + params_.kernel_cutoff * params_.sigma_factor * rmax);
  }
  // Adjacency: for every i, the ordered pairs (i, j) within max_reach.
  std::vector<std::vector<Pair>> adj(n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      double dx = x[i].x - x[j].x, dy = x[i].y - x[j].y;
      dx -= W * std::round(dx / W);
      dy -= H * std::round(dy / H);
      const double d2 = dx * dx + dy * dy;
      if (d2 > max_reach * max_reach || d2 <= 0) continue;
      const double d = std::sqrt(d2);
      adj[i].push_back({i, j, d, dx / d, dy / d});
      adj[j].push_back({j, i, d, -dx / d, -dy / d});
    }
  double energy = 0;
  std::vector<Pair> pairs;
  std::vector<double> g(bins), coef(bins);
  for (const Neighborhood& h : hoods_) {
    const double rmax = rmax_for_intensity(h.lambda);
    const double s = params_.sigma_factor * rmax, cutoff = params_.kernel_cutoff * s;
    const double r0 = rel_[0] * rmax, dr = drel * rmax;
    const double reach = rel_.back() * rmax + cutoff;
    // Members of N_k, then every ordered pair (i in N_k, j != i) within reach.
    pairs.clear();
    for (size_t i = 0; i < n; ++i) {
      if (h.radius > 0) {
        double dx = x[i].x - h.center.x, dy = x[i].y - h.center.y;
        dx -= W * std::round(dx / W);
        dy -= H * std::round(dy / H);
        if (dx * dx + dy * dy > h.radius * h.radius) continue;
      }
      for (const Pair& p : adj[i])
        if (p.d <= reach) pairs.push_back(p);
    }
    // g_k(r_b) and the error.
    std::fill(g.begin(), g.end(), 0.0);
    for (const Pair& p : pairs)
      for_kernel_bins(p.d, r0, dr, bins, s, cutoff, [&](int b, double k, double) { g[b] += k; });
    double ek = 0;
    for (int b = 0; b < bins; ++b) {
      const double scale = 1.0 / (h.norm * 2 * M_PI * (r0 + b * dr));
      g[b] *= scale;
      const double e = g[b] - h.target[b];
      ek += e * e * drel;
      coef[b] = 2.0 * e * drel * scale;  // dE_k/d(sum of kernels at bin b)
    }
    energy += ek;
    if (curves) (*curves)[&h - hoods_.data()] = g;
    if (!grad) continue;
    for (const Pair& p : pairs) {
      double phi = 0;
      for_kernel_bins(p.d, r0, dr, bins, s, cutoff, [&](int b, double, double kd) { phi -= coef[b] * kd; });
      (*grad)[p.i].x += phi * p.ux;
      (*grad)[p.i].y += phi * p.uy;
      (*grad)[p.j].x -= phi * p.ux;
      (*grad)[p.j].y -= phi * p.uy;
    }
  }
  return energy;
}

}  // namespace ppsynth::pcf2017
