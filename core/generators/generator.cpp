// Generator registry plumbing.
#include "core/generators/generator.hpp"

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

PointSet generate_points(const nlohmann::json& spec, size_t n, uint64_t seed, const Domain& domain,
                         const std::string& key_path) {
  auto gen = GeneratorRegistry::instance().create(spec, key_path);
  return gen->generate(n, seed, domain);
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("generator", ppsynth::GeneratorRegistry)
