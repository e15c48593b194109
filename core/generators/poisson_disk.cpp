#include "core/generators/poisson_disk.hpp"

#include <cmath>
#include <random>

#include "core/generators/dynamic_grid.hpp"
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
  if (opt.max_attempts == 0) throw config_error("poisson_disk.max_attempts", "must be positive");
  std::mt19937_64 rng(seed);
  PointSet ps(d);
  ps.reserve(n);
  gen_detail::DynamicGrid grid(d, std::max(r, 1e-9 * d.width()), d.periodic);
  size_t fails = 0;
  while (grid.size() < n && fails < opt.max_attempts) {
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

PPSYNTH_REGISTER(
    ppsynth::GeneratorRegistry, "poisson_disk",
    (nlohmann::json{{"radius", 0.0}, {"relative_radius", 0.65}, {"max_attempts", 100000}, {"require_all", false}}),
    (nlohmann::json{{"radius", "[0, 0.5]"}, {"relative_radius", "[0, 1]"}, {"max_attempts", "int [1, 1000000000]"}}),
    "dart-throwing Poisson disk (minimum distance `radius`, or relative_radius * 2 r_max when radius = 0)",
    [](const nlohmann::json& p, const std::string& key) {
      auto g = std::make_unique<ppsynth::PoissonDiskGen>();
      g->opt.radius = p["radius"].get<double>();
      g->opt.relative_radius = p["relative_radius"].get<double>();
      const double a = p["max_attempts"].get<double>();
      if (!(a >= 1)) throw ppsynth::config_error("max_attempts", "must be >= 1");
      g->opt.max_attempts = static_cast<size_t>(a);
      g->opt.require_all = p["require_all"].get<bool>();
      return g;
    })
