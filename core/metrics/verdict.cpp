#include "core/metrics/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "core/metrics/class_match.hpp"
#include "core/metrics/crops.hpp"
#include "core/metrics/second_order.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;
using Curve = std::vector<double>;

// r_max's candidates, in sub-window sides: spatstat's quarter first, then steps toward half.
constexpr double kRMaxLadder[] = {0.25, 0.3125, 0.375, 0.4375, 0.5};

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

// The row's points of one sub-window: (a, b) with b empty unless a pair; nullopt when the
// sub-window has too few (2 of the class, 1 of each type for a pair) for a K.
struct RowPoints {
  PointSet a, b;
};
std::optional<RowPoints> row_points(const PointSet& sub, const RowSpec& spec) {
  if (spec.row == "pair") {
    RowPoints p{sub.subset_class(spec.ci), sub.subset_class(spec.cj)};
    if (p.a.empty() || p.b.empty()) return std::nullopt;
    return p;
  }
  RowPoints p{spec.row == "class" ? sub.subset_class(spec.ci) : sub, PointSet()};
  if (p.a.size() < 2) return std::nullopt;
  return p;
}

Curve row_curve(const RowPoints& p, const RowSpec& spec, const Curve& r) {
  return second_order(p.a, spec.row == "pair" ? &p.b : nullptr, EdgeCorrection::Translation, r, false).k;
}

// The row's closest pair in one sub-window (a to b for a pair), infinity when none.
double closest_pair(const RowPoints& p, const RowSpec& spec) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> d;
  if (spec.row == "pair") {
    const NeighborIndex index(p.b.positions());
    for (size_t i = 0; i < p.a.size(); ++i)
      if (!index.knn(p.a[i], 1, &d).empty()) best = std::min(best, d[0]);
  } else {
    const NeighborIndex index(p.a.positions());
    for (size_t i = 0; i < p.a.size(); ++i) {
      double di = 0;
      index.nearest_other(i, &di);
      best = std::min(best, di);
    }
  }
  return best;
}

// Hahn's T for the curves split into `first` (indices into curves) and the rest, and how
// many radii carried evidence (a denominator above the rounding noise of its sums).
struct Studentized {
  double t = 0;
  size_t radii = 0;
};
Studentized studentized(const std::vector<Curve>& curves, const std::vector<char>& in_first, const Curve& dr) {
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
  Studentized st;
  for (size_t k = 0; k < R; ++k) {
    const double m1 = s1[k] / n1, m2 = s2[k] / n2;
    const double v1 = std::max(0.0, (q1[k] - n1 * m1 * m1) / (n1 - 1)), v2 = std::max(0.0, (q2[k] - n2 * m2 * m2) / (n2 - 1));
    const double den = v1 / n1 + v2 / n2;
    // Radii where every sub-window agrees (no pair yet below a hard core) carry no evidence.
    // The threshold is relative to the curves' size (q / n^2, the scale of den), so that it
    // is the same at any coordinate scale and above the rounding of q - n m^2 when all agree.
    const double noise = 1e-10 * (q1[k] / (n1 * (n1 - 1)) + q2[k] / (n2 * (n2 - 1)));
    if (den > noise && den > 0) {
      st.t += (m1 - m2) * (m1 - m2) / den * dr[k];
      ++st.radii;
    }
  }
  return st;
}

// C(n, k) as a double (large values are only compared with 1 / alpha).
double choose(size_t n, size_t k) {
  k = std::min(k, n - k);
  double c = 1;
  for (size_t i = 1; i <= k && c < 1e300; ++i) c = c * static_cast<double>(n - k + i) / static_cast<double>(i);
  return c;
}

std::string fmt(double v, const char* f = "%.4g") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string class_name(const PointSet& ps, int k) { return "class " + std::to_string(ps.class_label(k)); }

// A row decided without a test: its outcome and why.
void decide(json& row, const std::string& outcome, const std::string& reason) {
  row["outcome"] = outcome;
  row["p"] = nullptr;
  row["pass"] = outcome == "fail" ? json(false) : json(nullptr);
  row["reason"] = reason;
}

