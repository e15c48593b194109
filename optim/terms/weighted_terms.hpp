#pragma once
// The config shape shared by the optional loss terms beside the paper's (point terms,
// optim/terms/point_term.hpp; map terms, optim/gabor/stages/map_term.hpp):
//   "<key>": {"<registered name>": {"weight": w, ...params}, ...}
// A term is on when its weight is > 0; a term registered with a weight > 0 is on unless the
// config sets its weight to 0. Unknown names, unknown keys and a missing or negative weight are
// refused, naming the key path (method.<key>.<name>...).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/config.hpp"
#include "core/registry.hpp"

namespace ppsynth {

template <class Term>
struct WeightedTerm {
  std::string name;
  double weight = 0;
  std::unique_ptr<Term> term;
};

// The terms `terms` switches on, in name order.
template <class Term>
std::vector<WeightedTerm<Term>> create_weighted_terms(const nlohmann::json& terms, const std::string& key) {
  std::vector<WeightedTerm<Term>> out;
  if (!terms.is_null() && !terms.is_object()) throw config_error(key, "expected an object {\"name\": {\"weight\": w, ...}}");
  nlohmann::json named = terms.is_null() ? nlohmann::json::object() : terms;
  const auto& registry = Registry<Term>::instance();
  for (const auto& n : registry.names()) {  // the terms on by default
    const nlohmann::json& d = registry.entry(n).defaults;
    if (!named.contains(n) && d.contains("weight") && d["weight"].is_number() && d["weight"].get<double>() > 0)
      named[n] = nlohmann::json::object();
  }
  for (auto it = named.begin(); it != named.end(); ++it) {
    const std::string kp = key + "." + it.key();
    nlohmann::json spec = it.value().is_null() ? nlohmann::json::object() : it.value();
    if (!spec.is_object()) throw config_error(kp, "expected an object {\"weight\": w, ...}");
    if (spec.contains("type")) throw config_error(kp + ".type", "the term's name is its key here");
    spec["type"] = it.key();
    nlohmann::json resolved;
    auto term = Registry<Term>::instance().create(spec, kp, &resolved);
    if (!resolved.contains("weight") || !resolved["weight"].is_number())
      throw config_error(kp + ".weight", "every term needs a numeric weight");
    const double w = resolved["weight"].get<double>();
    if (!(w >= 0) || !std::isfinite(w)) throw config_error(kp + ".weight", "must be >= 0");
    if (w > 0) out.push_back({it.key(), w, std::move(term)});
  }
  return out;
}

// A rectangle output runs its stages in windows: every term `terms` switches on must say
// in_windows(); config_error naming <key>.<name> otherwise (`both`: the terms that know both).
template <class Term>
void check_terms_in_windows(const nlohmann::json& terms, const std::string& key, const std::string& both) {
  for (const auto& t : create_weighted_terms<Term>(terms, key))
    if (!t.term->in_windows())
      throw config_error(key + "." + t.name, "works on the paper's u x u outputs only, not on a rectangle output's "
                                             "windows (\"output\"); " + both + " works on both");
}

}  // namespace ppsynth
