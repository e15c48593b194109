// Thesis Chapter 3 (roveri2015): gradients of Eq. 3.5 / A.6 and Eq. 3.6 against central finite
// differences (double precision), zero self-distance of the similarity, matching with
// restarts, sampling control (hole filled, duplicate removed), and a lattice expansion.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "core/metrics/nearest_neighbor.hpp"
#include "core/metrics/quadrant.hpp"
#include "core/generators/uniform.hpp"
#include "optim/baselines/roveri2015/energy.hpp"
#include "optim/baselines/roveri2015/functional.hpp"
#include "optim/baselines/roveri2015/matching.hpp"
#include "optim/baselines/roveri2015/patch_init.hpp"
#include "optim/baselines/roveri2015/sampling_control.hpp"
#include "optim/baselines/roveri2015/similarity.hpp"
#include "optim/baselines/roveri2015/solver.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;
using namespace ppsynth::roveri2015;

namespace {

// Random neighborhood: n points in [-r, r]^2 with D random channels (owned by `store`).
Neighborhood random_nb(size_t n, int D, double r, std::mt19937_64& rng, std::vector<std::vector<double>>& store) {
  std::uniform_real_distribution<double> U(-r, r), A(-1.0, 1.0);
  Neighborhood nb;
  for (size_t i = 0; i < n; ++i) {
    store.emplace_back(size_t(D));
    for (double& v : store.back()) v = A(rng);
  }
  const size_t first = store.size() - n;
  for (size_t i = 0; i < n; ++i) nb.push({U(rng), U(rng)}, store[first + i].data(), i);
  return nb;
}

KernelParams kernel(WindowKind w) {
  KernelParams kp;
  kp.sigma = 0.3;
  kp.delta = 0.5;
  kp.window = w;
  kp.window_cutoff = 1e3;  // no truncation: the functions are smooth for the FD checks
  kp.pair_cutoff = 1e3;
  return kp;
}

double rel_err(double a, double b) { return std::abs(a - b) / std::max(1e-8, std::max(std::abs(a), std::abs(b))); }

PointSet grid_exemplar(int n, double jitter, uint64_t seed) {
  PointSet ps(Domain{0, 0, 1, 1, false});
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> J(-jitter, jitter);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) ps.add({(i + 0.5 + J(rng)) / n, (j + 0.5 + J(rng)) / n});
  return ps;
}

// Output = a copy of the exemplar's points on the same domain, every q_k matched to itself.
SynthesisState identity_state(const PointSet& ex, const PointSet& out, double delta_factor) {
  const ChannelEncoder enc(ex, 0.5);
  SynthesisState st(encode_points(ex, enc), ex.domain(), encode_points(out, enc), ex.domain(), false);
  const double dnn = mean_nn_distance(ex);
  KernelParams kp;
  kp.sigma = dnn;
  kp.delta = delta_factor * dnn;
  st.set_window(kp, 0.0);
  st.set_quadrature(dnn);
  for (size_t k = 0; k < st.quad.size(); ++k) {
    st.match[k] = st.quad[k];
    st.gather_exemplar(st.match[k], st.ex_nb[k], &st.quad[k]);
    st.ex_term[k] = similarity(Neighborhood{}, st.ex_nb[k], st.ex.D, st.kp, {false, true});
  }
  return st;
}

size_t nearest_quad(const SynthesisState& st, Vec2 p) {
  size_t best = 0;
  for (size_t k = 1; k < st.quad.size(); ++k)
    if (std::hypot(st.quad[k].x - p.x, st.quad[k].y - p.y) < std::hypot(st.quad[best].x - p.x, st.quad[best].y - p.y))
      best = k;
  return best;
}

}  // namespace

