// The verdict answers only what it can judge (core/metrics/verdict.hpp): a row is pass, fail or
// "cannot judge" with the reason, and "passed" is null, never true, when a row cannot judge;
// r_max reaches the exemplar's pairs; permutation counts and group sizes that cannot give a p
// below alpha are refused or cannot judge; classes are matched by label, and one missing from
// the output or extra in it fails; the test is the same at any coordinate scale.
#include <catch2/catch.hpp>

#include <utility>

#include "core/error.hpp"
#include "core/generators/poisson_disk.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/class_match.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/verdict.hpp"

using namespace ppsynth;
using nlohmann::json;

namespace {

VerdictOptions fast_options() {
  VerdictOptions o;
  o.permutations = 199;
  o.zoom = 1;
  return o;
}

PointSet two_classes(const PointSet& a, const PointSet& b) {
  PointSet ps(a.domain());
  for (size_t i = 0; i < a.size(); ++i) ps.add(a[i], 0);
  for (size_t i = 0; i < b.size(); ++i) ps.add(b[i], 1);
  return ps;
}

// A square lattice of spacing 0.15 over `d`, each point moved by up to 0.015 along each axis
// (seeded): no two points closer than 0.12.
PointSet lattice(Domain d, uint64_t seed) {
  const double h = 0.15;
  const PointSet jitter = uniform_points(10000, seed, Domain{-0.015, -0.015, 0.015, 0.015});
  PointSet ps(d);
  size_t i = 0;
  for (double y = d.y0 + h / 2; y < d.y1; y += h)
    for (double x = d.x0 + h / 2; x < d.x1; x += h, ++i) ps.add({x + jitter[i].x, y + jitter[i].y});
  return ps;
}

PointSet scaled(const PointSet& ps, double s) {
  const Domain d = ps.domain();
  return ps.mapped_to(Domain{d.x0 * s, d.y0 * s, d.x1 * s, d.y1 * s});
}

const json& row_of(const json& v, const std::string& kind, int label) {
  for (const auto& r : v["rows"])
    if (r["row"] == kind && (kind == "all" || r["label"] == label)) return r;
  FAIL("no row " << kind << " " << label << " in " << v.dump());
  return v;
}

}  // namespace

TEST_CASE("verdict: a pattern with no pair within a quarter sub-window is judged farther, never passed vacuously",
          "[metrics][verdict][verdict_honest]") {
  // Spacing 0.15 against r_max = a quarter of the 0.45-wide sub-windows (0.1125): spatstat's
  // rule alone sees K = 0 everywhere in both groups and gave p = 1 with statistic 0.
  const PointSet ex = lattice(Domain{}, 1);
  const VerdictOptions o = fast_options();
  const json same = verdict(ex, lattice(Domain{0, 0, 2, 2}, 2), o);
  const json& all = same["rows"][0];
  CHECK(all["r_max"].get<double>() > 0.1125 * 1.2);
  CHECK(all["r_max"].get<double>() <= 0.225 + 1e-12);
  CHECK(same["r_rule"].get<std::string>().find("half") != std::string::npos);
  REQUIRE(all["outcome"] == "pass");
  CHECK(all["statistic"].get<double>() > 0);
  // Uniform points of the lattice's density fail against it.
  int rejected = 0;
  for (uint64_t d = 0; d < 10; ++d)
    if (verdict(ex, uniform_points(4 * ex.size(), 40 + d, Domain{0, 0, 2, 2}), o)["rows"][0]["outcome"] == "fail") ++rejected;
  INFO(rejected << " of 10 uniform draws rejected");
  CHECK(rejected >= 8);

  // Two points per sub-window in opposite corners (0.62 apart): no pair within half a side
  // (0.225) anywhere in the exemplar: it cannot judge, and the verdict is not a pass.
  PointSet corners(Domain{});
  for (double cx : {0.0, 0.5})
    for (double cy : {0.0, 0.5}) {
      corners.add({cx + 0.03, cy + 0.03});
      corners.add({cx + 0.47, cy + 0.47});
    }
  const json none = verdict(corners, uniform_points(32, 7, Domain{0, 0, 2, 2}), o);
  CHECK(none["rows"][0]["outcome"] == "cannot judge");
  CHECK(none["rows"][0]["pass"].is_null());
  CHECK(none["rows"][0]["p"].is_null());
  CHECK(none["rows"][0]["reason"].get<std::string>().find("no two points") != std::string::npos);
  CHECK(none["passed"].is_null());
  CHECK(format_verdict(none).find("cannot judge") != std::string::npos);
}

