#include "core/generators/uniform.hpp"

#include <random>

#include "core/generators/generator.hpp"
#include "core/generators/sampling_util.hpp"

namespace ppsynth {

PointSet uniform_points(size_t n, uint64_t seed, Domain d) {
  gen_detail::check_domain(d, "uniform");
  std::mt19937_64 rng(seed);
  PointSet ps(d);
  ps.reserve(n);
  for (size_t i = 0; i < n; ++i) ps.add(gen_detail::uniform_in(rng, d));
  return ps;
}

namespace {
struct UniformGen : PointGenerator {
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return uniform_points(n, seed, d);
  }
  static const ParamTable<UniformGen>& params() {
    static const ParamTable<UniformGen> t("generator", {});
    return t;
  }
};
}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "uniform", ppsynth::UniformGen::params(),
                        "uniform random points (white noise)",
                        [](const ppsynth::UniformGen& g, const std::string&) { return std::make_unique<ppsynth::UniformGen>(g); })
