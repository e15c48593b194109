// method.measure "tiles" and "rolled" (optim/gabor/stages/random_tiles.hpp): the u x u torus cut into
// exemplar-sized tiles at a random offset, each measured as the exemplar is, or rolled under
// the whole grid. The cut partitions the points and keeps their gradient; a tile holding the
// exemplar itself has the exemplar's loss (zero); the roll wraps and keeps the gradient; both
// runs resume bit for bit; and the key is refused where it has no meaning.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "core/generators/lattices.hpp"
#include "core/output_shape.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/method/method.hpp"
#include "optim/gabor/stages/random_tiles.hpp"
#include "optim/run/run_config.hpp"
#include "optim/gabor/stages/synthesis_state.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;
using ppsynth::test::method_params;
using ppsynth::test::same_bits;

TEST_CASE("the cut partitions the torus's points into u x u tiles, each in its own unit square", "[optim][tiles]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unif(0, 1);
  for (int u : {1, 2, 3}) {
    INFO("u " << u);
    auto pts = torch::empty({300, 2}, torch::kFloat32);
    for (int64_t i = 0; i < 300; ++i) pts[i][0] = unif(rng), pts[i][1] = unif(rng);
    pts.set_requires_grad(true);
    const auto off = tile_offset(17, 2, 40, u);
    CHECK(off.first >= 0);
    CHECK(off.first < 1.0 / u);
    CHECK(off.second >= 0);
    CHECK(off.second < 1.0 / u);
    const auto tiles = cut_into_tiles(pts, u, off);
    CHECK(static_cast<int>(tiles.size()) <= u * u);
    std::vector<int> seen(300, 0);
    torch::Tensor sum;
    for (size_t t = 0; t < tiles.size(); ++t) {
      const auto rows = tiles[t].rows.accessor<int64_t, 1>();
      const auto loc_t = tiles[t].local.detach();
      const auto loc = loc_t.accessor<float, 2>();
      // the tile's corner: where its first point lies, back on the torus
      for (int64_t r = 0; r < rows.size(0); ++r) {
        ++seen[rows[r]];
        CHECK(loc[r][0] >= 0.0f);
        CHECK(loc[r][0] < 1.0f + 1e-6f);
        CHECK(loc[r][1] >= 0.0f);
        CHECK(loc[r][1] < 1.0f + 1e-6f);
      }
      const auto s = tiles[t].local.sum();
      sum = sum.defined() ? sum + s : s;
    }
    for (int k : seen) CHECK(k == 1);
    // Back from a tile to the torus: p = frac(offset + (corner + local) / u), so neighbors
    // within a tile are neighbors on the torus (the scale is u, nothing else).
    for (const auto& t : tiles) {
      const auto rows = t.rows.accessor<int64_t, 1>();
      const auto loc_t = t.local.detach().to(torch::kFloat64), p_t = pts.detach().to(torch::kFloat64);
      const auto loc = loc_t.accessor<double, 2>();
      const auto p = p_t.accessor<double, 2>();
      const double cx = std::floor(std::fmod(p[rows[0]][0] - off.first + 1.0, 1.0) * u),
                   cy = std::floor(std::fmod(p[rows[0]][1] - off.second + 1.0, 1.0) * u);
      for (int64_t r = 0; r < rows.size(0); ++r) {
        const double x = std::fmod(off.first + (cx + loc[r][0]) / u, 1.0);
        const double y = std::fmod(off.second + (cy + loc[r][1]) / u, 1.0);
        CHECK(std::min(std::abs(x - p[rows[r]][0]), 1 - std::abs(x - p[rows[r]][0])) < 1e-5);
        CHECK(std::min(std::abs(y - p[rows[r]][1]), 1 - std::abs(y - p[rows[r]][1])) < 1e-5);
      }
    }
    sum.backward();  // d local / d p = u for every point and axis
    CHECK(torch::allclose(pts.grad(), torch::full_like(pts, static_cast<float>(u))));
  }
  // the offset is a function of (seed, stage, iteration): the same cut on a resume, another
  // at the next iteration
  CHECK(tile_offset(17, 2, 40, 2) == tile_offset(17, 2, 40, 2));
  CHECK(tile_offset(17, 2, 40, 2) != tile_offset(17, 2, 41, 2));
  CHECK(tile_offset(17, 2, 40, 2) != tile_offset(18, 2, 40, 2));
}

