#include "core/metrics/metric_values.hpp"

#include <cstdio>

#include "core/error.hpp"

namespace ppsynth {

namespace {

// Class ids of an evaluation are dense and small; a larger one is not an evaluation's.
constexpr long long kMaxClassId = 1000000;
// border.hpp's profile has a handful of bands.
constexpr size_t kMaxBands = 64;

class Reader {
 public:
  Reader(const std::string& source, std::vector<std::pair<std::string, double>>& out) : source_(source), out_(out) {}

  [[noreturn]] void refuse(const std::string& key, const std::string& what) const {
    throw file_error(source_, 0, "key '" + key + "': " + what + " (not the layout of an evaluation)");
  }
  const nlohmann::json* object(const nlohmann::json& parent, const char* name, const std::string& key) const {
    if (!parent.contains(name)) return nullptr;
    if (!parent[name].is_object()) refuse(key, "expected an object");
    return &parent[name];
  }
  const nlohmann::json* array(const nlohmann::json& parent, const char* name, const std::string& key) const {
    if (!parent.contains(name)) return nullptr;
    if (!parent[name].is_array()) refuse(key, "expected a list");
    return &parent[name];
  }
  long long class_id(const nlohmann::json& parent, const char* name, const std::string& key) const {
    if (!parent.contains(name) || !parent[name].is_number_integer() || parent[name].get<long long>() < 0 ||
        parent[name].get<long long>() > kMaxClassId)
      refuse(key + "." + name, "expected a class id");
    return parent[name].get<long long>();
  }
  // A metric: a number, or null / absent (undefined for this output) and then left out.
  void add(const std::string& name, const nlohmann::json& parent, const char* field, const std::string& key) {
    if (!parent.contains(field) || parent[field].is_null()) return;
    if (!parent[field].is_number()) refuse(key + "." + field, "expected a number or null");
    out_.push_back({name, parent[field].get<double>()});
  }
  void patch(const std::string& scope, const nlohmann::json& p, const std::string& key) {
    for (const char* m : {"pcf_mse", "wasserstein", "wasserstein_estimate", "chamfer"}) add(scope + "/" + m, p, m, key);
  }

