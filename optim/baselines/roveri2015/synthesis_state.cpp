#include "optim/baselines/roveri2015/synthesis_state.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth::roveri2015 {

SynthesisState::SynthesisState(FunctionalSet exemplar, const Domain& exemplar_domain, FunctionalSet output,
                               const Domain& output_domain, bool periodic_output)
    : ex(std::move(exemplar)), ex_domain(exemplar_domain), match_box(exemplar_domain), out(std::move(output)),
      out_domain(output_domain), periodic(periodic_output) {
  ex_domain.periodic = false;
  out_domain.periodic = periodic;
  ex_index_ = std::make_unique<NeighborIndex>(ex.x);
  rebuild_output_index();
}

void SynthesisState::set_window(const KernelParams& params, double match_margin) {
  kp = params;
  const double mx = std::min(match_margin * kp.delta, 0.5 * ex_domain.width());
  const double my = std::min(match_margin * kp.delta, 0.5 * ex_domain.height());
  match_box = {ex_domain.x0 + mx, ex_domain.y0 + my, ex_domain.x1 - mx, ex_domain.y1 - my, false};
}

void SynthesisState::set_quadrature(double spacing) {
  const int nx = std::max(1, int(std::ceil(out_domain.width() / spacing - 1e-9)));
  const int ny = std::max(1, int(std::ceil(out_domain.height() / spacing - 1e-9)));
  quad.clear();
  quad_nx = nx;
  quad_ny = ny;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      quad.push_back({out_domain.x0 + (i + 0.5) * out_domain.width() / nx,
                      out_domain.y0 + (j + 0.5) * out_domain.height() / ny});
  match.assign(quad.size(), Vec2{0.5 * (ex_domain.x0 + ex_domain.x1), 0.5 * (ex_domain.y0 + ex_domain.y1)});
  ex_nb.assign(quad.size(), Neighborhood{});
  ex_term.assign(quad.size(), 0.0);
  quad_index_ = std::make_unique<NeighborIndex>(quad, out_domain, periodic);
}

void SynthesisState::rebuild_output_index() {
  out_index_ = std::make_unique<NeighborIndex>(out.x, out_domain, periodic);
}

void SynthesisState::gather_output(Vec2 q, Neighborhood& nb, size_t skip, const Vec2* m) const {
  nb.clear();
  if (out.size() == 0) return;
  for (size_t i : out_index_->radius(q, kp.radius())) {
    if (i == skip) continue;
    const Vec2 u = relative(q, out.x[i], out_domain, periodic);
    if (m && !ex_domain.contains({m->x + u.x, m->y + u.y}, 0)) continue;
    nb.push(u, out.attr(i), i);
  }
}

void SynthesisState::gather_exemplar(Vec2 m, Neighborhood& nb, const Vec2* q) const {
  nb.clear();
  for (size_t j : ex_index_->radius(m, kp.radius())) {
    const Vec2 v{ex.x[j].x - m.x, ex.x[j].y - m.y};
    if (q && !periodic && !out_domain.contains({q->x + v.x, q->y + v.y}, 0)) continue;
    nb.push(v, ex.attr(j), j);
  }
}

std::vector<size_t> SynthesisState::quad_neighbors(size_t k) const {
  std::vector<size_t> r;
  const int i = int(k) % quad_nx, j = int(k) / quad_nx;
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  for (int t = 0; t < 4; ++t) {
    int a = i + di[t], b = j + dj[t];
    if (periodic) {
      a = (a + quad_nx) % quad_nx;
      b = (b + quad_ny) % quad_ny;
    } else if (a < 0 || a >= quad_nx || b < 0 || b >= quad_ny) {
      continue;
    }
    if (size_t(b * quad_nx + a) != k) r.push_back(size_t(b * quad_nx + a));
  }
  return r;
}

std::vector<size_t> SynthesisState::quads_near(Vec2 p) const { return quad_index_->radius(p, kp.radius()); }

Vec2 SynthesisState::confine(Vec2 p) const {
  const Domain& d = out_domain;
  if (periodic) {
    p.x = d.x0 + std::fmod(std::fmod(p.x - d.x0, d.width()) + d.width(), d.width());
    p.y = d.y0 + std::fmod(std::fmod(p.y - d.y0, d.height()) + d.height(), d.height());
    return p;
  }
  return {std::clamp(p.x, d.x0, d.x1), std::clamp(p.y, d.y0, d.y1)};
}

Vec2 SynthesisState::confine_match(Vec2 m) const {
  return {std::clamp(m.x, match_box.x0, match_box.x1), std::clamp(m.y, match_box.y0, match_box.y1)};
}

}  // namespace ppsynth::roveri2015