TEST_CASE("roveri2015: similarity gradients match finite differences", "[roveri2015]") {
  for (WindowKind w : {WindowKind::Box, WindowKind::Gaussian}) {
    CAPTURE(int(w));
    std::mt19937_64 rng(11);
    std::vector<std::vector<double>> store;
    store.reserve(64);
    const int D = 3;
    Neighborhood out = random_nb(7, D, 0.6, rng, store);
    const Neighborhood ex = random_nb(6, D, 0.6, rng, store);
    const KernelParams kp = kernel(w);
    std::vector<Vec2> du, dv;
    std::vector<double> da;
    const double S = similarity(out, ex, D, kp, {}, {&du, &dv, &da});
    REQUIRE(S > 0);
    const double h = 1e-6;
    for (size_t i = 0; i < out.size(); ++i) {
      for (int c = 0; c < 2; ++c) {
        Neighborhood p = out, m = out;
        (c ? p.rel[i].y : p.rel[i].x) += h;
        (c ? m.rel[i].y : m.rel[i].x) -= h;
        const double fd = (similarity(p, ex, D, kp) - similarity(m, ex, D, kp)) / (2 * h);
        CHECK(rel_err(fd, c ? du[i].y : du[i].x) < 1e-6);
      }
      for (int d = 0; d < D; ++d) {
        const double saved = store[i][d];
        // S is quadratic in the channels: a central difference is exact for any step, so a
        // large one keeps round-off (~eps S / h) out of the comparison.
        const double ha = 1e-3;
        store[i][d] = saved + ha;
        const double sp = similarity(out, ex, D, kp);
        store[i][d] = saved - ha;
        const double sm = similarity(out, ex, D, kp);
        store[i][d] = saved;
        CHECK(rel_err((sp - sm) / (2 * ha), da[i * D + d]) < 1e-6);
      }
    }
    // dS/dm: moving m by +h moves every v_j = e_j - m by -h.
    const Vec2 gm = match_gradient(dv);
    for (int c = 0; c < 2; ++c) {
      Neighborhood p = ex, m = ex;
      for (size_t j = 0; j < ex.size(); ++j) {
        (c ? p.rel[j].y : p.rel[j].x) -= h;
        (c ? m.rel[j].y : m.rel[j].x) += h;
      }
      const double fd = (similarity(out, p, D, kp) - similarity(out, m, D, kp)) / (2 * h);
      CHECK(rel_err(fd, c ? gm.y : gm.x) < 1e-6);
    }
  }
}

TEST_CASE("roveri2015: Gaussian-window closed form equals numerical integration of Eq. 3.2", "[roveri2015]") {
  // Checks the derivation of Eq. A.6: S = (1/c) Int |f(q+s) - e(m+s)|^2 exp(-|s|^2/delta^2) ds.
  std::mt19937_64 rng(5);
  std::vector<std::vector<double>> store;
  store.reserve(16);
  const Neighborhood out = random_nb(4, 2, 0.5, rng, store);
  const Neighborhood ex = random_nb(3, 2, 0.5, rng, store);
  const KernelParams kp = kernel(WindowKind::Gaussian);
  const double s2 = kp.sigma * kp.sigma, d2 = kp.delta * kp.delta;
  const double c = M_PI * s2 * d2 / (s2 + 2 * d2);
  double integral = 0;
  const double L = 3.0, ds = 0.01;
  for (double x = -L; x <= L; x += ds)
    for (double y = -L; y <= L; y += ds) {
      double diff2 = 0;
      for (int d = 0; d < 2; ++d) {
        double f = 0, e = 0;
        for (size_t i = 0; i < out.size(); ++i) f += out.a[i][d] * std::exp(-(std::pow(x - out.rel[i].x, 2) + std::pow(y - out.rel[i].y, 2)) / s2);
        for (size_t j = 0; j < ex.size(); ++j) e += ex.a[j][d] * std::exp(-(std::pow(x - ex.rel[j].x, 2) + std::pow(y - ex.rel[j].y, 2)) / s2);
        diff2 += (f - e) * (f - e);
      }
      integral += diff2 * std::exp(-(x * x + y * y) / d2) * ds * ds;
    }
  CHECK(rel_err(integral / c, similarity(out, ex, 2, kp)) < 1e-4);
}

TEST_CASE("roveri2015: a neighborhood is at zero distance from itself", "[roveri2015]") {
  std::mt19937_64 rng(3);
  std::vector<std::vector<double>> store;
  store.reserve(16);
  for (WindowKind w : {WindowKind::Box, WindowKind::Gaussian}) {
    const Neighborhood nb = random_nb(9, 2, 0.8, rng, store);
    const KernelParams kp = kernel(w);
    CHECK(std::abs(similarity(nb, nb, 2, kp)) < 1e-12);
    Neighborhood moved = nb;
    moved.rel[0].x += 0.1;
    CHECK(similarity(moved, nb, 2, kp) > 1e-4);
    Neighborhood fewer = nb;
    fewer.rel.pop_back();
    fewer.a.pop_back();
    fewer.index.pop_back();
    CHECK(similarity(fewer, nb, 2, kp) > 1e-4);
    // Sampling error: zero for identical windows, -1 with one point missing (box counts).
    CHECK(std::abs(sampling_error(nb, nb, kp)) < 1e-12);
    CHECK(sampling_error(fewer, nb, kp) < 0);
  }
}

