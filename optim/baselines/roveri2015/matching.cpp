#include "optim/baselines/roveri2015/matching.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace ppsynth::roveri2015 {

double match_energy(const SynthesisState& st, size_t k, const Neighborhood& out_nb, Vec2 m, Vec2* d_m,
                    bool with_out_out) {
  Neighborhood out, ex;
  for (size_t i = 0; i < out_nb.size(); ++i)
    if (st.ex_domain.contains({m.x + out_nb.rel[i].x, m.y + out_nb.rel[i].y}, 0))
      out.push(out_nb.rel[i], out_nb.a[i], out_nb.index[i]);
  st.gather_exemplar(m, ex, &st.quad[k]);
  std::vector<Vec2> dv;
  SimilarityGrad g;
  if (d_m) g.d_ex = &dv;
  const double S = similarity(out, ex, st.ex.D, st.kp, {with_out_out, true}, g);
  if (d_m) *d_m = match_gradient(dv);
  return S;
}

namespace {

// Normalized gradient descent from m0; returns the best energy and sets `m`.
double descend(const SynthesisState& st, size_t k, const Neighborhood& out_nb, Vec2 m0, const MatchOptions& opt, Vec2& m) {
  m = st.confine_match(m0);
  Vec2 g;
  double S = match_energy(st, k, out_nb, m, &g);
  const double max_step = opt.step * st.kp.sigma;
  double step = max_step;
  for (int it = 0; it < opt.iterations && step > 1e-4 * st.kp.sigma; ++it) {
    const double n = std::hypot(g.x, g.y);
    if (!(n > 0)) break;
    const Vec2 trial = st.confine_match({m.x - step * g.x / n, m.y - step * g.y / n});
    Vec2 gt;
    const double St = match_energy(st, k, out_nb, trial, &gt);
    if (St < S) {
      m = trial;
      S = St;
      g = gt;
      step = std::min(2.0 * step, max_step);
    } else {
      step *= 0.5;
    }
  }
  return S;
}

}  // namespace

double match_point(SynthesisState& st, size_t k, const MatchOptions& opt, uint64_t seed) {
  Neighborhood out_nb;
  st.gather_output(st.quad[k], out_nb);
  std::vector<Vec2> starts{st.match[k]};
  if (opt.coherent) {
    for (size_t j : st.quad_neighbors(k)) {
      const Vec2 d = relative(st.quad[j], st.quad[k], st.out_domain, st.periodic);
      starts.push_back({st.match[j].x + d.x, st.match[j].y + d.y});
    }
  }
  if (opt.aligned_starts > 0 && out_nb.size() > 0) {
    // Point-aligned candidates: put the output point nearest q_k onto each exemplar point
    // (m = e_j - u_nearest) and keep the best few by S as descent starts. The true match
    // of a neighborhood always aligns some point with some exemplar point, so this finds
    // basins that random starts (area ~ sigma^2 each) almost never hit.
    size_t near = 0;
    for (size_t i = 1; i < out_nb.size(); ++i)
      if (std::hypot(out_nb.rel[i].x, out_nb.rel[i].y) < std::hypot(out_nb.rel[near].x, out_nb.rel[near].y)) near = i;
    std::vector<std::pair<double, Vec2>> cand;
    cand.reserve(st.ex.size());
    for (const Vec2& e : st.ex.x) {
      const Vec2 m = st.confine_match({e.x - out_nb.rel[near].x, e.y - out_nb.rel[near].y});
      cand.push_back({match_energy(st, k, out_nb, m), m});
    }
    const size_t keep = std::min<size_t>(size_t(opt.aligned_starts), cand.size());
    std::partial_sort(cand.begin(), cand.begin() + long(keep), cand.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t i = 0; i < keep; ++i) starts.push_back(cand[i].second);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(st.match_box.x0, st.match_box.x1), uy(st.match_box.y0, st.match_box.y1);
  for (int r = 0; r < opt.restarts; ++r) starts.push_back({ux(rng), uy(rng)});

  double best = 0;
  Vec2 best_m = st.match[k];
  bool first = true;
  for (const Vec2& s : starts) {
    Vec2 m;
    const double S = descend(st, k, out_nb, s, opt, m);
    if (first || S < best) {
      best = S;
      best_m = m;
      first = false;
    }
  }
  st.match[k] = best_m;
  st.gather_exemplar(best_m, st.ex_nb[k], &st.quad[k]);
  st.ex_term[k] = similarity(Neighborhood{}, st.ex_nb[k], st.ex.D, st.kp, {false, true});
  return best;
}

double match_all(SynthesisState& st, const MatchOptions& opt, uint64_t seed) {
  std::mt19937_64 seeder(seed);
  double T = 0;
  for (size_t k = 0; k < st.quad.size(); ++k) T += match_point(st, k, opt, seeder());
  return T;
}

}  // namespace ppsynth::roveri2015