// Why a class or pair row is decided by the classes' presence alone ("" when it is tested):
// a class one pattern has points of and the other has not fails; one neither has cannot judge.
std::string presence(const RowSpec& spec, const std::vector<size_t>& ex_n, const std::vector<size_t>& out_n,
                     const PointSet& labels, std::string& outcome) {
  std::vector<int> classes;
  if (spec.row == "class") classes = {spec.ci};
  if (spec.row == "pair") classes = {spec.ci, spec.cj};
  std::string fail, none;
  for (int k : classes) {
    const size_t e = static_cast<size_t>(k) < ex_n.size() ? ex_n[static_cast<size_t>(k)] : 0;
    const size_t o = static_cast<size_t>(k) < out_n.size() ? out_n[static_cast<size_t>(k)] : 0;
    if (e > 0 && o == 0)
      fail = "the output has no point of " + class_name(labels, k) + " (the exemplar has " + std::to_string(e) + ")";
    else if (e == 0 && o > 0)
      fail = "the exemplar has no " + class_name(labels, k) + " (the output has " + std::to_string(o) + " points of it)";
    else if (e == 0 && o == 0)
      none = "neither pattern has a point of " + class_name(labels, k);
  }
  if (!fail.empty()) {
    outcome = "fail";
    return fail;
  }
  if (!none.empty()) outcome = "cannot judge";
  return none;
}

}  // namespace

void check_verdict_options(const VerdictOptions& o) {
  if (o.split < 1 || o.split > 20) throw InputError("verdict split (--verdict-split) must be in 1..20");
  if (!(o.guard >= 0 && o.guard <= 0.9)) throw InputError("verdict guard (--verdict-guard) must be in [0, 0.9]");
  if (!(o.alpha > 0 && o.alpha < 1)) throw InputError("verdict alpha (--verdict-alpha) must be in (0, 1)");
  if (o.permutations < 1 || o.permutations > 1000000)
    throw InputError("verdict permutations (--verdict-permutations) must be in 1..1000000");
  // p is at least 1 / (1 + permutations): with fewer, no output could fail.
  if (!(1.0 / (1.0 + o.permutations) < o.alpha)) {
    const long need = static_cast<long>(std::floor(1.0 / o.alpha));
    throw InputError("verdict permutations (--verdict-permutations) " + std::to_string(o.permutations) +
                     " cannot give a p below alpha " + fmt(o.alpha) + " (the smallest p is 1 / (1 + permutations)); give at least " +
                     std::to_string(need));
  }
  if (o.r_values < 2 || o.r_values > 10000) throw InputError("verdict r values must be in 2..10000");
  if (!(o.zoom >= 0) || !std::isfinite(o.zoom)) throw InputError("zoom (--zoom) must be a number >= 0");
}

