// Generator registry plumbing.
#include "core/generators/generator.hpp"

#include "core/config/defaults_catalog.hpp"
#include "core/memory_budget.hpp"

namespace ppsynth {

PointSet generate_points(const nlohmann::json& spec, size_t n, uint64_t seed, const Domain& domain,
                         const std::string& key_path) {
  auto gen = GeneratorRegistry::instance().create(spec, key_path);
  // positions, class and bookkeeping of a PointSet, and the generators' own per-point state
  check_memory(static_cast<double>(n) * 96.0, "generating " + std::to_string(n) + " points");
  return gen->generate(n, seed, domain);
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("generator", ppsynth::GeneratorRegistry)