 private:
  const std::string& source_;
  std::vector<std::pair<std::string, double>>& out_;
};

}  // namespace

std::vector<std::pair<std::string, double>> metric_values(const nlohmann::json& m, const std::string& source) {
  std::vector<std::pair<std::string, double>> v;
  Reader r(source, v);
  if (!m.is_object()) throw file_error(source, 0, "expected a JSON object (an evaluation)");
  if (const auto* all = r.object(m, "all", "all")) r.patch("all", *all, "all");
  if (const auto* out = r.object(m, "output", "output")) {
    r.add("all/relative_radius", *out, "relative_radius", "output");
    r.add("all/border_fraction", *out, "border_fraction", "output");
    // The border's density over uniform's, band by band ("border_density_0.5%"; border.hpp).
    if (const auto* p = r.object(*out, "border_profile", "output.border_profile")) {
      const auto* band = r.array(*p, "band", "output.border_profile.band");
      const auto* over = r.array(*p, "over_uniform", "output.border_profile.over_uniform");
      if (!band || !over || band->size() != over->size() || band->size() > kMaxBands)
        r.refuse("output.border_profile", "expected lists 'band' and 'over_uniform' of one length (at most 64)");
      for (size_t i = 0; i < band->size(); ++i) {
        const std::string key = "output.border_profile.band[" + std::to_string(i) + "]";
        if (!(*band)[i].is_number()) r.refuse(key, "expected a number");
        char name[64];
        std::snprintf(name, sizeof name, "all/border_density_%g%%", 100 * (*band)[i].get<double>());
        const nlohmann::json value = {{"v", (*over)[i]}};
        r.add(name, value, "v", "output.border_profile.over_uniform[" + std::to_string(i) + "]");
      }
    }
  }
  if (const auto* classes = r.array(m, "classes", "classes"))
    for (size_t i = 0; i < classes->size(); ++i) {
      const std::string key = "classes[" + std::to_string(i) + "]";
      const nlohmann::json& c = (*classes)[i];
      if (!c.is_object()) r.refuse(key, "expected an object");
      r.patch("class " + std::to_string(r.class_id(c, "class", key)), c, key);
    }
  if (const auto* cross = r.array(m, "cross", "cross"))
    for (size_t i = 0; i < cross->size(); ++i) {
      const std::string key = "cross[" + std::to_string(i) + "]";
      const nlohmann::json& c = (*cross)[i];
      if (!c.is_object()) r.refuse(key, "expected an object");
      const long long ci = r.class_id(c, "ci", key), cj = r.class_id(c, "cj", key);
      r.add("classes " + std::to_string(ci) + "-" + std::to_string(cj) + "/pcf_mse", c, "pcf_mse", key);
    }
  // spatstat's L (sup distance) and the verdict's p-value and pass (1/0: the mean over seeds
  // is the pass rate), in the scopes above (second_order_report.hpp, verdict.hpp).
  auto rows_of = [&](const nlohmann::json& parent, const char* section, const std::string& at, auto&& each) {
    const auto* sec = r.object(parent, section, at);
    if (!sec) return;
    const std::string key = at + ".rows";
    const auto* list = r.array(*sec, "rows", key);
    if (!list) return;
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string k = key + "[" + std::to_string(i) + "]";
      const nlohmann::json& row = (*list)[i];
      if (!row.is_object()) r.refuse(k, "expected an object");
      const std::string kind = row.contains("row") && row["row"].is_string() ? row["row"].get<std::string>() : "all";
      const std::string scope =
          kind == "class"  ? "class " + std::to_string(r.class_id(row, "class", k))
          : kind == "pair" ? "classes " + std::to_string(r.class_id(row, "ci", k)) + "-" + std::to_string(r.class_id(row, "cj", k))
                           : std::string("all");
      each(scope, row, k);
    }
  };
  auto rows = [&](const char* section, auto&& each) { rows_of(m, section, section, each); };
  rows("second_order", [&](const std::string& scope, const nlohmann::json& row, const std::string& k) {
    r.add(scope + "/l_sup", row, "l_sup", k);
  });
  rows("verdict", [&](const std::string& scope, const nlohmann::json& row, const std::string& k) {
    r.add(scope + "/verdict_p", row, "p", k);
    if (row.contains("pass") && !row["pass"].is_null()) {
      if (!row["pass"].is_boolean()) r.refuse(k + ".pass", "expected true, false or null");
      const nlohmann::json value = {{"v", row["pass"].get<bool>() ? 1.0 : 0.0}};
      r.add(scope + "/verdict_pass", value, "v", k + ".pass");
    } else if (row.contains("pass")) {  // neither pass nor fail: counted apart, never as a pass
      const nlohmann::json value = {{"v", 1.0}};
      r.add(scope + "/verdict_cannot_judge", value, "v", k + ".pass");
    }
  });
  // The scorecard (novelty.hpp, close_pairs.hpp): the share of the output's neighbourhoods
  // copied from the exemplar and its copy flag (1/0: the mean over seeds is the share of seeds
  // flagged); per row the share of points in a pair closer than the exemplar's closest and the
  // normalized minimum distance.
  if (const auto* sc = r.object(m, "scorecard", "scorecard")) {
    if (const auto* nov = r.object(*sc, "novelty", "scorecard.novelty")) {
      r.add("all/novelty_share", *nov, "share", "scorecard.novelty");
      if (nov->contains("copy") && !(*nov)["copy"].is_null()) {
        if (!(*nov)["copy"].is_boolean()) r.refuse("scorecard.novelty.copy", "expected true, false or null");
        const nlohmann::json value = {{"v", (*nov)["copy"].get<bool>() ? 1.0 : 0.0}};
        r.add("all/copy", value, "v", "scorecard.novelty.copy");
      }
    }
    // The periodogram's ratio at the exemplar's period and its flag (periodicity.hpp), the same way.
    if (const auto* per = r.object(*sc, "periodicity", "scorecard.periodicity")) {
      r.add("all/periodicity_ratio", *per, "ratio", "scorecard.periodicity");
      if (per->contains("periodic") && !(*per)["periodic"].is_null()) {
        if (!(*per)["periodic"].is_boolean()) r.refuse("scorecard.periodicity.periodic", "expected true, false or null");
        const nlohmann::json value = {{"v", (*per)["periodic"].get<bool>() ? 1.0 : 0.0}};
        r.add("all/periodic", value, "v", "scorecard.periodicity.periodic");
      }
    }
    // Fidelity (fidelity.hpp): per row each distance in spreads, and within band (1/0: the
    // mean over seeds is the share of seeds within); mark rows in scope "all" by attribute.
    rows_of(*sc, "fidelity", "scorecard.fidelity", [&](const std::string& scope, const nlohmann::json& row, const std::string& k) {
      const bool mark = row.contains("row") && row["row"] == "mark";
      const std::string at = mark && row.contains("attribute") && row["attribute"].is_string()
                                 ? "_" + row["attribute"].get<std::string>()
                                 : std::string();
      for (const char* d : {"l", "g", "kmm"})
        if (const auto* m = r.object(row, d, k + "." + d)) r.add(scope + "/fidelity_" + d + at + "_spreads", *m, "spreads", k + "." + d);
      if (row.contains("within") && !row["within"].is_null()) {
        if (!row["within"].is_boolean()) r.refuse(k + ".within", "expected true, false or null");
        const nlohmann::json value = {{"v", row["within"].get<bool>() ? 1.0 : 0.0}};
        r.add(scope + "/fidelity_within" + at, value, "v", k + ".within");
      }
    });
    rows_of(*sc, "close_pairs", "scorecard.close_pairs", [&](const std::string& scope, const nlohmann::json& row, const std::string& k) {
      r.add(scope + "/close_pair_share", row, "share_below", k);
      r.add(scope + "/min_distance_normalized", row, "output_normalized", k);
    });
  }
  return v;
}

}  // namespace ppsynth