TEST_CASE("roveri2015: total energy and local energy gradients match finite differences", "[roveri2015]") {
  const PointSet ex = uniform_points(12, 21);
  const PointSet out = uniform_points(10, 22);
  const ChannelEncoder enc(ex, 0.5);
  SynthesisState st(encode_points(ex, enc), ex.domain(), encode_points(out, enc), ex.domain(), false);
  KernelParams kp;
  kp.sigma = 0.15;
  kp.delta = 0.3;
  kp.window_cutoff = 100;  // every point in every window: T is smooth
  kp.pair_cutoff = 100;
  st.set_window(kp, 0.0);
  st.set_quadrature(0.25);
  MatchOptions mo;
  mo.aligned_starts = 0;  // matches only need to exist here; keep every image off the mask borders
  match_all(st, mo, 1);
  std::vector<Vec2> g;
  output_energy(st, &g);
  const double h = 1e-6;
  for (size_t i = 0; i < st.out.size(); ++i)
    for (int c = 0; c < 2; ++c) {
      const Vec2 saved = st.out.x[i];
      (c ? st.out.x[i].y : st.out.x[i].x) += h;
      st.rebuild_output_index();
      const double ep = output_energy(st);
      st.out.x[i] = saved;
      (c ? st.out.x[i].y : st.out.x[i].x) -= h;
      st.rebuild_output_index();
      const double em = output_energy(st);
      st.out.x[i] = saved;
      st.rebuild_output_index();
      CHECK(rel_err((ep - em) / (2 * h), c ? g[i].y : g[i].x) < 1e-6);
    }
  // Matching gradient through match_energy (exemplar neighborhood regathered at m).
  // (Masks are active but no image crosses a domain border under a 1e-6 move.)
  Neighborhood nb;
  st.gather_output(st.quad[3], nb);
  Vec2 gm;
  const Vec2 m{0.47, 0.52};
  match_energy(st, 3, nb, m, &gm);
  CHECK(rel_err((match_energy(st, 3, nb, {m.x + h, m.y}) - match_energy(st, 3, nb, {m.x - h, m.y})) / (2 * h), gm.x) < 1e-6);
  CHECK(rel_err((match_energy(st, 3, nb, {m.x, m.y + h}) - match_energy(st, 3, nb, {m.x, m.y - h})) / (2 * h), gm.y) < 1e-6);
  // Gradient with respect to a candidate point (sampling control's local optimization).
  std::vector<double> ch(size_t(st.out.D), 1.0);
  const std::vector<size_t> qs = st.quads_near({0.5, 0.5});
  const ExtraPoint e{{0.41, 0.63}, ch.data()};
  Vec2 ge;
  local_energy(st, qs, SynthesisState::npos, &e, &ge);
  const ExtraPoint ep{{0.41 + h, 0.63}, ch.data()}, em{{0.41 - h, 0.63}, ch.data()};
  CHECK(rel_err((local_energy(st, qs, SynthesisState::npos, &ep) - local_energy(st, qs, SynthesisState::npos, &em)) / (2 * h), ge.x) < 1e-6);
}

TEST_CASE("roveri2015: matching with restarts finds the true location", "[roveri2015]") {
  // Output = exemplar (white noise: a unique best match); every interior q_k must match to
  // itself with S ~ 0, from random starts only (no warm start at the answer).
  const PointSet ex = uniform_points(150, 9);
  const ChannelEncoder enc(ex, 0.5);
  SynthesisState st(encode_points(ex, enc), ex.domain(), encode_points(ex, enc), ex.domain(), false);
  const double dnn = mean_nn_distance(ex);
  KernelParams kp;
  kp.sigma = dnn;
  kp.delta = 1.5 * dnn;
  st.set_window(kp, 1.0);
  st.set_quadrature(0.2);
  MatchOptions mo;
  mo.coherent = false;
  mo.restarts = 12;
  mo.iterations = 40;
  int interior = 0, found = 0;
  for (size_t k = 0; k < st.quad.size(); ++k) {
    const Vec2 q = st.quad[k];
    if (q.x < st.match_box.x0 || q.x > st.match_box.x1 || q.y < st.match_box.y0 || q.y > st.match_box.y1) continue;
    ++interior;
    st.match[k] = {0.5 * (st.match_box.x0 + st.match_box.x1), st.match_box.y0};  // a poor warm start
    match_point(st, k, mo, 100 + k);
    found += std::hypot(st.match[k].x - q.x, st.match[k].y - q.y) < 0.05 * dnn;
  }
  REQUIRE(interior >= 4);
  CHECK(found >= interior - 1);  // measured: all of them
}

