// The field's estimators (core/metrics/second_order.hpp, mark_correlation.hpp) against R's
// spatstat on the same patterns: real data sets exported from spatstat.data by
// scripts/spatstat_export.R, summarized by scripts/spatstat_summaries.R. Skipped, saying why,
// where R or spatstat is not installed (scripts/setup.sh installs them).
//
// Tolerances (what was measured, with margin):
//   r grids       equal to 1e-12 relative (the same arithmetic)
//   K, L          1e-9 relative to the curve's maximum (the same sums, summed in another order)
//   g, cross g    |difference| <= 0.01 + 0.02 |g| from the 5th radius on, and a median
//                 difference <= 2e-3: spatstat's density() bins the distances onto 1024
//                 points before smoothing, ppsynth sums the kernel exactly. Measured: a
//                 median of 3e-4..8e-4 on the four data sets; the largest, 1.6 % of g, where
//                 redwood's coordinates (rounded to 0.01) put many pairs at one distance
//                 (binning moves such a point mass most); at the first radii (g ~ 1/r)
//                 redwood differs by 0.2, which is why they are left out
//   mark corr.    1e-3 absolute (measured 1.2e-4: the same binning, in a ratio where most of
//                 it cancels)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/formats/point_io.hpp"
#include "core/metrics/mark_correlation.hpp"
#include "core/metrics/second_order.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;

namespace {

const std::string kSource = PPSYNTH_SOURCE_DIR;

// Why spatstat cannot be asked here, or "" when it can.
std::string spatstat_missing() {
  const auto r = test::run_program("Rscript", "-e 'suppressMessages(library(spatstat.explore)); library(spatstat.data)'");
  if (r.status == 0) return "";
  return "R with spatstat.explore and spatstat.data is not installed (scripts/setup.sh installs them): " + r.output;
}

using Curves = std::map<std::string, std::vector<double>>;

// scripts/spatstat_summaries.R's lines: "NAME [I J] CORRECTION v...".
Curves spatstat_curves(const std::string& file) {
  const auto res = test::run_program("Rscript", kSource + "/scripts/spatstat_summaries.R " + file);
  REQUIRE(res.status == 0);
  Curves c;
  std::istringstream in(res.output);
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string name, key, tok;
    s >> name;
    key = name;
    const int extra = name.find("cross") != std::string::npos ? 3 : 1;  // I J CORRECTION, or CORRECTION
    for (int e = 0; e < extra && s >> tok; ++e) key += " " + tok;
    std::vector<double> v;
    while (s >> tok) v.push_back(tok == "Inf" ? INFINITY : tok == "NaN" || tok == "NA" ? NAN : std::stod(tok));
    c[key] = v;
  }
  return c;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, std::abs(x));
  return m;
}

void same_grid(const std::vector<double>& ours, const std::vector<double>& theirs) {
  REQUIRE(ours.size() == theirs.size());
  for (size_t k = 0; k < ours.size(); ++k) REQUIRE(ours[k] == Approx(theirs[k]).epsilon(1e-12).margin(1e-15));
}

void same_k(const std::vector<double>& ours, const std::vector<double>& theirs) {
  REQUIRE(ours.size() == theirs.size());
  const double tol = 1e-9 * max_abs(theirs);
  for (size_t k = 0; k < ours.size(); ++k) {
    INFO("r index " << k);
    REQUIRE(std::abs(ours[k] - theirs[k]) <= tol);
  }
}

// From the 5th radius on (g(0) is 1/0, and near it 1/r magnifies the binning of R's
// density()): each difference within 0.01 + 0.02 |g|, the median within 2e-3.
void close_g(const std::vector<double>& ours, const std::vector<double>& theirs) {
  REQUIRE(ours.size() == theirs.size());
  std::vector<double> diff;
  for (size_t k = 4; k < ours.size(); ++k) {
    REQUIRE(std::isfinite(ours[k]));
    INFO("r index " << k << ": ours " << ours[k] << ", spatstat's " << theirs[k]);
    CHECK(std::abs(ours[k] - theirs[k]) <= 0.01 + 0.02 * std::abs(theirs[k]));
    diff.push_back(std::abs(ours[k] - theirs[k]));
  }
  std::sort(diff.begin(), diff.end());
  INFO("median difference " << diff[diff.size() / 2]);
  CHECK(diff[diff.size() / 2] <= 2e-3);
}

}  // namespace

