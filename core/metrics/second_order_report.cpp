#include "core/metrics/second_order_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/mark_correlation.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/second_order.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

json values(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(std::isfinite(x) ? json(x) : json(nullptr));
  return a;
}

double sup_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = std::numeric_limits<double>::quiet_NaN();
  for (size_t k = 0; k < a.size() && k < b.size(); ++k)
    if (std::isfinite(a[k]) && std::isfinite(b[k])) m = std::isnan(m) ? std::abs(a[k] - b[k]) : std::max(m, std::abs(a[k] - b[k]));
  return m;
}

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// One row: a (to b for a pair) in the exemplar against the same in the output.
json row(const PointSet& ea, const PointSet* eb, const PointSet& oa, const PointSet* ob, bool curves) {
  const bool pair = eb != nullptr;
  const bool ok = pair ? !ea.empty() && !eb->empty() && !oa.empty() && !ob->empty() : ea.size() >= 2 && oa.size() >= 2;
  json j;
  if (!ok) {
    j["l_sup"] = j["l_sup_spacings"] = nullptr;
    return j;
  }
  const PointSet& second = pair ? *eb : ea;
  const std::vector<double> r = spatstat_r_grid(ea.domain(), static_cast<double>(second.size()) / ea.domain().area());
  const SecondOrder e = second_order(ea, eb, EdgeCorrection::Translation, r, curves);
  const SecondOrder o = second_order(oa, ob, EdgeCorrection::Translation, r, curves);
  const double sup = sup_difference(e.l, o.l);
  j["l_sup"] = num(sup);
  j["l_sup_spacings"] = num(sup * std::sqrt(static_cast<double>(second.size()) / ea.domain().area()));
  if (curves) {
    j["r"] = r;
    j["exemplar"] = {{"k", values(e.k)}, {"l", values(e.l)}, {"g", values(e.g)}};
    j["output"] = {{"k", values(o.k)}, {"l", values(o.l)}, {"g", values(o.g)}};
  }
  return j;
}

}  // namespace

json second_order_report(const PointSet& exemplar, const PointSet& output, double zoom, bool curves) {
  if (!(zoom > 0)) throw InputError("second-order summaries: the zoom must be > 0");
  const Domain E = exemplar.domain(), O = output.domain();
  const PointSet ex = exemplar.mapped_to(Domain{0, 0, E.width(), E.height()});
  const PointSet out = output.mapped_to(Domain{0, 0, O.width() / zoom, O.height() / zoom});
  json rows = json::array();
  json all = row(ex, nullptr, out, nullptr, curves);
  all["row"] = "all";
  rows.push_back(all);
  const int K = exemplar.num_classes();
  if (K > 1) {
    std::vector<PointSet> ek, ok;
    for (int k = 0; k < K; ++k) {
      ek.push_back(ex.subset_class(k));
      ok.push_back(out.subset_class(k));
    }
    for (int k = 0; k < K; ++k) {
      json c = row(ek[k], nullptr, ok[k], nullptr, curves);
      c["row"] = "class";
      c["class"] = k;
      rows.push_back(c);
    }
    if (K <= kMaxPairClasses)
      for (int a = 0; a < K; ++a)
        for (int b = a + 1; b < K; ++b) {
          json c = row(ek[a], &ek[b], ok[a], &ok[b], curves);
          c["row"] = "pair";
          c["ci"] = a;
          c["cj"] = b;
          rows.push_back(c);
        }
  }
  json marks = json::array();
  for (size_t a = 0; a < ex.num_attributes(); ++a) {
    const std::string& name = ex.attribute_names()[a];
    json m = {{"attribute", name}};
    const auto oa = out.attribute_index(name);
    try {
      if (!oa) throw InputError("the output has no attribute '" + name + "'");
      const MarkCorrelation me = mark_correlation(ex, a, EdgeCorrection::Translation);
      const MarkCorrelation mo = mark_correlation(out, static_cast<size_t>(*oa), EdgeCorrection::Translation, me.r);
      m["sup"] = num(sup_difference(me.k, mo.k));
      if (curves) {
        m["r"] = me.r;
        m["exemplar"] = values(me.k);
        m["output"] = values(mo.k);
      }
    } catch (const InputError& e) {
      m["skipped"] = e.what();
    }
    marks.push_back(m);
  }
  json report = {{"correction", "translation"}, {"zoom", zoom}, {"rows", rows}, {"mark_correlation", marks}};
  if (K > kMaxPairClasses)
    report["pairs_skipped"] = "the exemplar has " + std::to_string(K) + " classes: the " +
                              std::to_string(static_cast<size_t>(K) * (K - 1) / 2) +
                              " class pairs' K, L and g are computed up to " + std::to_string(kMaxPairClasses) +
                              " classes only";
  return report;
}

}  // namespace ppsynth