TEST_CASE("roveri2015: sampling control fills a hole and removes a duplicate", "[roveri2015]") {
  const PointSet ex = grid_exemplar(8, 0.1, 4);
  const double dnn = mean_nn_distance(ex);
  const size_t hole = 3 * 8 + 4;  // an interior point
  std::vector<size_t> keep;
  for (size_t i = 0; i < ex.size(); ++i)
    if (i != hole) keep.push_back(i);
  {
    SynthesisState st = identity_state(ex, ex.subset(keep), 2.0);
    const size_t k = nearest_quad(st, ex[hole]);
    Neighborhood nb;
    st.gather_pair(k, nb);
    REQUIRE(sampling_error(nb, st.ex_nb[k], st.kp) < 0);
    SamplingOptions so;
    REQUIRE(try_add_point(st, k, so, 1));
    REQUIRE(st.out.size() == ex.size());
    const Vec2 added = st.out.x.back();
    CHECK(std::hypot(added.x - ex[hole].x, added.y - ex[hole].y) < 0.1 * dnn);
    // Nothing more to add or remove: a full round leaves the count unchanged.
    const SamplingResult r = sampling_control(st, so, 2);
    CHECK(r.added == 0);
    CHECK(r.removed == 0);
  }
  {
    PointSet dup = ex;
    dup.add({ex[hole].x + 0.02 * dnn, ex[hole].y}, 0);
    SynthesisState st = identity_state(ex, dup, 2.0);
    SamplingOptions so;
    const SamplingResult r = sampling_control(st, so, 3);
    CHECK(r.removed == 1);
    CHECK(r.added == 0);
    REQUIRE(st.out.size() == ex.size());
    // The remaining point at the duplicated location is one of the pair.
    size_t near = 0;
    for (const Vec2& p : st.out.x) near += std::hypot(p.x - ex[hole].x, p.y - ex[hole].y) < 0.05 * dnn;
    CHECK(near == 1);
  }
}

TEST_CASE("roveri2015: random patch copy keeps the density", "[roveri2015]") {
  const PointSet ex = grid_exemplar(6, 0.0, 1);
  const PointSet init = random_patch_copy(ex, Domain{0, 0, 2, 2, false}, 0.5, 7);
  CHECK(init.size() == 4 * ex.size());  // a lattice: every half-open window holds 9 points
  CHECK(window_schedule(1.0, 0.9, 0.5).size() == 7);
}

TEST_CASE("roveri2015: expanding a 6x6 lattice gives a lattice", "[roveri2015]") {
  const PointSet ex = grid_exemplar(6, 0.0, 1);
  auto method = MethodRegistry::instance().create({{"type", "roveri2015"}}, "method");
  SynthesisContext ctx;
  ctx.output.upscale = 2;
  ctx.seed = 95;
  nlohmann::json stats;
  ctx.stats = &stats;
  // From white noise (not the lattice-friendly patch copy), so the method has to build the lattice.
  const PointSet init = uniform_points(144, 33);
  ctx.initialization = &init;
  const PointSet out = method->synthesize(ex, ctx);
  const PatchMetrics m0 = quadrant_metrics(ex, init);
  const PatchMetrics m = quadrant_metrics(ex, out);
  const double rho = relative_radius(out), rho0 = relative_radius(init);
  WARN("lattice: points " << out.size() << ", relative radius " << rho0 << " -> " << rho << ", PCF MSE " << m0.pcf_mse
                          << " -> " << m.pcf_mse << ", " << stats["seconds"].get<double>() << " s");
  CHECK(std::abs(double(out.size()) - 144.0) <= 8);
  // Measured (seed 95): rho 0.09 -> 0.38, PCF MSE 0.70 -> 0.11; a perfect square lattice has
  // rho ~0.93, so lattice defects remain (docs/explanation/roveri2015.md). The check: no near-coincident
  // pairs are left and the spacing became regular enough to quadruple rho.
  CHECK(rho > 0.3);
  CHECK(rho > 3 * rho0);
  CHECK(m.pcf_mse < 0.5 * m0.pcf_mse);
}
