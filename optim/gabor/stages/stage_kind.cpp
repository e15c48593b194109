#include "optim/gabor/stages/stage_kind.hpp"

#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/method/method.hpp"

namespace ppsynth {

std::vector<std::shared_ptr<StageKind>> class_end_kinds(const GaborSettings& settings) {
  std::vector<std::shared_ptr<StageKind>> kinds;
  const auto& registry = StageKindRegistry::instance();
  for (const std::string& name : registry.names()) {  // a std::map's order: the same plan every run
    const auto block = settings.stage_kinds.find(name);
    const nlohmann::json& params = block != settings.stage_kinds.end() ? *block : registry.entry(name).defaults;
    if (auto kind = registry.entry(name).make(params, "method." + name, settings)) kinds.push_back(std::move(kind));
  }
  return kinds;
}

bool register_stage_kind(const std::string& name, StageKindRegistry::Entry entry) {
  nlohmann::json defaults = entry.defaults, bounds = entry.bounds;
  StageKindRegistry::instance().add(name, std::move(entry));
  // Registered before this kind, the method lacks its block (gabor_defaults() lists the kinds
  // registered by then): it takes it now, so that method.<name> is a key of the method's
  // whatever the order of the static registrations.
  auto& methods = MethodRegistry::instance();
  if (methods.contains("gabor")) {
    MethodRegistry::Entry gabor = methods.entry("gabor");
    gabor.defaults[name] = defaults;
    if (!bounds.empty()) gabor.bounds[name] = bounds;
    methods.replace("gabor", std::move(gabor));
  }
  return true;
}

}  // namespace ppsynth
