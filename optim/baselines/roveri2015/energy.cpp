#include "optim/baselines/roveri2015/energy.hpp"

#include <cmath>

namespace ppsynth::roveri2015 {

double output_energy(const SynthesisState& st, std::vector<Vec2>* grad_x, std::vector<double>* grad_a) {
  const int D = st.out.D;
  if (grad_x) grad_x->assign(st.out.size(), Vec2{0, 0});
  if (grad_a) grad_a->assign(st.out.size() * size_t(D), 0.0);
  Neighborhood nb;
  std::vector<Vec2> du;
  std::vector<double> da;
  SimilarityGrad g;
  if (grad_x) g.d_out = &du;
  if (grad_a) g.d_attr = &da;
  double T = 0;
  for (size_t k = 0; k < st.quad.size(); ++k) {
    st.gather_pair(k, nb);
    T += similarity(nb, st.ex_nb[k], D, st.kp, {true, false}, g);
    for (size_t i = 0; i < nb.size(); ++i) {
      if (grad_x) {
        (*grad_x)[nb.index[i]].x += du[i].x;
        (*grad_x)[nb.index[i]].y += du[i].y;
      }
      if (grad_a)
        for (int d = 0; d < D; ++d) (*grad_a)[nb.index[i] * D + d] += da[i * D + d];
    }
  }
  return T;
}

double total_energy(const SynthesisState& st) {
  double T = output_energy(st);
  for (double b : st.ex_term) T += b;
  return T;
}

double local_energy(const SynthesisState& st, const std::vector<size_t>& quads, size_t skip, const ExtraPoint* extra,
                    Vec2* d_extra) {
  const int D = st.out.D;
  const double R = st.kp.radius();
  Neighborhood nb;
  std::vector<Vec2> du;
  SimilarityGrad g;
  if (d_extra) {
    g.d_out = &du;
    *d_extra = {0, 0};
  }
  double T = 0;
  for (size_t k : quads) {
    st.gather_pair(k, nb, skip);
    bool has_extra = false;
    if (extra) {
      const Vec2 r = relative(st.quad[k], extra->x, st.out_domain, st.periodic);
      const Vec2 im{st.match[k].x + r.x, st.match[k].y + r.y};
      if (r.x * r.x + r.y * r.y <= R * R && st.ex_domain.contains(im, 0)) {
        nb.push(r, extra->a, SynthesisState::npos);
        has_extra = true;
      }
    }
    T += similarity(nb, st.ex_nb[k], D, st.kp, {true, false}, g);
    if (d_extra && has_extra) {
      d_extra->x += du.back().x;
      d_extra->y += du.back().y;
    }
  }
  return T;
}

}  // namespace ppsynth::roveri2015