TEST_CASE("the rolled torus: frac(p - offset), every point in the unit square, the gradient kept", "[optim][tiles]") {
  auto pts = torch::tensor({{0.05, 0.9}, {0.5, 0.5}, {0.99, 0.01}}, torch::kFloat32).set_requires_grad(true);
  const auto off = tile_offset(17, 2, 40, 1);
  CHECK(off.first < 1.0);
  CHECK(off.second < 1.0);
  const auto r = roll_torus(pts, {0.1, 0.2});
  const auto a = r.detach();
  CHECK(a[0][0].item<float>() == Approx(0.95));
  CHECK(a[0][1].item<float>() == Approx(0.7));
  CHECK(a[1][0].item<float>() == Approx(0.4));
  CHECK(a[2][0].item<float>() == Approx(0.89));
  CHECK(a[2][1].item<float>() == Approx(0.81));
  CHECK(a.min().item<float>() >= 0.0f);
  CHECK(a.max().item<float>() < 1.0f);
  (r * torch::tensor({{1.0, 2.0}}, torch::kFloat32)).sum().backward();
  CHECK(torch::equal(pts.grad(), torch::tensor({{1.0, 2.0}, {1.0, 2.0}, {1.0, 2.0}}, torch::kFloat32)));
}

TEST_CASE("a tile holding the exemplar itself has the exemplar's loss: zero, where the whole grid's is not", "[optim][tiles]") {
  const PointSet ex = test::small_exemplar(1, false);
  json p = method_params(json{{"type", "gabor"}, {"measure", "tiles"}, {"jitter", false}});
  p["grid"]["res"] = 32;
  p["feature_net"]["channels"] = 8;
  OutputShape shape;
  shape.upscale = 2;
  const GaborSettings s = resolve_gabor_settings(p, ex, shape, false);
  REQUIRE(s.measure_tiles());
  GaborPipeline pipe(s, 9);
  pipe.set_targets(positions_tensor(ex), {}, s.sigmas.back());
  // The output: the exemplar tiled 2 x 2 on the unit square (each copy zoomed out by 2).
  auto ex_xy = positions_tensor(ex, torch::kFloat64);
  std::vector<torch::Tensor> copies;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) copies.push_back((ex_xy + torch::tensor({{double(i), double(j)}}, torch::kFloat64)) / 2);
  const auto out = torch::cat(copies).to(torch::kFloat32);
  const auto tiles = cut_into_tiles(out, 2, {0.0, 0.0});
  REQUIRE(tiles.size() == 4u);
  double tiled = 0;
  for (const auto& t : tiles) tiled += pipe.loss(pipe.features(pipe.tile_maps(t.local, {}, s.sigmas.back(), {}))).item<double>() / 4;
  const double exemplar_own = pipe.loss(pipe.features(pipe.tile_maps(positions_tensor(ex), {}, s.sigmas.back(), {}))).item<double>();
  CHECK(exemplar_own == 0.0);
  CHECK(tiled < 1e-9);
  // Cut elsewhere, the tiles hold other windows of the periodic pattern: a loss above zero.
  double shifted = 0;
  for (const auto& t : cut_into_tiles(out, 2, {0.13, 0.31}))
    shifted += pipe.loss(pipe.features(pipe.tile_maps(t.local, {}, s.sigmas.back(), {}))).item<double>() / 4;
  CHECK(shifted > 1e3 * std::max(tiled, 1e-12));

  // A tile holding fewer points than the exemplar's k (16 here: every exemplar point) divides
  // as the exemplar does, by 16, not by its own 12: a point weighs what it weighs there.
  const auto twelve = positions_tensor(ex).slice(0, 0, 12);
  GaborMapsOptions o;
  o.res = 32;
  GaborFeatureMaps own_count(o);  // divides by min(k, 12) = 12
  const auto by_own = own_count->forward(twelve, {}, s.sigmas.back(), {});
  CHECK(torch::allclose(pipe.tile_maps(twelve, {}, s.sigmas.back(), {}), by_own * (12.0 / 16.0), 1e-5, 1e-7));
}

