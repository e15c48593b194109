// Mirrored edges (models/mirror_edges.hpp): which points get images, where the images lie,
// that the weights follow them and that the gradient reaches the points through them.
// (The engine's use, on a window run: tests/optim/test_windows.cpp.)
#include <catch2/catch.hpp>

#include <limits>

#include "models/mirror_edges.hpp"

using namespace ppsynth;

TEST_CASE("mirror_edges: images across each edge within reach, corners thrice, gradients through them", "[models][mirror]") {
  // One point near the left edge, one in the lower-left corner, one in the middle.
  auto p = torch::tensor({{0.05, 0.5}, {0.02, 0.04}, {0.5, 0.5}}, torch::kFloat64).set_requires_grad(true);
  auto w = torch::tensor({{1.0}, {2.0}, {3.0}}, torch::kFloat64);
  const MirroredPoints m = mirror_edges(p, w, MirrorEdges{0, 0, 1, 1}, 0.1);
  // 3 points; across x = 0: the first two; across y = 0: the corner point and its x-image.
  REQUIRE(m.points.size(0) == 3 + 2 + 2);
  REQUIRE(m.weights.size(0) == 7);
  const torch::Tensor images = m.points.detach();
  auto a = images.accessor<double, 2>();
  CHECK(a[3][0] == Approx(-0.05));
  CHECK(a[3][1] == Approx(0.5));
  CHECK(a[4][0] == Approx(-0.02));
  CHECK(a[5][1] == Approx(-0.04));  // the corner point across y = 0
  CHECK(a[6][0] == Approx(-0.02));  // and its x-image across y = 0: the corner's third image
  CHECK(a[6][1] == Approx(-0.04));
  auto wa = m.weights.accessor<double, 2>();
  CHECK(wa[3][0] == 1.0);
  CHECK(wa[4][0] == 2.0);
  CHECK(wa[6][0] == 2.0);
  // d(sum of x over all images)/dx: +1 for the point itself, -1 per image reflected in x.
  m.points.select(1, 0).sum().backward();
  const torch::Tensor grad = p.grad();
  auto g = grad.accessor<double, 2>();
  CHECK(g[0][0] == Approx(1 - 1));      // itself, its x-image
  CHECK(g[1][0] == Approx(1 - 1 + 1 - 1));  // itself, x-image, y-image (+), xy-image (-)
  CHECK(g[2][0] == Approx(1));
  CHECK(g[1][1] == Approx(0));  // y appears in no sum

  // An infinite edge is not reflected; nothing within reach: the input itself.
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(mirror_edges(p, w, MirrorEdges{-inf, -inf, inf, inf}, 0.1).points.size(0) == 3);
  CHECK(mirror_edges(p, torch::Tensor(), MirrorEdges{0, 0, 1, 1}, 0.01).points.size(0) == 3);
  CHECK_FALSE(mirror_edges(p, torch::Tensor(), MirrorEdges{0, 0, 1, 1}, 0.1).weights.defined());
}
