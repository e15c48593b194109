#include "optim/point_term.hpp"

#include <cmath>

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

std::vector<WeightedPointTerm> create_point_terms(const nlohmann::json& terms) {
  std::vector<WeightedPointTerm> out;
  if (terms.is_null()) return out;
  if (!terms.is_object()) throw config_error("method.terms", "expected an object {\"name\": {\"weight\": w, ...}}");
  for (auto it = terms.begin(); it != terms.end(); ++it) {
    const std::string kp = "method.terms." + it.key();
    nlohmann::json spec = it.value().is_null() ? nlohmann::json::object() : it.value();
    if (!spec.is_object()) throw config_error(kp, "expected an object {\"weight\": w, ...}");
    if (spec.contains("type")) throw config_error(kp + ".type", "the term's name is its key here");
    spec["type"] = it.key();
    nlohmann::json resolved;
    auto term = PointTermRegistry::instance().create(spec, kp, &resolved);
    if (!resolved.contains("weight") || !resolved["weight"].is_number())
      throw config_error(kp + ".weight", "every point term needs a numeric weight");
    const double w = resolved["weight"].get<double>();
    if (!(w >= 0) || !std::isfinite(w)) throw config_error(kp + ".weight", "must be >= 0");
    if (w > 0) out.push_back({it.key(), w, std::move(term)});
  }
  return out;
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("point_term", ppsynth::PointTermRegistry)
