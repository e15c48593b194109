#include "core/generators/poisson_disk.hpp"

#include <cmath>
#include <random>

#include "core/generators/dynamic_grid.hpp"
#include "core/config/params.hpp"
#include "core/generators/generator.hpp"
#include "core/log.hpp"
#include "core/metrics/nearest_neighbor.hpp"

namespace ppsynth {

PointSet poisson_disk_points(size_t n, uint64_t seed, Domain d, const PoissonDiskOptions& opt) {
  gen_detail::check_domain(d, "poisson_disk");
  double r = opt.radius;
  if (r <= 0) {
    if (!(opt.relative_radius > 0) || opt.relative_radius >= 1)
      throw config_error("poisson_disk.relative_radius", "must be in (0, 1)");
    r = n > 0 ? opt.relative_radius * 2 * packing_radius(n, d.area()) : 0;
  }
  // r is the minimum distance d_min; relative radius = (d_min / 2) / r_max.
  if (!std::isfinite(r)) throw config_error("poisson_disk.radius", "must be finite");
  if (opt.max_attempts < 1) throw config_error("poisson_disk.max_attempts", "must be positive");
  std::mt19937_64 rng(seed);
  PointSet ps(d);
  ps.reserve(n);
  gen_detail::DynamicGrid grid(d, std::max(r, 1e-9 * d.width()), d.periodic);
  size_t fails = 0;
  while (grid.size() < n && fails < static_cast<size_t>(opt.max_attempts)) {
    Vec2 c = gen_detail::uniform_in(rng, d);
    if (r > 0 && grid.nearest_within(c, r) < r) {
      ++fails;
      continue;
    }
    fails = 0;
    grid.insert(c);
    ps.add(c);
  }
  if (ps.size() < n) {
    std::string msg = "poisson_disk: placed only " + std::to_string(ps.size()) + " of " +
                      std::to_string(n) + " points with radius " + std::to_string(r) + " after " +
                      std::to_string(opt.max_attempts) + " consecutive rejections";
    if (opt.require_all) throw InputError(msg);
    spdlog::warn(msg);
  }
  return ps;
}

namespace {
struct PoissonDiskGen : PointGenerator {
  PoissonDiskOptions opt;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return poisson_disk_points(n, seed, d, opt);
  }
};
}  // namespace

}  // namespace ppsynth

namespace ppsynth {
const ParamTable<PoissonDiskOptions>& PoissonDiskOptions::params() {
  using O = PoissonDiskOptions;
  static const ParamTable<O> t("generator", {
      param("radius", &O::radius, "[0, 0.5]", "the minimum distance, in domain units (0: from relative_radius)"),
      param("relative_radius", &O::relative_radius, "[0, 1]", "the minimum distance as a fraction of 2 r_max (when radius is 0)"),
      param("max_attempts", &O::max_attempts, "int [1, 1000000000]", "rejected candidates in a row before it gives up"),
      param("require_all", &O::require_all, "", "fewer than n points is an error (else a warning)"),
  });
  return t;
}
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "poisson_disk", ppsynth::PoissonDiskOptions::params(),
                        "dart-throwing Poisson disk (minimum distance `radius`, or relative_radius * 2 r_max when radius = 0)",
                        [](const ppsynth::PoissonDiskOptions& o, const std::string&) {
                          auto g = std::make_unique<ppsynth::PoissonDiskGen>();
                          g->opt = o;
                          return g;
                        })
