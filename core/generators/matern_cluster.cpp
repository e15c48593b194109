#include "core/generators/matern_cluster.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/config/params.hpp"
#include "core/generators/generator.hpp"
#include "core/generators/sampling_util.hpp"

namespace ppsynth {

PointSet matern_cluster_points(size_t n, uint64_t seed, Domain d, const MaternClusterOptions& opt) {
  gen_detail::check_domain(d, "matern_cluster");
  if (!(opt.mean_children > 0) || !std::isfinite(opt.mean_children))
    throw config_error("matern_cluster.mean_children", "must be positive");
  if (!(opt.radius >= 0) || !std::isfinite(opt.radius))
    throw config_error("matern_cluster.radius", "must be >= 0");
  if (!(opt.parent_intensity >= 0) || !std::isfinite(opt.parent_intensity))
    throw config_error("matern_cluster.parent_intensity", "must be >= 0");
  PointSet ps(d);
  if (n == 0) return ps;
  std::mt19937_64 rng(seed);
  const double intensity =
      opt.parent_intensity > 0 ? opt.parent_intensity : n / (opt.mean_children * d.area());
  std::poisson_distribution<long> n_parents(intensity * d.area());
  std::poisson_distribution<long> n_children(opt.mean_children);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Vec2> pts;
  // Realizations until at least n children exist (conditioning on n).
  for (int round = 0; pts.size() < n; ++round) {
    if (round > 10000) throw InputError("matern_cluster: cannot produce n points with these parameters");
    const long parents = std::max(1L, n_parents(rng));
    for (long p = 0; p < parents; ++p) {
      const Vec2 c = gen_detail::uniform_in(rng, d);
      const long k = n_children(rng);
      for (long t = 0; t < k; ++t) {
        const double r = opt.radius * std::sqrt(u01(rng)), a = 2 * M_PI * u01(rng);
        pts.push_back(gen_detail::wrap({c.x + r * std::cos(a), c.y + r * std::sin(a)}, d));
      }
    }
  }
  std::vector<size_t> idx(pts.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::shuffle(idx.begin(), idx.end(), rng);
  ps.reserve(n);
  for (size_t t = 0; t < n; ++t) ps.add(pts[idx[t]]);
  return ps;
}

namespace {
struct MaternGen : PointGenerator {
  MaternClusterOptions opt;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return matern_cluster_points(n, seed, d, opt);
  }
};
}  // namespace

}  // namespace ppsynth

namespace ppsynth {
const ParamTable<MaternClusterOptions>& MaternClusterOptions::params() {
  using O = MaternClusterOptions;
  static const ParamTable<O> t("generator", {
      param("parent_intensity", &O::parent_intensity, "[0, inf)", "parents per unit area (0: n / mean_children over the area)"),
      param("mean_children", &O::mean_children, "(0, inf)", "the mean number of points per parent"),
      param("radius", &O::radius, "(0, 0.5]", "the radius of a parent's disk, in domain units"),
  });
  return t;
}
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "matern_cluster", ppsynth::MaternClusterOptions::params(),
                        "Matern cluster process conditioned on n points (parent_intensity 0 = n / mean_children)",
                        [](const ppsynth::MaternClusterOptions& o, const std::string&) {
                          auto g = std::make_unique<ppsynth::MaternGen>();
                          g->opt = o;
                          return g;
                        })