TEST_CASE("a tiles or rolled run resumes from any checkpoint bit for bit, and differs from the whole grid's", "[optim][tiles][checkpoint]") {
  const std::string measure = GENERATE(as<std::string>{}, "tiles", "rolled");
  for (auto [classes, disks] : {std::pair{1, false}, std::pair{2, true}}) {
    INFO(measure << ", " << classes << " classes, disks " << disks);
    const PointSet ex = test::small_exemplar(classes, disks);
    auto run = [&](const std::string& measure, const std::string* resume, std::vector<std::string>* saved) {
      // class_own (on by default) measures the unrolled grid: the paper's loss alone here
      auto r = test::checkpointed_run(json{{"type", "gabor"}, {"measure", measure}, {"map_terms", {{"class_own", {{"weight", 0}}}}},
                                           {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 6}, {"num_sigmas", 2}}}},
                                      ex, 5, resume);
      if (saved) *saved = std::move(r.checkpoints);
      return r.output;
    };
    std::vector<std::string> cps;
    const PointSet whole = run(measure, nullptr, &cps);
    REQUIRE(cps.size() > 8);
    for (size_t i : {size_t{2}, cps.size() / 2, cps.size() - 2}) {
      INFO("checkpoint " << i);
      CHECK(same_bits(run(measure, &cps[i], nullptr), whole));
    }
    CHECK(same_bits(run(measure, nullptr, nullptr), whole));  // the offsets are the seed's, not a clock's
    CHECK_FALSE(same_bits(run("grid", nullptr, nullptr), whole));
    CHECK_FALSE(same_bits(run(measure == "tiles" ? "rolled" : "tiles", nullptr, nullptr), whole));
    for (size_t i = 0; i < whole.size(); ++i) CHECK(whole.domain().contains(whole[i], 0.0));
  }
}

TEST_CASE("method.measure is refused where it means nothing, naming the key", "[optim][tiles]") {
  const PointSet ex = test::small_exemplar(1, false);
  OutputShape square;
  square.upscale = 2;
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(json{{"type", "gabor"}, {"measure", "quadrants"}}), ex, square, false),
                    Catch::Contains("method.measure"));
  const OutputShape rect = resolve_output_shape(resolve_run_config(json{{"output", {{"size", {2, 2}}}}}, {}), ex);
  for (const char* measure : {"tiles", "rolled"}) {
    INFO(measure);
    CHECK_THROWS_WITH(resolve_gabor_settings(method_params(json{{"type", "gabor"}, {"measure", measure}}), ex, rect, false),
                      Catch::Contains("method.measure"));
    const json own = method_params(json{{"type", "gabor"}, {"measure", measure}, {"map_terms", {{"class_own", {{"weight", 1}}}}}});
    CHECK_THROWS_WITH(resolve_gabor_settings(own, test::small_exemplar(2, false), square, false), Catch::Contains("method.map_terms"));
    // On one class the per-class term acts on nothing, and nothing refuses it.
    CHECK(resolve_gabor_settings(own, ex, square, false).options.measure != GaborOptions::Measure::grid);
  }
  CHECK(resolve_gabor_settings(method_params(json{{"type", "gabor"}, {"measure", "rolled"}}), ex, square, false).options.measure ==
        GaborOptions::Measure::rolled);
}
