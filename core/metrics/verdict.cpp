#include "core/metrics/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "core/metrics/crops.hpp"
#include "core/metrics/second_order.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;
using Curve = std::vector<double>;

// Sub-windows of size a_x x a_y (guard shrinks each cell) tiling `d` from its corner.
std::vector<Domain> sub_windows(const Domain& d, double ax, double ay, double guard) {
  const int nx = static_cast<int>(std::floor(d.width() / ax + 1e-9)), ny = static_cast<int>(std::floor(d.height() / ay + 1e-9));
  const double gx = 0.5 * guard * ax, gy = 0.5 * guard * ay;
  std::vector<Domain> w;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      w.push_back(Domain{d.x0 + i * ax + gx, d.y0 + j * ay + gy, d.x0 + (i + 1) * ax - gx, d.y0 + (j + 1) * ay - gy});
  return w;
}

// Sub-windows of size a_x x a_y (guard shrinks each cell) on a block of at most
// max_x x max_y cells of `d`'s grid, the block placed by the seed (all of `d` when it holds no
// more cells than that).
std::vector<Domain> sub_windows(const Domain& d, double ax, double ay, double guard, int max_x, int max_y,
                                uint64_t seed) {
  const int nx = static_cast<int>(std::floor(d.width() / ax + 1e-9)), ny = static_cast<int>(std::floor(d.height() / ay + 1e-9));
  const int bx = std::min(nx, max_x), by = std::min(ny, max_y);
  std::mt19937_64 rng(seed * 0xD1B54A32D192ED03ull + static_cast<uint64_t>(nx) * 1000003u + static_cast<uint64_t>(ny));
  const int i0 = nx > bx ? static_cast<int>(rng() % static_cast<uint64_t>(nx - bx + 1)) : 0;
  const int j0 = ny > by ? static_cast<int>(rng() % static_cast<uint64_t>(ny - by + 1)) : 0;
  return sub_windows(Domain{d.x0 + i0 * ax, d.y0 + j0 * ay, d.x0 + (i0 + bx) * ax, d.y0 + (j0 + by) * ay}, ax, ay, guard);
}

// What a row measures on one sub-window's points: K of all, of a class, or of a class pair.
struct RowSpec {
  std::string row;  // "all", "class", "pair"
  int ci = -1, cj = -1;
};

std::optional<Curve> row_curve(const PointSet& sub, const RowSpec& spec, const Curve& r) {
  if (spec.row == "pair") {
    const PointSet a = sub.subset_class(spec.ci), b = sub.subset_class(spec.cj);
    if (a.empty() || b.empty()) return std::nullopt;
    return second_order(a, &b, EdgeCorrection::Translation, r, false).k;
  }
  const PointSet a = spec.row == "class" ? sub.subset_class(spec.ci) : sub;
  if (a.size() < 2) return std::nullopt;
  return second_order(a, nullptr, EdgeCorrection::Translation, r, false).k;
}

// Hahn's T for the curves split into `first` (indices into curves) and the rest.
double studentized(const std::vector<Curve>& curves, const std::vector<char>& in_first, const Curve& dr) {
  const size_t R = dr.size();
  std::vector<double> s1(R, 0), q1(R, 0), s2(R, 0), q2(R, 0);
  double n1 = 0, n2 = 0;
  for (size_t u = 0; u < curves.size(); ++u) {
    auto& s = in_first[u] ? s1 : s2;
    auto& q = in_first[u] ? q1 : q2;
    (in_first[u] ? n1 : n2) += 1;
    for (size_t k = 0; k < R; ++k) {
      s[k] += curves[u][k];
      q[k] += curves[u][k] * curves[u][k];
    }
  }
  double t = 0;
  for (size_t k = 0; k < R; ++k) {
    const double m1 = s1[k] / n1, m2 = s2[k] / n2;
    const double v1 = std::max(0.0, (q1[k] - n1 * m1 * m1) / (n1 - 1)), v2 = std::max(0.0, (q2[k] - n2 * m2 * m2) / (n2 - 1));
    const double den = v1 / n1 + v2 / n2;
    // Radii where every sub-window agrees (no pair yet below a hard core) carry no evidence.
    if (den > 1e-300) t += (m1 - m2) * (m1 - m2) / den * dr[k];
  }
  return t;
}

std::string fmt(double v, const char* f = "%.4g") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

void check_verdict_options(const VerdictOptions& o) {
  if (o.split < 1 || o.split > 20) throw InputError("verdict split (--verdict-split) must be in 1..20");
  if (!(o.guard >= 0 && o.guard <= 0.9)) throw InputError("verdict guard (--verdict-guard) must be in [0, 0.9]");
  if (o.permutations < 19 || o.permutations > 1000000)
    throw InputError("verdict permutations (--verdict-permutations) must be in 19..1000000");
  if (o.r_values < 2 || o.r_values > 10000) throw InputError("verdict r values must be in 2..10000");
  if (!(o.alpha > 0 && o.alpha < 1)) throw InputError("verdict alpha (--verdict-alpha) must be in (0, 1)");
  if (!(o.zoom >= 0) || !std::isfinite(o.zoom)) throw InputError("zoom (--zoom) must be a number >= 0");
}