json verdict(const PointSet& exemplar, const PointSet& output_in, const VerdictOptions& opt) {
  check_verdict_options(opt);
  if (exemplar.empty() || output_in.empty()) throw InputError("verdict: the exemplar and the output need points");
  const ClassMatch match = match_classes(exemplar, output_in);
  const PointSet& output = match.output;
  const double zoom = opt.zoom > 0 ? opt.zoom : density_zoom(exemplar, output);
  const Domain E = exemplar.domain(), O = output.domain();
  // Both patterns in units of the sub-window's shorter side (exemplar units / `unit`): K,
  // its sums and the threshold of evidence are then the same at any coordinate scale.
  const double ax = E.width() / opt.split, ay = E.height() / opt.split;  // a cell, exemplar units
  const double sw = ax * (1 - opt.guard), sh = ay * (1 - opt.guard);
  const double unit = std::min(sw, sh);
  const PointSet ex = exemplar.mapped_to(Domain{0, 0, E.width() / unit, E.height() / unit});
  const PointSet out = output.mapped_to(Domain{0, 0, O.width() / zoom / unit, O.height() / zoom / unit});
  const std::vector<Domain> ex_w = sub_windows(ex.domain(), ax / unit, ay / unit, opt.guard);
  const int block = kOutputBlockPerExemplarSide * opt.split;
  const std::vector<Domain> out_w = sub_windows(out.domain(), ax / unit, ay / unit, opt.guard, block, block, opt.seed);

  std::vector<PointSet> subs;
  for (const Domain& w : ex_w) subs.push_back(ex.crop(w));
  for (const Domain& w : out_w) subs.push_back(out.crop(w));

  const int K = match.exemplar_classes;
  const int K_all = std::max(output.num_classes(), K);
  std::vector<RowSpec> specs{{"all"}};
  if (K > 1 || !match.missing.empty() || !match.extra.empty()) {
    for (int k = 0; k < K; ++k) specs.push_back({"class", k});
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b) specs.push_back({"pair", a, b});
    for (int k = K; k < K_all; ++k) specs.push_back({"class", k});
  }
  const std::vector<size_t> ex_n = exemplar.class_counts(), out_n = output.class_counts();

  json rows = json::array();
  size_t failed = 0, undecided = 0;
  for (const RowSpec& spec : specs) {
    json row = {{"row", spec.row}};
    if (spec.row == "class") {
      row["class"] = spec.ci;
      row["label"] = output.class_label(spec.ci);
    } else if (spec.row == "pair") {
      row["ci"] = spec.ci;
      row["cj"] = spec.cj;
      row["labels"] = {output.class_label(spec.ci), output.class_label(spec.cj)};
    }
    const size_t index = rows.size();
    auto finish = [&](json&& r) {
      if (r["outcome"] == "fail") ++failed;
      if (r["outcome"] == "cannot judge") ++undecided;
      rows.push_back(std::move(r));
    };
    std::string outcome;
    if (const std::string why = presence(spec, ex_n, out_n, output, outcome); !why.empty()) {
      row["units"] = {0, 0};
      decide(row, outcome, why);
      finish(std::move(row));
      continue;
    }
    std::vector<RowPoints> points;
    std::vector<char> first;
    for (size_t u = 0; u < subs.size(); ++u)
      if (auto p = row_points(subs[u], spec)) {
        points.push_back(std::move(*p));
        first.push_back(u < ex_w.size());
      }
    const size_t n1 = static_cast<size_t>(std::count(first.begin(), first.end(), 1)), n2 = points.size() - n1;
    row["units"] = {n1, n2};
    if (n1 < 2 || n2 < 2) {
      decide(row, "cannot judge",
             "needs 2 sub-windows with points in each pattern (" + std::to_string(n1) + " in the exemplar, " +
                 std::to_string(n2) + " in the output)");
      finish(std::move(row));
      continue;
    }
    // The exact test's smallest p: one reassignment in C (two when the groups are of one size,
    // as T is the same with the groups swapped). Monte Carlo cannot go below it either.
    const double assignments = choose(n1 + n2, n1);
    const double floor_p = (n1 == n2 ? 2.0 : 1.0) / assignments;
    if (!(floor_p < opt.alpha)) {
      decide(row, "cannot judge",
             std::to_string(n1) + " + " + std::to_string(n2) + " sub-windows have " + fmt(assignments, "%.0f") +
                 " reassignments: p cannot fall below " + fmt(floor_p) + ", not below alpha " + fmt(opt.alpha));
      finish(std::move(row));
      continue;
    }
    // r_max: spatstat's quarter of the sub-window's side, extended toward half of it until
    // at least half of the exemplar's sub-windows hold a pair of the row within it (else the
    // exemplar's K is 0 at every radius, and a pattern with no close pairs "matches" it).
    std::vector<double> closest;
    for (size_t u = 0; u < points.size(); ++u)
      if (first[u]) closest.push_back(closest_pair(points[u], spec));
    auto holding = [&](double r) {
      return static_cast<size_t>(std::count_if(closest.begin(), closest.end(), [&](double d) { return d <= r; }));
    };
    double r_max = 0;
    for (double f : kRMaxLadder)
      if (2 * holding(f) >= n1) {
        r_max = f;
        break;
      }
    if (r_max == 0 && holding(kRMaxLadder[4]) > 0) r_max = kRMaxLadder[4];
    if (r_max == 0) {
      decide(row, "cannot judge",
             "no two points of the row lie within half a sub-window's side (" + fmt(0.5 * unit) +
                 " exemplar units) in any of the exemplar's sub-windows: its K is 0 at every radius");
      finish(std::move(row));
      continue;
    }
    row["r_max"] = r_max * unit;
    row["r_max_sides"] = r_max;
    Curve r(static_cast<size_t>(opt.r_values)), dr(r.size(), r_max / opt.r_values);
    for (size_t k = 0; k < r.size(); ++k) r[k] = r_max * static_cast<double>(k + 1) / opt.r_values;
    std::vector<Curve> curves;
    curves.reserve(points.size());
    for (const RowPoints& p : points) curves.push_back(row_curve(p, spec, r));
    const Studentized observed = studentized(curves, first, dr);
    if (observed.radii == 0) {
      decide(row, "cannot judge", "every sub-window's K is the same at every radius up to r_max: no radius carries evidence");
      finish(std::move(row));
      continue;
    }
    const double t = observed.t;
    // One generator per row, seeded from the row's place: rows do not shift one another.
    std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + index);
    std::vector<char> perm = first;
    size_t beyond = 0;
    for (int p = 0; p < opt.permutations; ++p) {
      // Fisher-Yates on the labels (uniform over reassignments with the groups' sizes).
      for (size_t i = perm.size() - 1; i > 0; --i) {
        const size_t j = static_cast<size_t>(rng() % (i + 1));
        std::swap(perm[i], perm[j]);
      }
      if (studentized(curves, perm, dr).t >= t * (1 - 1e-12)) ++beyond;
    }
    const double pv = (1.0 + static_cast<double>(beyond)) / (1.0 + opt.permutations);
    row["statistic"] = t;
    row["p"] = pv;
    row["pass"] = pv >= opt.alpha;
    row["outcome"] = pv >= opt.alpha ? "pass" : "fail";
    finish(std::move(row));
  }
  const json passed = failed > 0 ? json(false) : undecided > 0 ? json(nullptr) : json(true);
  return {{"test", "studentized permutation test of equal K-functions over sub-windows (Hahn 2012)"},
          {"statistic", "K, translation correction, in units of the sub-window's shorter side"},
          {"split", opt.split},
          {"guard", opt.guard},
          {"zoom", zoom},
          {"sub_window", {sw, sh}},
          {"r_max", 0.25 * unit},
          {"r_rule", "a quarter of the sub-window's shorter side (spatstat's), extended by sixteenths up to half of it "
                     "until half of the exemplar's sub-windows hold a pair of the row; no pair within half: cannot judge"},
          {"permutations", opt.permutations},
          {"seed", opt.seed},
          {"alpha", opt.alpha},
          {"classes", class_match_json(match)},
          {"rows", rows},
          {"failed", failed},
          {"cannot_judge", undecided},
          {"passed", passed}};
}

