// The evaluation protocols (core/metrics/eval_protocol.hpp): the paper's quadrants for u = 2
// squares, exemplar-sized crops for rectangles and other sizes; border share on rectangles.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/matern_cluster.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/border.hpp"
#include "core/metrics/crops.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/quadrant.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

EvalOptions no_curves(PatchProtocol p = PatchProtocol::Auto) {
  EvalOptions o;
  o.include_curves = false;
  o.protocol = p;
  return o;
}

// Exemplar: a 64-point jittered grid of cell 1/8. Outputs in exemplar units: the same cell.
PointSet exemplar64(uint64_t seed = 1) { return jittered_grid_points(64, seed); }
PointSet jittered_output(double w, double h, uint64_t seed) {
  return jittered_grid_points(static_cast<size_t>(std::lround(64 * w * h)), seed, Domain{0, 0, w, h});
}

}  // namespace

TEST_CASE("crops at a given zoom: the output's own scale, not its density's", "[metrics][protocol]") {
  const PointSet ex = exemplar64();
  // 4 x 1 exemplar units holding 10 % more points than the exemplar's density: the densities
  // say zoom 0.95 (crops holding 64 points); the run that made it says 1 (crops of its scale).
  const PointSet out = jittered_grid_points(282, 5, Domain{0, 0, 4, 1});
  const CropPlan by_density = plan_crops(ex, out, 20, 7);
  CHECK(by_density.zoom == Approx(std::sqrt(256.0 / 282.0)));
  const CropPlan given = plan_crops(ex, out, 20, 7, 1.0);
  CHECK(given.zoom == 1.0);
  for (const Domain& w : given.windows) {
    CHECK(w.width() == Approx(1.0));
    CHECK(w.height() == Approx(1.0));
  }
  EvalOptions o;
  o.protocol = PatchProtocol::Crops;
  o.include_curves = false;
  o.zoom = 1.0;
  CHECK(evaluate(ex, out, o)["protocol"]["zoom"].get<double>() == 1.0);
  o.zoom = 0;
  CHECK(evaluate(ex, out, o)["protocol"]["zoom"].get<double>() == Approx(by_density.zoom));
  o.zoom = -1;
  CHECK_THROWS_WITH(evaluate(ex, out, o), Catch::Contains("--zoom"));
}

TEST_CASE("crops: exemplar-sized windows inside the output, the same for a seed", "[metrics][protocol]") {
  const PointSet ex = exemplar64();
  const PointSet out = jittered_output(4, 1, 2);
  const CropPlan a = plan_crops(ex, out, 20, 7), b = plan_crops(ex, out, 20, 7), c = plan_crops(ex, out, 20, 8);
  REQUIRE(a.windows.size() == 20);
  CHECK(a.zoom == Approx(1.0));  // 256 points on 4 x 1 at the exemplar's density
  bool differs = false;
  for (size_t i = 0; i < a.windows.size(); ++i) {
    const Domain& w = a.windows[i];
    CHECK(w.x0 == b.windows[i].x0);
    CHECK(w.y0 == b.windows[i].y0);
    differs = differs || w.x0 != c.windows[i].x0;
    CHECK(w.x0 >= 0);
    CHECK(w.x1 <= 4);
    CHECK(w.y0 >= 0);
    CHECK(w.y1 <= 1);
    CHECK(w.width() == Approx(1.0));
    CHECK(w.height() == Approx(1.0));
  }
  CHECK(differs);
  // The whole evaluation is a function of the seed.
  EvalOptions o = no_curves(PatchProtocol::Crops);
  o.crop_seed = 7;
  const auto r1 = evaluate(ex, out, o), r2 = evaluate(ex, out, o);
  CHECK(r1.dump() == r2.dump());
  CHECK(r1["protocol"]["name"] == "crops");
  CHECK(r1["protocol"]["patches"] == 20);
  CHECK(r1["protocol"]["seed"] == 7);
  CHECK(r1["protocol"]["windows"].size() == 20);
  CHECK(r1["protocol"]["crop_size"][0].get<double>() == Approx(1.0));
  const auto& all = r1["all"];
  REQUIRE(all["per_crop"]["pcf_mse"].size() == 20);
  CHECK(all["per_crop"]["chamfer"].size() == 20);
  const auto q = all["pcf_mse_quartiles"];
  CHECK(q[0].get<double>() <= q[1].get<double>());
  CHECK(q[1].get<double>() <= q[2].get<double>());
  // The mean is the mean of the per-crop values.
  double sum = 0;
  for (const auto& v : all["per_crop"]["pcf_mse"]) sum += v.get<double>();
  CHECK(all["pcf_mse"].get<double>() == Approx(sum / 20).epsilon(1e-12));
}