json verdict(const PointSet& exemplar, const PointSet& output, const VerdictOptions& opt) {
  check_verdict_options(opt);
  if (exemplar.empty() || output.empty()) throw InputError("verdict: the exemplar and the output need points");
  const double zoom = opt.zoom > 0 ? opt.zoom : density_zoom(exemplar, output);
  const Domain E = exemplar.domain(), O = output.domain();
  const PointSet ex = exemplar.mapped_to(Domain{0, 0, E.width(), E.height()});
  const PointSet out = output.mapped_to(Domain{0, 0, O.width() / zoom, O.height() / zoom});
  const double ax = E.width() / opt.split, ay = E.height() / opt.split;
  const std::vector<Domain> ex_w = sub_windows(ex.domain(), ax, ay, opt.guard);
  const int block = kOutputBlockPerExemplarSide * opt.split;
  const std::vector<Domain> out_w = sub_windows(out.domain(), ax, ay, opt.guard, block, block, opt.seed);
  const double sw = ax * (1 - opt.guard), sh = ay * (1 - opt.guard);
  const double r_max = 0.25 * std::min(sw, sh);
  Curve r(static_cast<size_t>(opt.r_values)), dr(r.size(), r_max / opt.r_values);
  for (size_t k = 0; k < r.size(); ++k) r[k] = r_max * static_cast<double>(k + 1) / opt.r_values;

  std::vector<PointSet> subs;
  for (const Domain& w : ex_w) subs.push_back(ex.crop(w));
  for (const Domain& w : out_w) subs.push_back(out.crop(w));

  std::vector<RowSpec> specs{{"all"}};
  const int K = std::max(exemplar.num_classes(), 1);
  if (K > 1) {
    for (int k = 0; k < K; ++k) specs.push_back({"class", k});
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b) specs.push_back({"pair", a, b});
  }

  json rows = json::array();
  for (const RowSpec& spec : specs) {
    std::vector<Curve> curves;
    std::vector<char> first;
    for (size_t u = 0; u < subs.size(); ++u)
      if (auto c = row_curve(subs[u], spec, r)) {
        curves.push_back(std::move(*c));
        first.push_back(u < ex_w.size());
      }
    const size_t n1 = static_cast<size_t>(std::count(first.begin(), first.end(), 1)), n2 = curves.size() - n1;
    json row = {{"row", spec.row}, {"units", {n1, n2}}};
    if (spec.row == "class") {
      row["class"] = spec.ci;
      row["label"] = exemplar.class_label(spec.ci);
    } else if (spec.row == "pair") {
      row["ci"] = spec.ci;
      row["cj"] = spec.cj;
    }
    if (n1 < 2 || n2 < 2) {
      row["p"] = nullptr;
      row["pass"] = nullptr;
      row["reason"] = "needs 2 sub-windows with points in each pattern (" + std::to_string(n1) + " in the exemplar, " +
                      std::to_string(n2) + " in the output)";
      rows.push_back(row);
      continue;
    }
    const double t = studentized(curves, first, dr);
    // One generator per row, seeded from the row's place: rows do not shift one another.
    std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + rows.size());
    std::vector<char> perm = first;
    size_t beyond = 0;
    for (int p = 0; p < opt.permutations; ++p) {
      // Fisher-Yates on the labels (uniform over reassignments with the groups' sizes).
      for (size_t i = perm.size() - 1; i > 0; --i) {
        const size_t j = static_cast<size_t>(rng() % (i + 1));
        std::swap(perm[i], perm[j]);
      }
      if (studentized(curves, perm, dr) >= t * (1 - 1e-12)) ++beyond;
    }
    const double pv = (1.0 + static_cast<double>(beyond)) / (1.0 + opt.permutations);
    row["statistic"] = t;
    row["p"] = pv;
    row["pass"] = pv >= opt.alpha;
    rows.push_back(row);
  }
  return {{"test", "studentized permutation test of equal K-functions over sub-windows (Hahn 2012)"},
          {"statistic", "K, translation correction"},
          {"split", opt.split},
          {"guard", opt.guard},
          {"zoom", zoom},
          {"sub_window", {sw, sh}},
          {"r_max", r_max},
          {"permutations", opt.permutations},
          {"seed", opt.seed},
          {"alpha", opt.alpha},
          {"rows", rows}};
}

std::string format_verdict(const json& v) {
  std::ostringstream os;
  os << "verdict: " << v.value("test", std::string()) << ", " << v["split"].get<int>() << " x " << v["split"].get<int>()
     << " sub-windows of the exemplar (" << fmt(v["sub_window"][0].get<double>()) << " x "
     << fmt(v["sub_window"][1].get<double>()) << " exemplar units), r up to " << fmt(v["r_max"].get<double>()) << ", "
     << v["permutations"].get<int>() << " permutations; pass: p >= " << fmt(v["alpha"].get<double>()) << "\n";
  for (const auto& row : v["rows"]) {
    const std::string kind = row["row"].get<std::string>();
    std::string name = kind == "all" ? "all classes"
                       : kind == "class" ? "class " + std::to_string(row["label"].get<int>())
                                         : "pair " + std::to_string(row["ci"].get<int>()) + "-" + std::to_string(row["cj"].get<int>());
    char line[256];
    if (row["p"].is_null()) {
      std::snprintf(line, sizeof line, "  %-14s  untestable: %s\n", name.c_str(), row["reason"].get<std::string>().c_str());
    } else {
      std::snprintf(line, sizeof line, "  %-14s  p = %.4f  %s  (%zu + %zu sub-windows)\n", name.c_str(), row["p"].get<double>(),
                    row["pass"].get<bool>() ? "pass" : "FAIL", row["units"][0].get<size_t>(), row["units"][1].get<size_t>());
    }
    os << line;
  }
  return os.str();
}

}  // namespace ppsynth
