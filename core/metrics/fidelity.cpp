#include "core/metrics/fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/metrics/class_match.hpp"
#include "core/metrics/mark_correlation.hpp"
#include "core/metrics/second_order.hpp"
#include "core/metrics/subwindow_spread.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;
using Curve = std::vector<double>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

double sup_difference(const Curve& a, const Curve& b) {
  double m = kNaN;
  for (size_t k = 0; k < a.size() && k < b.size(); ++k)
    if (std::isfinite(a[k]) && std::isfinite(b[k])) m = std::isnan(m) ? std::abs(a[k] - b[k]) : std::max(m, std::abs(a[k] - b[k]));
  return m;
}

// Root mean square of a - b over the radii from `from` on (finite values only).
double rms_difference(const Curve& r, const Curve& a, const Curve& b, double from) {
  double s = 0;
  size_t n = 0;
  for (size_t k = 0; k < r.size() && k < a.size() && k < b.size(); ++k)
    if (r[k] >= from && std::isfinite(a[k]) && std::isfinite(b[k])) {
      s += (a[k] - b[k]) * (a[k] - b[k]);
      ++n;
    }
  return n ? std::sqrt(s / static_cast<double>(n)) : kNaN;
}

// One row's summaries of one pattern (exemplar, output or a sub-window): the curves the
// distances compare, empty when the pattern has too few of the row's points.
struct Summary {
  Curve l, g;        // all, class, pair rows
  Curve k;           // mark rows: k_mm
  double h = 0;      // g's kernel half-width
  bool ok = false;
};

// What a row measures on a pattern's points (classes split once per pattern).
struct Row {
  std::string kind;  // "all", "class", "pair", "mark"
  int ci = -1, cj = -1;
  size_t attribute = 0;
  std::string attribute_name;
};

// A pattern split into its classes once (the rows take their points from here).
struct Split {
  PointSet all;
  std::vector<PointSet> cls;
};
Split split(const PointSet& ps, int classes) {
  Split s{ps, {}};
  if (classes > 1)
    for (int k = 0; k < classes; ++k) s.cls.push_back(ps.subset_class(k));
  return s;
}

Summary summarize(const Split& p, const Row& row, const Curve& r) {
  Summary s;
  if (row.kind == "mark") {
    try {
      if (p.all.size() < 2) return s;
      const auto a = p.all.attribute_index(row.attribute_name);
      if (!a) return s;
      s.k = mark_correlation(p.all, static_cast<size_t>(*a), EdgeCorrection::Translation, r).k;
      s.ok = true;
    } catch (const InputError&) {  // a window whose marks are all 0: no k_mm there
    }
    return s;
  }
  const PointSet& a = row.kind == "all" ? p.all : p.cls[static_cast<size_t>(row.ci)];
  const PointSet* b = row.kind == "pair" ? &p.cls[static_cast<size_t>(row.cj)] : nullptr;
  if (b ? a.empty() || b->empty() : a.size() < 2) return s;
  const SecondOrder so = second_order(a, b, EdgeCorrection::Translation, r, true);
  s.l = so.l;
  s.g = so.g;
  s.h = so.bandwidth;
  s.ok = true;
  return s;
}

// The row's distances between two summaries: "l" (in spacings), "g"; or "kmm".
std::vector<std::pair<const char*, double>> distances(const Summary& a, const Summary& b, const Curve& r, double spacing) {
  if (!b.ok || !a.ok) return {};
  if (!a.k.empty()) return {{"kmm", sup_difference(a.k, b.k)}};
  return {{"l", sup_difference(a.l, b.l) / spacing}, {"g", rms_difference(r, a.g, b.g, std::max(a.h, b.h))}};
}

std::string name_of(const PointSet& labels, const Row& row) {
  if (row.kind == "class") return "class " + std::to_string(labels.class_label(row.ci));
  if (row.kind == "pair")
    return "classes " + std::to_string(labels.class_label(row.ci)) + "-" + std::to_string(labels.class_label(row.cj));
  if (row.kind == "mark") return "mark '" + row.attribute_name + "'";
  return "all points";
}

}  // namespace

