#include "core/config/param_docs.hpp"

#include <map>
#include <utility>
#include <vector>

#include "core/config/config.hpp"

namespace ppsynth {

namespace {
std::map<std::pair<std::string, std::string>, std::vector<std::function<nlohmann::json()>>>& all() {
  static std::map<std::pair<std::string, std::string>, std::vector<std::function<nlohmann::json()>>> d;
  return d;
}
}  // namespace

bool register_param_docs(const std::string& kind, const std::string& part, std::function<nlohmann::json()> docs) {
  all()[{kind, part}].push_back(std::move(docs));
  return true;
}

nlohmann::json param_docs(const std::string& kind, const std::string& part) {
  nlohmann::json d = nlohmann::json::object();
  auto it = all().find({kind, part});
  if (it != all().end())
    for (const auto& f : it->second) d = merge(d, f());
  return d;
}

}  // namespace ppsynth