TEST_CASE("crops: a larger jittered grid matches the exemplar, a clustered output does not", "[metrics][protocol]") {
  // The floor: the exemplar against other 64-point jittered grids on its own square.
  const PointSet ex = exemplar64(11);
  double floor = 0;
  for (uint64_t s = 0; s < 5; ++s) floor += quadrant_metrics(ex, jittered_grid_points(256, 100 + s)).pcf_mse / 5;
  const Domain d{0, 0, 4, 4};
  MaternClusterOptions mc;
  mc.radius = 0.1;
  for (uint64_t seed : {21, 22, 23}) {
    INFO("seed " << seed);
    const auto good = evaluate(ex, jittered_output(4, 4, seed), no_curves());
    const auto bad = evaluate(ex, matern_cluster_points(1024, seed, d, mc), no_curves());
    const auto white = evaluate(ex, uniform_points(1024, seed, d), no_curves());
    REQUIRE(good["protocol"]["name"] == "crops");  // 16 x the exemplar's points
    const double g = good["all"]["pcf_mse"].get<double>(), b = bad["all"]["pcf_mse"].get<double>(),
                 w = white["all"]["pcf_mse"].get<double>();
    INFO("jittered " << g << " clustered " << b << " uniform " << w << " floor " << floor);
    CHECK(g < 3 * floor);  // the crops see what the exemplar's own square would
    CHECK(b > 10 * g);
    CHECK(w > 3 * g);
    CHECK(good["all"]["chamfer"].get<double>() < bad["all"]["chamfer"].get<double>());
  }
}

TEST_CASE("auto: quadrants for a u = 2 square, crops for a rectangle or another count", "[metrics][protocol]") {
  const PointSet ex = exemplar64();
  const auto square = evaluate(ex, jittered_grid_points(256, 3), no_curves());
  CHECK(square["protocol"]["name"] == "quadrants");
  CHECK(square["protocol"]["patches"] == 4);
  CHECK(square["protocol"]["zoom"].get<double>() == Approx(0.5));
  CHECK(square["all"]["pcf_mse"].get<double>() == quadrant_metrics(ex, jittered_grid_points(256, 3)).pcf_mse);
  CHECK_FALSE(square["all"].contains("per_crop"));
  CHECK(format_evaluation(square).find("protocol: quadrants") != std::string::npos);
  CHECK(format_evaluation(square).find("quadrant metrics   pcf_mse") != std::string::npos);
  const auto strip = evaluate(ex, jittered_output(4, 1, 4), no_curves());
  CHECK(strip["protocol"]["name"] == "crops");
  CHECK(strip["protocol"]["reason"].get<std::string>().find("not square") != std::string::npos);
  const std::string t = format_evaluation(strip);
  CHECK(t.find("protocol: crops, 20 crops") != std::string::npos);
  CHECK(t.find("crop means         pcf_mse") != std::string::npos);
  CHECK(t.find("pcf_mse over the 20 crops") != std::string::npos);
  // A square with 16 x the exemplar's points (exemplar units): crops too.
  CHECK(evaluate(ex, jittered_output(4, 4, 5), no_curves())["protocol"]["name"] == "crops");
  // Asked for, quadrants run on an output of the exemplar's shape (the protocol says it was
  // requested), and are refused on the strip, whose quadrants would be compared squashed.
  const auto forced = evaluate(ex, jittered_output(4, 4, 4), no_curves(PatchProtocol::Quadrants));
  CHECK(forced["protocol"]["name"] == "quadrants");
  CHECK(forced["protocol"]["reason"] == "requested");
  CHECK_THROWS_WITH(evaluate(ex, jittered_output(4, 1, 4), no_curves(PatchProtocol::Quadrants)),
                    Catch::Contains("2 x 0.5") && Catch::Contains("--protocol crops"));
  // Per class and cross-class rows carry their crops too.
  PointSet ex2 = ex, out2 = jittered_output(4, 1, 6);
  for (size_t i = 0; i < ex2.size(); i += 2) ex2.set_cls(i, 1);
  for (size_t i = 0; i < out2.size(); i += 2) out2.set_cls(i, 1);
  const auto two = evaluate(ex2, out2, no_curves());
  REQUIRE(two["classes"].size() == 2);
  CHECK(two["classes"][1]["per_crop"]["pcf_mse"].size() == 20);
  REQUIRE(two["cross"].size() == 1);
  CHECK(two["cross"][0]["pcf_mse_quartiles"].size() == 3);
}