std::string verdict_row_name(const json& row) {
  const std::string kind = row["row"].get<std::string>();
  if (kind == "all") return "all classes";
  if (kind == "class") return "class " + std::to_string(row["label"].get<int>());
  if (row.contains("labels"))
    return "pair " + std::to_string(row["labels"][0].get<int>()) + "-" + std::to_string(row["labels"][1].get<int>());
  return "pair " + std::to_string(row["ci"].get<int>()) + "-" + std::to_string(row["cj"].get<int>());
}

std::string format_verdict(const json& v) {
  std::ostringstream os;
  os << "verdict: " << v.value("test", std::string()) << ", " << v["split"].get<int>() << " x " << v["split"].get<int>()
     << " sub-windows of the exemplar (" << fmt(v["sub_window"][0].get<double>()) << " x "
     << fmt(v["sub_window"][1].get<double>()) << " exemplar units), r up to " << fmt(v["r_max"].get<double>())
     << " (more where a row's exemplar holds no pair within it), " << v["permutations"].get<int>()
     << " permutations; pass: p >= " << fmt(v["alpha"].get<double>()) << "\n";
  const double base = v["r_max"].get<double>();
  for (const auto& row : v["rows"]) {
    const std::string name = verdict_row_name(row);
    const std::string outcome = row.value("outcome", std::string(row["p"].is_null() ? "cannot judge" : "pass"));
    char line[512];
    if (row["p"].is_null()) {
      std::snprintf(line, sizeof line, "  %-14s  %s: %s\n", name.c_str(), outcome == "fail" ? "FAIL" : "cannot judge",
                    row["reason"].get<std::string>().c_str());
    } else {
      std::string r_note;
      if (row.contains("r_max") && row["r_max"].get<double>() > base * (1 + 1e-9))
        r_note = "; r up to " + fmt(row["r_max"].get<double>());
      std::snprintf(line, sizeof line, "  %-14s  p = %.4f  %s  (%zu + %zu sub-windows%s)\n", name.c_str(), row["p"].get<double>(),
                    row["pass"].get<bool>() ? "pass" : "FAIL", row["units"][0].get<size_t>(), row["units"][1].get<size_t>(),
                    r_note.c_str());
    }
    os << line;
  }
  const size_t n = v["rows"].size();
  if (v.contains("passed")) {
    if (v["passed"].is_null())
      os << "  verdict: cannot judge (" << v.value("cannot_judge", size_t(0)) << " of " << n << " rows; none fails)\n";
    else if (v["passed"].get<bool>())
      os << "  verdict: pass (every row)\n";
    else
      os << "  verdict: FAIL (" << v.value("failed", size_t(0)) << " of " << n << " rows)\n";
  }
  if (v.contains("classes")) {
    const std::string w = class_match_warning(v["classes"]);
    if (!w.empty()) os << "  " << w << "\n";
  }
  return os.str();
}

}  // namespace ppsynth