void check_fidelity_options(const FidelityOptions& o) {
  if (o.windows < 16 || o.windows > 4096) throw InputError("fidelity windows (--fidelity-windows) must be in 16..4096");
  if (!(o.side >= 0.2 && o.side <= 0.8)) throw InputError("fidelity side (--fidelity-side) must be in [0.2, 0.8] of the exemplar's sides");
  if (!(o.band >= 1 && o.band <= 100)) throw InputError("fidelity band (--fidelity-band) must be in [1, 100] spreads");
  if (o.r_values < 8 || o.r_values > 2048) throw InputError("fidelity r values must be in 8..2048");
}

json fidelity_report(const PointSet& exemplar, const PointSet& output_in, double zoom, const FidelityOptions& opt) {
  check_fidelity_options(opt);
  if (!(zoom > 0)) throw InputError("fidelity: the zoom must be > 0");
  const PointSet& output = match_classes(exemplar, output_in).output;
  const Domain E = exemplar.domain(), O = output.domain();
  const PointSet ex = exemplar.mapped_to(Domain{0, 0, E.width(), E.height()});
  const PointSet out = output.mapped_to(Domain{0, 0, O.width() / zoom, O.height() / zoom});
  const double A = ex.domain().area(), A_out = out.domain().area();
  const std::vector<Domain> windows = random_subwindows(ex.domain(), opt.side, opt.windows, opt.seed);
  const double a = windows.front().area();
  const double scale = spread_scale(a, A, A_out);
  const double quarter = std::min(windows.front().width(), windows.front().height()) / 4;

  const int K = exemplar.num_classes();
  const Split ex_split = split(ex, K), out_split = split(out, std::max(K, output.num_classes()));
  std::vector<Split> subs;
  subs.reserve(windows.size());
  for (const Domain& w : windows) subs.push_back(split(ex.crop(w), K));

  std::vector<Row> rows{{"all", -1, -1, 0, ""}};
  if (K > 1) {
    for (int k = 0; k < K; ++k) rows.push_back({"class", k, -1, 0, ""});
    if (K <= kMaxFidelityPairClasses)
      for (int i = 0; i < K; ++i)
        for (int j = i + 1; j < K; ++j) rows.push_back({"pair", i, j, 0, ""});
  }
  for (size_t at = 0; at < ex.num_attributes(); ++at)
    if (out.attribute_index(ex.attribute_names()[at])) rows.push_back({"mark", -1, -1, at, ex.attribute_names()[at]});

  json list = json::array();
  size_t out_of_band = 0, cannot = 0;
  for (const Row& row : rows) {
    json j = {{"row", row.kind}};
    if (row.kind == "class") {
      j["class"] = row.ci;
      j["label"] = exemplar.class_label(row.ci);
    } else if (row.kind == "pair") {
      j["ci"] = row.ci;
      j["cj"] = row.cj;
      j["labels"] = {exemplar.class_label(row.ci), exemplar.class_label(row.cj)};
    } else if (row.kind == "mark") {
      j["attribute"] = row.attribute_name;
    }
    j["name"] = name_of(exemplar, row);
    // The row's intensity (its second class, as spatstat's cross functions) sets its spacing
    // and the cap on r.
    const PointSet& second = row.kind == "pair" ? ex_split.cls[static_cast<size_t>(row.cj)]
                             : row.kind == "class" ? ex_split.cls[static_cast<size_t>(row.ci)]
                                                   : ex;
    const double lambda = static_cast<double>(second.size()) / A;
    const double r_max = std::min(quarter, lambda > 0 ? kFidelityMaxSpacings / std::sqrt(lambda) : quarter);
    Curve r(static_cast<size_t>(opt.r_values));
    for (size_t k = 0; k < r.size(); ++k) r[k] = r_max * static_cast<double>(k + 1) / opt.r_values;
    j["r_max"] = r_max;
    const double spacing = lambda > 0 ? 1 / std::sqrt(lambda) : kNaN;
    j["spacing"] = num(spacing);
    const Summary se = summarize(ex_split, row, r);
    const Summary so = summarize(out_split, row, r);
    auto finish = [&](const json& within, const std::string& reason) {
      j["within"] = within;
      if (!reason.empty()) j["reason"] = reason;
      if (within.is_null()) ++cannot;
      if (within == false) ++out_of_band;
      list.push_back(j);
    };
    if (!se.ok) {
      finish(nullptr, "the exemplar has too few of the row's points (2 of a class, 1 of each class of a pair, marks not all 0)");
      continue;
    }
    if (!so.ok) {
      finish(false, "the output has too few of the row's points (2 of a class, 1 of each class of a pair, marks not all 0)");
      continue;
    }
    // How clustered the row is at r_max: 1 + the extra neighbours (of the row's second class)
    // within r_max over Poisson's, lambda (K_ex(r_max) - pi r_max^2), at least 1 (a regular row
    // is 1). The band widens with it (kFidelityClusterExponent: why).
    const double l_end = se.l.empty() ? kNaN : se.l.back();
    const double extra = std::isfinite(l_end) ? lambda * kPi * (l_end * l_end - r_max * r_max) : 0.0;
    const double clustering = 1 + std::max(0.0, extra);
    const double edge = opt.band * std::pow(clustering, kFidelityClusterExponent);
    j["clustering"] = clustering;
    // The null: each sub-window against the whole exemplar, scaled to the output's area.
    std::vector<std::vector<double>> null;
    size_t draws = 0;
    for (const Split& s : subs) {
      const auto d = distances(summarize(s, row, r), se, r, spacing);
      if (d.empty()) continue;
      ++draws;
      if (null.empty()) null.resize(d.size());
      for (size_t i = 0; i < d.size(); ++i) null[i].push_back(d[i].second * scale);
    }
    j["draws"] = draws;
    if (draws < kMinFidelityDraws) {
      finish(nullptr, std::to_string(draws) + " of " + std::to_string(windows.size()) +
                          " sub-windows hold the row's points: too few for a band (" + std::to_string(kMinFidelityDraws) + ")");
      continue;
    }
    bool all_within = true, any_unknown = false;
    const auto observed = distances(so, se, r, spacing);
    for (size_t i = 0; i < observed.size(); ++i) {
      const Spread spread = spread_of(null[i]);
      const double d = observed[i].second;
      json m = {{"distance", num(d)}, {"spread", num(spread.median)}};
      if (std::isfinite(d) && spread.draws >= kMinFidelityDraws && spread.median > 0) {
        const double spreads = d / spread.median;
        m["spreads"] = spreads;
        m["band"] = edge;
        m["within"] = spreads <= edge;
        all_within = all_within && spreads <= edge;
      } else {
        m["spreads"] = m["band"] = m["within"] = nullptr;
        any_unknown = true;
      }
      j[observed[i].first] = m;
    }
    if (!all_within)
      finish(false, "");
    else if (any_unknown)
      finish(nullptr, "no spread: at least half the sub-windows' curves equal the exemplar's (no pair of the row within r_max in "
                      "either), or a distance is undefined");
    else
      finish(true, "");
  }
  return {{"measures",
           "per row, L (sup distance, mean spacings) and g (root mean square) of the output against the exemplar, in "
           "spreads: the median distance that independent realizations of the output's size show, estimated from the "
           "exemplar's random sub-windows (subwindow_spread.hpp); within band: up to `band` spreads times the row's "
           "clustering to the power 1/4"},
          {"windows", opt.windows},
          {"side", opt.side},
          {"band", opt.band},
          {"nominal_rate", opt.band == FidelityOptions{}.band ? json(kFidelityNominalRate) : json(nullptr)},
          {"seed", opt.seed},
          {"scale", scale},
          {"exemplar_area", A},
          {"output_area", A_out},
          {"rows", list},
          {"out_of_band", out_of_band},
          {"cannot_judge", cannot},
          {"within", out_of_band > 0 ? json(false) : cannot > 0 ? json(nullptr) : json(true)}};
}

}  // namespace ppsynth
