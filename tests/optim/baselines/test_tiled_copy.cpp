// The copy baseline (method "tiled_copy"): u x u copies of the exemplar with classes and
// attributes (radii / u), a seeded torus offset, and the quadrant metric's two extremes: an
// offset of [0, 0] puts one exact copy in each quadrant (every quadrant metric 0), a shifted
// copy is the same pattern cut differently.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/quadrant.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;

namespace {

PointSet exemplar() {
  PointSet ex;
  ex.add_attribute("radius");
  const auto a = uniform_points(10, 3), b = uniform_points(6, 4);
  for (size_t i = 0; i < a.size(); ++i) ex.add(a[i], 0, {0.01 * (1 + i % 3)});
  for (size_t i = 0; i < b.size(); ++i) ex.add(b[i], 1, {0.02});
  return ex;
}

PointSet run(const nlohmann::json& params, uint64_t seed, int upscale = 2) {
  SynthesisContext ctx;
  ctx.seed = seed;
  ctx.output.upscale = upscale;
  nlohmann::json spec = {{"type", "tiled_copy"}};
  spec.update(params);
  return MethodRegistry::instance().create(spec, "method")->synthesize(exemplar(), ctx);
}

}  // namespace

TEST_CASE("tiled_copy: u x u copies with classes and radii / u", "[baselines][tiled_copy]") {
  const auto ex = exemplar();
  const auto out = run({{"offset", {0.0, 0.0}}}, 1, 3);
  REQUIRE(out.size() == 9 * ex.size());
  const int r = *out.attribute_index("radius");
  // Tile (a, b) holds point i at ((x + a) / 3, (y + b) / 3), in the exemplar's order.
  const size_t tile = 1 * 3 + 2, i = 4;
  const size_t k = tile * ex.size() + i;
  CHECK(out[k].x == Approx((ex[i].x + 1) / 3));
  CHECK(out[k].y == Approx((ex[i].y + 2) / 3));
  CHECK(out.cls(k) == ex.cls(i));
  CHECK(out.attr(k, r) == Approx(ex.attr(i, r) / 3));
}

TEST_CASE("tiled_copy: quadrant metrics 0 when aligned, seeded offsets otherwise", "[baselines][tiled_copy]") {
  const auto ex = exemplar();
  const auto aligned = run({{"offset", {0.0, 0.0}}}, 1);
  CHECK(quadrant_metrics(ex.subset_class(0), aligned.subset_class(0)).pcf_mse == Approx(0).margin(1e-12));
  CHECK(quadrant_metrics(ex, aligned).chamfer == Approx(0).margin(1e-12));
  const auto a = run(nlohmann::json::object(), 7), b = run(nlohmann::json::object(), 7), c = run(nlohmann::json::object(), 8);
  REQUIRE(a.size() == c.size());
  CHECK(a[0].x == b[0].x);
  CHECK(a[0].x != c[0].x);
  CHECK(quadrant_metrics(ex, a).chamfer > 0);  // shifted copies are cut by the quadrants
  CHECK_THROWS_WITH(run({{"offset", "center"}}, 1), Catch::Contains("method.offset"));
  CHECK_THROWS_AS(run({{"offset", {0.1}}}, 1), InputError);
}