TEST_CASE("edge weights: the isotropic weight is 1 inside, 2 on an edge, 4 in a corner; translation is |W| / overlap",
          "[metrics][spatstat]") {
  const Domain w{0, 0, 2, 1};
  CHECK(isotropic_weight(w, {1, 0.5}, 0.3) == Approx(1.0));
  CHECK(isotropic_weight(w, {1, 0.0}, 0.3) == Approx(2.0));
  CHECK(isotropic_weight(w, {0, 0}, 0.3) == Approx(4.0));
  CHECK(isotropic_weight(w, {1e-9, 0}, 0.3) == Approx(4.0));  // spatstat: 4 at and beside a corner
  // A circle reaching one edge at half its radius: the arc beyond it is 2 acos(1/2) = 120 degrees.
  CHECK(isotropic_weight(w, {1, 0.15}, 0.3) == Approx(1.0 / (1.0 - 1.0 / 3.0)));
  // Near a corner inside the circle: each edge's outer half arc, acos(d / r), plus the two
  // inner halves, which stop at the corner's direction (45 degrees each): the quarter beyond
  // the corner is counted once.
  const double d = 0.1, r = 0.3;
  const double beyond = 2 * std::acos(d / r) + M_PI / 2;
  CHECK(isotropic_weight(w, {d, d}, r) == Approx(1.0 / (1.0 - beyond / (2 * M_PI))).epsilon(1e-12));
  CHECK(translation_weight(w, 0.5, -0.25) == Approx(2.0 / (1.5 * 0.75)));
  CHECK(translation_weight(w, 1.999, 0.999) == kMaxEdgeWeight);
}

TEST_CASE("K, L and g of a regular grid: no pair below the spacing, K jumps there", "[metrics][spatstat]") {
  PointSet ps(Domain{0, 0, 1, 1});
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) ps.add({0.05 + 0.1 * i, 0.05 + 0.1 * j});
  const SecondOrder s = second_order(ps, nullptr, EdgeCorrection::Translation);
  REQUIRE(s.r.size() == kSpatstatRValues);
  CHECK(s.r.back() == Approx(0.25));
  for (size_t k = 0; k < s.r.size(); ++k) {
    if (s.r[k] < 0.1 - 1e-9) CHECK(s.k[k] == 0.0);
    if (s.r[k] < 0.1 - s.bandwidth && s.r[k] > 0) CHECK(s.g[k] == 0.0);
  }
  CHECK(s.bandwidth == Approx(0.015));
}

TEST_CASE("K, L, g, cross-type K, L, g and the mark correlation agree with spatstat on its own data sets",
          "[metrics][spatstat]") {
  const std::string why = spatstat_missing();
  if (!why.empty()) {
    WARN("skipped: " << why);
    return;
  }
  const auto dir = test::scratch_dir("spatstat_estimators");
  const auto exp = test::run_program("Rscript", kSource + "/scripts/spatstat_export.R " + dir.string() +
                                                    " redwood swedishpines amacrine longleaf");
  INFO(exp.output);
  REQUIRE(exp.status == 0);
  for (const std::string name : {"redwood", "swedishpines", "amacrine", "longleaf"}) {
    INFO("data set " << name);
    const std::string file = (dir / (name + ".txt")).string();
    const PointSet ps = read_points(file);
    const Curves ref = spatstat_curves(file);
    for (const EdgeCorrection c : {EdgeCorrection::Isotropic, EdgeCorrection::Translation}) {
      const std::string corr = c == EdgeCorrection::Isotropic ? "iso" : "trans";
      INFO("correction " << corr);
      const SecondOrder s = second_order(ps, nullptr, c);
      same_grid(s.r, ref.at("r -"));
      same_grid(s.r, ref.at("rg -"));
      same_k(s.k, ref.at("K " + corr));
      same_k(s.l, ref.at("L " + corr));
      close_g(s.g, ref.at("g " + corr));
      if (ps.num_classes() > 1) {
        for (int i = 0; i < ps.num_classes(); ++i)
          for (int j = 0; j < ps.num_classes(); ++j) {
            if (i == j) continue;
            const std::string ij = " " + std::to_string(i) + " " + std::to_string(j) + " ";
            INFO("types " << ij);
            const PointSet a = ps.subset_class(i), b = ps.subset_class(j);
            const SecondOrder x = second_order(a, &b, c);
            same_grid(x.r, ref.at("rcross" + ij + "-"));
            same_k(x.k, ref.at("Kcross" + ij + corr));
            close_g(x.g, ref.at("gcross" + ij + corr));
          }
      }
      if (auto m = ps.attribute_index("mark")) {
        const MarkCorrelation mc = mark_correlation(ps, static_cast<size_t>(*m), c);
        same_grid(mc.r, ref.at("rmark -"));
        const auto& theirs = ref.at("markcorr " + corr);
        double worst = 0;
        for (size_t k = 0; k < mc.k.size(); ++k) worst = std::max(worst, std::abs(mc.k[k] - theirs[k]));
        INFO("largest mark correlation difference " << worst);
        CHECK(worst <= 1e-3);
      }
    }
  }
}