TEST_CASE("bad protocol options and crops that do not fit are refused, naming them", "[metrics][protocol]") {
  EvalOptions o;
  o.crops = 0;
  CHECK_THROWS_WITH(check_eval_options(o), Catch::Contains("--crops"));
  o.crops = kMaxCrops + 1;
  CHECK_THROWS_WITH(check_eval_options(o), Catch::Contains("--crops"));
  CHECK_THROWS_WITH(parse_patch_protocol("tiles"), Catch::Contains("--protocol"));
  CHECK(parse_patch_protocol("crops") == PatchProtocol::Crops);
  // An output smaller than the exemplar at its density: the crop cannot fit.
  const PointSet ex = exemplar64();
  const PointSet small = jittered_output(0.5, 0.5, 3);
  CHECK_THROWS_WITH(evaluate(ex, small, no_curves(PatchProtocol::Crops)), Catch::Contains("0.5 x 0.5"));
  // The command: bad values exit non-zero with the flag named; good ones run.
  const auto dir = ppsynth::test::scratch_dir("eval_protocol_cli");
  const std::string e = (dir / "ex.txt").string(), s = (dir / "strip.txt").string();
  write_points(e, ex);
  write_points(s, jittered_output(4, 1, 9));
  auto bad = ppsynth::test::run_ppsynth("eval --exemplar " + e + " --output " + s + " --protocol tiles");
  CHECK(bad.status != 0);
  CHECK(bad.output.find("--protocol") != std::string::npos);
  bad = ppsynth::test::run_ppsynth("eval --exemplar " + e + " --output " + s + " --crops 0");
  CHECK(bad.status != 0);
  CHECK(bad.output.find("--crops") != std::string::npos);
  const auto ok = ppsynth::test::run_ppsynth("eval --exemplar " + e + " --output " + s +
                                             " --protocol crops --crops 5 --crop-seed 3 --json --no-curves");
  REQUIRE(ok.status == 0);
  const auto j = nlohmann::json::parse(ok.output);
  CHECK(j["protocol"]["patches"] == 5);
  CHECK(j["protocol"]["seed"] == 3);
  fs::remove_all(dir);
}

TEST_CASE("border share on rectangles: 1 % of the shorter side, with the uniform expectation", "[metrics][protocol]") {
  CHECK(uniform_border_fraction(Domain{}) == Approx(1 - 0.98 * 0.98));
  const Domain strip{0, 0, 4, 1};
  CHECK(border_band(strip) == Approx(0.01));
  CHECK(uniform_border_fraction(strip) == Approx(1 - 3.98 * 0.98 / 4));
  // Monte-Carlo: uniform points land in the band as often as its share of the area says.
  for (const Domain& d : {strip, Domain{0, 0, 10, 10}, Domain{-1, 2, 0.5, 2.25}}) {
    const PointSet ps = uniform_points(200000, 17, d);
    const double p = uniform_border_fraction(d), sd = std::sqrt(p * (1 - p) / 200000);
    INFO("domain " << d.width() << " x " << d.height() << ": expected " << p);
    CHECK(std::abs(border_fraction(ps) - p) < 4 * sd);
  }
  const auto r = evaluate(exemplar64(), jittered_output(4, 1, 2), no_curves());
  CHECK(r["output"]["border_fraction_uniform"].get<double>() == Approx(uniform_border_fraction(strip)));
  CHECK(r["exemplar"]["border_fraction_uniform"].get<double>() == Approx(0.0396));
  CHECK(format_evaluation(r).find("  if uniform") != std::string::npos);
}

