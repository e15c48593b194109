#include "optim/baselines/roveri2015/sampling_control.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "optim/baselines/roveri2015/energy.hpp"

namespace ppsynth::roveri2015 {

namespace {

// Sum over `pts` of g(p - r, sigma) (the a = 1 density of Eq. 3.4 at p, relative coordinates).
double density(Vec2 p, const std::vector<Vec2>& pts, double sigma) {
  double s = 0;
  const double inv = 1.0 / (sigma * sigma);
  for (const Vec2& r : pts) s += std::exp(-((p.x - r.x) * (p.x - r.x) + (p.y - r.y) * (p.y - r.y)) * inv);
  return s;
}

// Energy change of having `extra` in the output, over the quadrature points near it.
double add_delta(const SynthesisState& st, const ExtraPoint& extra, Vec2* grad) {
  const std::vector<size_t> qs = st.quads_near(extra.x);
  const double with = local_energy(st, qs, SynthesisState::npos, &extra, grad);
  const double without = local_energy(st, qs);
  return with - without;
}

}  // namespace

bool try_add_point(SynthesisState& st, size_t k, const SamplingOptions& opt, uint64_t seed) {
  const Neighborhood& ex = st.ex_nb[k];
  if (ex.size() == 0) return false;
  Neighborhood out;
  st.gather_pair(k, out);
  const double sigma = st.kp.sigma;
  // Proposal: the exemplar point with the largest deficit whose image lies in the output.
  size_t best = SynthesisState::npos;
  double best_deficit = -1e300;
  for (size_t j = 0; j < ex.size(); ++j) {
    const Vec2 p{st.quad[k].x + ex.rel[j].x, st.quad[k].y + ex.rel[j].y};
    if (!st.periodic && !st.out_domain.contains(p, 0)) continue;
    const double d = density(ex.rel[j], ex.rel, sigma) - density(ex.rel[j], out.rel, sigma);
    if (d > best_deficit) {
      best_deficit = d;
      best = j;
    }
  }
  if (best == SynthesisState::npos) return false;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> jitter(0.0, 0.05 * sigma);
  std::vector<double> ch(ex.a[best], ex.a[best] + st.out.D);
  ExtraPoint cand{st.confine({st.quad[k].x + ex.rel[best].x + jitter(rng), st.quad[k].y + ex.rel[best].y + jitter(rng)}),
                  ch.data()};
  Vec2 g;
  double delta = add_delta(st, cand, &g);
  double step = 0.25 * sigma;
  for (int it = 0; it < opt.candidate_iterations && step > 1e-3 * sigma; ++it) {
    const double n = std::hypot(g.x, g.y);
    if (!(n > 0)) break;
    ExtraPoint trial{st.confine({cand.x.x - step * g.x / n, cand.x.y - step * g.y / n}), ch.data()};
    Vec2 gt;
    const double dt = add_delta(st, trial, &gt);
    if (dt < delta) {
      cand = trial;
      delta = dt;
      g = gt;
    } else {
      step *= 0.5;
    }
  }
  if (!(delta < 0)) return false;
  st.out.add(cand.x, ch.data());
  st.rebuild_output_index();
  return true;
}

bool try_remove_point(SynthesisState& st, size_t k, const SamplingOptions& opt) {
  Neighborhood out;
  st.gather_pair(k, out);
  if (out.size() == 0) return false;
  const Neighborhood& ex = st.ex_nb[k];
  size_t best = 0;
  double best_surplus = -1e300;
  for (size_t i = 0; i < out.size(); ++i) {
    const double s = density(out.rel[i], out.rel, st.kp.sigma) - density(out.rel[i], ex.rel, st.kp.sigma);
    if (s > best_surplus) {
      best_surplus = s;
      best = i;
    }
  }
  const size_t idx = out.index[best];
  const std::vector<size_t> qs = st.quads_near(st.out.x[idx]);
  const double delta = local_energy(st, qs, idx) - local_energy(st, qs);
  if (!(delta < 0)) return false;
  st.out.erase(idx);
  st.rebuild_output_index();
  return true;
}

SamplingResult sampling_control(SynthesisState& st, const SamplingOptions& opt, uint64_t seed) {
  SamplingResult res;
  std::vector<std::pair<double, size_t>> order;
  Neighborhood out;
  for (size_t k = 0; k < st.quad.size(); ++k) {
    st.gather_pair(k, out);
    const double P = sampling_error(out, st.ex_nb[k], st.kp);
    if (std::abs(P) > opt.epsilon) order.push_back({-std::abs(P), k});
  }
  std::sort(order.begin(), order.end());
  const size_t limit = size_t(std::ceil(opt.max_fraction * double(st.quad.size())));
  if (order.size() > limit) order.resize(limit);
  std::mt19937_64 seeder(seed);
  for (const auto& [negP, k] : order) {
    st.gather_pair(k, out);
    const double P = sampling_error(out, st.ex_nb[k], st.kp);
    const uint64_t s = seeder();
    if (P < -opt.epsilon) {
      ++res.tried_add;
      res.added += try_add_point(st, k, opt, s);
    } else if (P > opt.epsilon) {
      ++res.tried_remove;
      res.removed += try_remove_point(st, k, opt);
    }
  }
  return res;
}

}  // namespace ppsynth::roveri2015