TEST_CASE("verdict: permutations and groups too few for p to reach alpha are refused or cannot judge",
          "[metrics][verdict][verdict_honest]") {
  const PointSet ex = poisson_disk_points(80, 1);
  VerdictOptions o = fast_options();
  o.permutations = 19;  // p >= 1/20 = alpha: no output could fail
  CHECK_THROWS_WITH(verdict(ex, uniform_points(320, 2, Domain{0, 0, 2, 2}), o),
                    Catch::Contains("--verdict-permutations") && Catch::Contains("at least 20"));
  o.permutations = 20;
  CHECK_NOTHROW(verdict(ex, uniform_points(320, 2, Domain{0, 0, 2, 2}), o));
  o.alpha = 0.01;  // 20 permutations: p >= 1/21
  CHECK_THROWS_WITH(verdict(ex, uniform_points(320, 2, Domain{0, 0, 2, 2}), o), Catch::Contains("at least 100"));

  // 4 exemplar sub-windows against 2 of the output: 15 reassignments, p >= 1/15 > 0.05.
  o = fast_options();
  const json v = verdict(ex, uniform_points(40, 3, Domain{0, 0, 1, 0.5}), o);
  CHECK(v["rows"][0]["units"] == json({4, 2}));
  CHECK(v["rows"][0]["outcome"] == "cannot judge");
  CHECK(v["rows"][0]["reason"].get<std::string>().find("15 reassignments") != std::string::npos);
  CHECK(v["passed"].is_null());
}

TEST_CASE("verdict: passed is true when every row passes, false when one fails, with an outcome per row",
          "[metrics][verdict][verdict_honest]") {
  const PointSet ex = two_classes(poisson_disk_points(60, 1), poisson_disk_points(60, 2));
  const Domain d{0, 0, 2, 2};
  const VerdictOptions o = fast_options();
  const json good = verdict(ex, two_classes(poisson_disk_points(240, 3, d), poisson_disk_points(240, 5, d)), o);
  for (const auto& r : good["rows"]) CHECK(r["outcome"] == "pass");
  CHECK(good["passed"] == true);
  const json bad = verdict(ex, two_classes(poisson_disk_points(240, 3, d), uniform_points(240, 4, d)), o);
  CHECK(row_of(bad, "class", 1)["outcome"] == "fail");
  CHECK(bad["passed"] == false);
  CHECK(format_verdict(bad).find("verdict: FAIL") != std::string::npos);
}

TEST_CASE("verdict: a class missing from the output or extra in it fails its row, naming the label",
          "[metrics][verdict][verdict_honest][evaluation]") {
  const PointSet ex = two_classes(poisson_disk_points(60, 1), poisson_disk_points(60, 2));
  const Domain d{0, 0, 2, 2};
  const PointSet out = two_classes(poisson_disk_points(240, 3, d), poisson_disk_points(240, 5, d));
  const VerdictOptions o = fast_options();

  const PointSet only0 = out.subset_class(0);
  const json missing = verdict(ex, only0, o);
  CHECK(row_of(missing, "class", 1)["outcome"] == "fail");
  CHECK(row_of(missing, "class", 1)["pass"] == false);
  CHECK(row_of(missing, "class", 1)["reason"].get<std::string>().find("no point of class 1") != std::string::npos);
  CHECK(missing["passed"] == false);
  EvalOptions eo;
  eo.verdict_options.permutations = 99;
  const json e = evaluate(ex, only0, eo);
  CHECK(e["verdict"]["passed"] == false);
  CHECK(e["classes_matched"]["missing"] == json({1}));
  CHECK(format_evaluation(e).find("the output has no point of class 1") != std::string::npos);

  PointSet extra = out;
  for (size_t i = 0; i < 40; ++i) extra.add(uniform_points(40, 9, d)[i], 2);
  const json v = verdict(ex, extra, o);
  CHECK(row_of(v, "class", 2)["outcome"] == "fail");
  CHECK(row_of(v, "class", 2)["reason"].get<std::string>().find("the exemplar has no class 2") != std::string::npos);
  CHECK(v["classes"]["extra"] == json({2}));
  CHECK(v["passed"] == false);

  // One class each: matched whatever the labels (a Gabor file's 1000 against a plain 0).
  PointSet labelled = poisson_disk_points(80, 1);
  labelled.set_class_labels({1000});
  const json one = verdict(labelled, poisson_disk_points(320, 6, d), o);
  CHECK(one["rows"].size() == 1);
  CHECK(one["classes"]["by"] == "the only class of each");
  CHECK(one["passed"] == true);
}