TEST_CASE("the border profile tells a pile on the edge from a thin seam behind it", "[metrics][protocol]") {
  // Uniform points read 1 in every band, on a square and on a strip.
  for (const Domain& d : {Domain{}, Domain{0, 0, 4, 1}}) {
    const BorderProfile u = border_profile(uniform_points(200000, 5, d));
    REQUIRE(u.band == std::vector<double>{0.005, 0.01, 0.02, 0.04});
    for (double v : u.over_uniform) CHECK(v == Approx(1).margin(0.04));
  }
  // A pile within 0.3 % of the edge with nothing behind it: 100 points on a lattice of the
  // inside (0.05 .. 0.95) and 8 on the edge. The 0.5 % band holds the pile (8 of 108, 3.7 x
  // uniform's 1.99 % of the area); the 4 % band holds the pile and no lattice point (0.48 x).
  PointSet ps;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) ps.add({0.05 + 0.1 * i, 0.05 + 0.1 * j});
  for (int k = 0; k < 8; ++k) ps.add({0.06 + 0.12 * k, k % 2 ? 0.002 : 0.997});
  const BorderProfile p = border_profile(ps);
  const double share = 8.0 / 108;
  CHECK(p.share[0] == Approx(share));
  CHECK(p.over_uniform[0] == Approx(share / (1 - 0.99 * 0.99)));
  CHECK(p.over_uniform[3] == Approx(share / (1 - 0.92 * 0.92)));
  CHECK(p.over_uniform[0] > 1);  // the pile
  CHECK(p.over_uniform[3] < 1);  // the seam behind it, thinner than uniform
  CHECK(std::isnan(border_profile(PointSet{}).over_uniform[0]));
  // In evaluate's JSON and table, and border_fraction is the profile's 1 % band.
  const auto r = evaluate(ps, ps, no_curves());
  CHECK(r["output"]["border_profile"]["over_uniform"][1].get<double>() ==
        Approx(r["output"]["border_fraction"].get<double>() / r["output"]["border_fraction_uniform"].get<double>()));
  CHECK(format_evaluation(r).find("  within 0.5 %") != std::string::npos);
}

TEST_CASE("crops: an output at the exemplar's height with a point or two fewer than its share still fits",
          "[metrics][protocol]") {
  // A 2 x 1 output of a 1 x 1 exemplar (64 points) holds 126 points instead of 128: the
  // densities read a crop 0.8 % taller than the output, well inside the counts' spread (about
  // 7 %). The crop is then the largest of the exemplar's shape that fits.
  const PointSet ex = exemplar64();
  const PointSet out = jittered_grid_points(126, 5, Domain{0, 0, 2, 1});
  CHECK(density_zoom(ex, out) > 1.0);
  const CropPlan c = plan_crops(ex, out, 5, 3);
  CHECK(c.zoom_fitted);
  CHECK(c.zoom == Approx(1.0));
  CHECK(c.height == Approx(1.0));
  for (const Domain& w : c.windows) CHECK(w.y1 <= out.domain().y1);
  const auto e = evaluate(ex, out, no_curves(PatchProtocol::Crops));
  CHECK(e["protocol"]["zoom"].get<double>() == Approx(1.0));
  // Beyond the spread the output is smaller than the exemplar at its density: refused as before.
  CHECK(density_zoom_spread(ex, out) == Approx(0.5 * std::sqrt(1.0 / 64 + 1.0 / 126)));
  const PointSet short_out = jittered_grid_points(115, 5, Domain{0, 0, 2, 0.9});
  CHECK_THROWS_WITH(plan_crops(ex, short_out, 5, 3), Catch::Contains("smaller than the exemplar"));
  // A zoom the caller gives is taken as given.
  CHECK_THROWS_WITH(plan_crops(ex, out, 5, 3, 1.01), Catch::Contains("smaller than the exemplar"));
}
