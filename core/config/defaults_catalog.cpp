#include "core/config/defaults_catalog.hpp"

#include <map>

namespace ppsynth {

namespace {
std::map<std::string, std::function<nlohmann::json()>>& kinds() {
  static std::map<std::string, std::function<nlohmann::json()>> k;
  return k;
}
}  // namespace

bool register_defaults_kind(const std::string& kind, std::function<nlohmann::json()> describe) {
  kinds()[kind] = std::move(describe);
  return true;
}

nlohmann::json defaults_catalog() {
  nlohmann::json j = nlohmann::json::object();
  for (auto& [k, f] : kinds()) j[k] = f();
  return j;
}

}  // namespace ppsynth
