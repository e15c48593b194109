#include <fstream>

#include <catch2/catch.hpp>

#include "core/formats/point_io.hpp"
#include "core/paths.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"

using namespace ppsynth;

// The acceptance check: against a jittered-grid exemplar, a jittered-grid output
// ranks above a uniform output on every quadrant metric.
TEST_CASE("evaluate ranks a jittered grid above white noise", "[metrics]") {
  for (uint64_t seed : {1, 2, 3, 4}) {
    INFO("seed " << seed);
    PointSet exemplar = jittered_grid_points(64, seed);
    auto good = evaluate(exemplar, jittered_grid_points(256, seed + 100));
    auto bad = evaluate(exemplar, uniform_points(256, seed + 100));
    for (const char* metric : {"pcf_mse", "wasserstein", "chamfer"}) {
      INFO(metric << ": jittered " << good["all"][metric] << " uniform " << bad["all"][metric]);
      CHECK(good["all"][metric].get<double>() < bad["all"][metric].get<double>());
    }
  }
}

TEST_CASE("evaluate reports counts, classes, cross terms and curves", "[metrics]") {
  PointSet ex = uniform_points(60, 1);
  for (size_t i = 0; i < ex.size(); i += 2) ex.set_cls(i, 1);
  PointSet out = uniform_points(240, 2);
  for (size_t i = 0; i < out.size(); i += 3) out.set_cls(i, 1);
  auto r = evaluate(ex, out);
  CHECK(r["exemplar"]["count"] == 60);
  CHECK(r["output"]["count"] == 240);
  CHECK(r["upscale"].get<double>() == Approx(2.0));
  REQUIRE(r["classes"].size() == 2);
  REQUIRE(r["cross"].size() == 1);
  CHECK(r["cross"][0]["pcf_mse"].get<double>() > 0);
  CHECK(r["all"]["pcf"]["r"].size() == 100);
  CHECK(r["all"]["pcf"]["output"].size() == 100);
  CHECK(r["classes"][1]["pcf"]["exemplar"].size() == 100);
  CHECK(r["all"]["exemplar_points"] == 60);
  CHECK(r["classes"][1]["exemplar_points"] == 30);
  CHECK(format_evaluation(r).find("note: with fewer than") == std::string::npos);
  // A class of 3 exemplar points: the table says how little its row rests on.
  PointSet few = ex;
  for (size_t i = 0; i < few.size(); ++i) few.set_cls(i, i < 3 ? 1 : 0);
  auto rf = evaluate(few, out);
  CHECK(rf["classes"][1]["exemplar_points"] == 3);
  CHECK(format_evaluation(rf).find("note: with fewer than 16 exemplar points") != std::string::npos);
  EvalOptions o;
  o.include_curves = false;
  CHECK_FALSE(evaluate(ex, out, o)["all"].contains("pcf"));
}

// The reference numbers of shared/data/reference/README.md (an independent implementation
// of the protocol on the published code's outputs). Skipped when the shared folder is absent.
TEST_CASE("evaluate reproduces the reference quadrant numbers", "[metrics]") {
  const std::string ex_path = resolve_data_path("shared:data/exemplars/gabor-paper/lines.txt");
  const std::string out_path = resolve_data_path("shared:data/reference/lines/output.txt");
  if (!std::ifstream(ex_path) || !std::ifstream(out_path)) {
    WARN("shared data not found, skipped");
    return;
  }
  EvalOptions o;
  o.include_curves = false;
  auto r = evaluate(read_points(ex_path), read_points(out_path), o);
  CHECK(r["all"]["pcf_mse"].get<double>() == Approx(0.0156).epsilon(0.05));
  CHECK(r["all"]["wasserstein"].get<double>() == Approx(0.112).epsilon(0.01));
  CHECK(r["all"]["chamfer"].get<double>() == Approx(0.195).epsilon(0.01));
  auto p = evaluate(read_points("shared:data/exemplars/gabor-paper/poisson_n64c2_point.txt"),
                    read_points("shared:data/reference/poisson_n64c2_point/output.txt"), o);
  REQUIRE(p["classes"].size() == 2);
  CHECK(p["classes"][0]["pcf_mse"].get<double>() == Approx(0.0116).epsilon(0.05));
  CHECK(p["classes"][1]["pcf_mse"].get<double>() == Approx(0.0095).epsilon(0.05));
}

TEST_CASE("evaluate reports the closest pair on the torus and in the square", "[metrics]") {
  // Two points in opposite corners: neighbors on the torus, far apart in the square.
  PointSet ps;
  ps.add({0.001, 0.001});
  ps.add({0.999, 0.999});
  ps.add({0.5, 0.5});
  auto r = evaluate(ps, ps);
  CHECK(r["output"]["d_min"].get<double>() == Approx(std::sqrt(2.0) * 0.002).margin(1e-9));
  CHECK(r["output"]["d_min_square"].get<double>() == Approx(std::sqrt(2.0) * 0.499).margin(1e-9));
  CHECK(format_evaluation(r).find("d_min_square") != std::string::npos);
  // Two of the three points lie within 1 % of the border.
  CHECK(r["output"]["border_fraction"].get<double>() == Approx(2.0 / 3));
  CHECK(format_evaluation(r).find("border_fraction") != std::string::npos);
}

TEST_CASE("evaluate reports disk overlap per class pair, in JSON and in the table", "[metrics]") {
  PointSet ex;
  ex.add_attribute("radius");
  ex.add({0.2, 0.2}, 0, {0.05});
  ex.add({0.7, 0.2}, 0, {0.05});
  ex.add({0.2, 0.7}, 1, {0.05});
  ex.add({0.7, 0.7}, 1, {0.05});
  PointSet out = ex;  // the same 4 disks (no overlap) plus 2 that overlap class 0 and class 1
  out.add({0.25, 0.2}, 0, {0.05});  // overlaps (0.2, 0.2): a 0-0 pair
  out.add({0.7, 0.66}, 0, {0.05});  // overlaps (0.7, 0.7): a 0-1 pair
  auto r = evaluate(ex, out);
  REQUIRE(r.contains("overlap"));
  const auto& o = r["overlap"]["output"];
  REQUIRE(o.size() == 4);  // all, 0-0, 0-1, 1-1
  CHECK(r["overlap"]["exemplar"][0]["pairs"] == 0);
  CHECK(o[0]["pairs"] == 2);
  CHECK(o[1]["pairs"] == 1);
  CHECK(o[2]["pairs"] == 1);
  CHECK(o[3]["pairs"] == 0);
  const std::string t = format_evaluation(r);
  CHECK(t.find("overlapping disks") != std::string::npos);
  CHECK(t.find("  all classes                   0             2") != std::string::npos);
  CHECK(t.find("  classes 0-1                   0             1") != std::string::npos);
  CHECK(t.find("  classes 1-1                   0             0") != std::string::npos);
}
