#include "optim/gabor/stages/stage_kind.hpp"

namespace ppsynth {

std::vector<std::shared_ptr<StageKind>> class_end_kinds(const GaborSettings& settings) {
  std::vector<std::shared_ptr<StageKind>> kinds;
  const auto& registry = StageKindRegistry::instance();
  for (const std::string& name : registry.names())  // a std::map's order: the same plan every run
    if (auto kind = registry.entry(name).make(nlohmann::json::object(), "method." + name, settings))
      kinds.push_back(std::move(kind));
  return kinds;
}

}  // namespace ppsynth
