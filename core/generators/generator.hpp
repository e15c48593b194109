#pragma once
// Seeded classic point processes ("generators"), used as exemplars, initializations and
// metric baselines. Each process is a free function `PointSet f(size_t n, uint64_t seed,
// Domain d = {}, ...params)` in its own header, plus a PointGenerator registered in
// GeneratorRegistry under its config name, so configs and `ppsynth generate` can say
// {"type": "jittered_grid"} (parameters and their defaults: `ppsynth config --kind generator`).
//
// Contract: same (n, seed, params) => same points (std::mt19937_64 seeded explicitly); all
// points lie in the domain; a single class (0). Impossible parameters throw InputError.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "core/registry.hpp"

namespace ppsynth {

class PointGenerator {
 public:
  virtual ~PointGenerator() = default;
  virtual PointSet generate(size_t n, uint64_t seed, const Domain& domain) const = 0;
};

using GeneratorRegistry = Registry<PointGenerator>;

// Convenience: GeneratorRegistry::create(spec, key_path)->generate(n, seed, domain).
// `spec` is {"type": name, ...params}.
PointSet generate_points(const nlohmann::json& spec, size_t n, uint64_t seed,
                         const Domain& domain = {}, const std::string& key_path = "generator");

}  // namespace ppsynth