TEST_CASE("evaluate: classes are matched by label, not by their index in the file", "[metrics][verdict_honest][evaluation]") {
  PointSet ex = two_classes(poisson_disk_points(50, 1), uniform_points(50, 2));
  ex.set_class_labels({1000, 2000});
  const Domain d{0, 0, 2, 2};
  PointSet out = two_classes(poisson_disk_points(200, 3, d), uniform_points(200, 4, d));
  out.set_class_labels({1000, 2000});
  // The same points with the ids swapped and the labels listed the other way round.
  PointSet swapped = out;
  for (size_t i = 0; i < swapped.size(); ++i) swapped.set_cls(i, 1 - out.cls(i));
  swapped.set_class_labels({2000, 1000});
  EvalOptions eo;
  eo.verdict_options.permutations = 99;
  eo.include_curves = false;
  const json a = evaluate(ex, out, eo), b = evaluate(ex, swapped, eo);
  for (int k = 0; k < 2; ++k) {
    CHECK(b["classes"][k]["label"] == a["classes"][k]["label"]);
    CHECK(b["classes"][k]["pcf_mse"] == a["classes"][k]["pcf_mse"]);
  }
  CHECK(b["cross"] == a["cross"]);
  CHECK(b["verdict"] == a["verdict"]);
  CHECK(b["second_order"]["rows"] == a["second_order"]["rows"]);
  CHECK(b["classes_matched"]["missing"].empty());
  CHECK(b["classes_matched"]["extra"].empty());
  CHECK(b["classes_matched"]["by"] == "label");
  // A file that names no labels (a bare class column 0, 1) is matched by index, and says so.
  PointSet bare = out;
  bare.set_class_labels({});
  const json c = evaluate(ex, bare, eo);
  CHECK(c["classes_matched"]["by"] == "index (the output names no class labels)");
  CHECK(c["verdict"]["rows"] == a["verdict"]["rows"]);
  CHECK(c["classes"][1]["label"] == 2000);
}

TEST_CASE("verdict: the same p at any coordinate scale", "[metrics][verdict][verdict_honest]") {
  const PointSet ex = poisson_disk_points(80, 11);
  const PointSet out = uniform_points(320, 12, Domain{0, 0, 2, 2});
  VerdictOptions o = fast_options();
  o.zoom = 0;  // from the densities, as eval does
  const json unit = verdict(ex, out, o);
  REQUIRE(unit["rows"][0]["outcome"] == "fail");
  for (double s : {1e-75, 1e80}) {
    INFO("scale " << s);
    const json v = verdict(scaled(ex, s), scaled(out, s), o);
    CHECK(v["rows"][0]["p"] == unit["rows"][0]["p"]);
    CHECK(v["rows"][0]["statistic"].get<double>() == Approx(unit["rows"][0]["statistic"].get<double>()).epsilon(1e-9));
    CHECK(v["passed"] == false);
    EvalOptions eo;
    eo.verdict_options = fast_options();
    eo.second_order = false;
    eo.include_curves = false;
    CHECK(evaluate(scaled(ex, s), scaled(out, s), eo)["verdict"]["rows"][0]["p"] == unit["rows"][0]["p"]);
  }
}
