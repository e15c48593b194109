#include "core/generators/lloyd.hpp"

#include <cmath>
#include <random>

#include "core/config/params.hpp"
#include "core/generators/generator.hpp"
#include "core/generators/sampling_util.hpp"
#include "core/generators/uniform.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

double lloyd_step(PointSet& ps, size_t samples, uint64_t seed) {
  const size_t n = ps.size();
  if (n == 0) return 0;
  const Domain d = ps.domain();
  NeighborIndex index(ps.positions(), d, /*periodic=*/true);
  std::mt19937_64 rng(seed);
  std::vector<Vec2> sum(n);
  std::vector<size_t> count(n, 0);
  for (size_t s = 0; s < samples; ++s) {
    Vec2 q = gen_detail::uniform_in(rng, d);
    const size_t i = index.knn(q, 1).front();
    Vec2 dv = gen_detail::torus_delta(ps[i], q, d);
    sum[i].x += dv.x;
    sum[i].y += dv.y;
    ++count[i];
  }
  double moved = 0;
  for (size_t i = 0; i < n; ++i) {
    if (count[i] == 0) continue;  // cell missed by the samples: keep the site
    Vec2 m{sum[i].x / count[i], sum[i].y / count[i]};
    moved += std::hypot(m.x, m.y);
    ps[i] = gen_detail::wrap({ps[i].x + m.x, ps[i].y + m.y}, d);
  }
  return moved / n;
}

PointSet lloyd_points(size_t n, uint64_t seed, Domain d, const LloydOptions& opt) {
  gen_detail::check_domain(d, "lloyd");
  if (opt.iterations < 0) throw config_error("lloyd.iterations", "must be >= 0");
  if (opt.samples_per_point < 1) throw config_error("lloyd.samples_per_point", "must be >= 1");
  PointSet ps = uniform_points(n, seed, d);
  std::mt19937_64 seeds(seed ^ 0x9E3779B97F4A7C15ull);
  for (int it = 0; it < opt.iterations; ++it) lloyd_step(ps, n * opt.samples_per_point, seeds());
  return ps;
}

namespace {
struct LloydGen : PointGenerator {
  LloydOptions opt;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return lloyd_points(n, seed, d, opt);
  }
};
}  // namespace

}  // namespace ppsynth

namespace ppsynth {
const ParamTable<LloydOptions>& LloydOptions::params() {
  using O = LloydOptions;
  static const ParamTable<O> t("generator", {
      param("iterations", &O::iterations, "int [0, 100000]", "Lloyd steps"),
      param("samples_per_point", &O::samples_per_point, "int [1, 100000]", "uniform samples per point that estimate each cell's centroid"),
  });
  return t;
}
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "lloyd", ppsynth::LloydOptions::params(),
                        "toroidal Lloyd relaxation of uniform points (sampled Voronoi cells)",
                        [](const ppsynth::LloydOptions& o, const std::string&) {
                          auto g = std::make_unique<ppsynth::LloydGen>();
                          g->opt = o;
                          return g;
                        })
