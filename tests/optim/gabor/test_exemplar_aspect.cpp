// A rectangular exemplar keeps its aspect ratio (core/output_shape.hpp): with no "output" in
// the run config, a 1.6 x 1 exemplar gets u x u copies of its rectangle in exemplar units, not
// the paper's unit square, which packed its points into a square and squeezed the pattern.
// A square exemplar keeps the paper's unit square.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/metrics/nearest_neighbor.hpp"
#include "core/output_shape.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/synthesize.hpp"

using namespace ppsynth;

namespace {

// A lattice of spacing 0.1 on [0, 1.6] x [0, 1] (two classes in columns): its structure is the
// same along x and along y, so any squeeze shows in the nearest-neighbor vectors.
PointSet lattice(double width, double height) {
  PointSet ex(Domain{0, 0, width, height});
  int col = 0;
  for (double x = 0.05; x < width; x += 0.1, ++col)
    for (double y = 0.05; y < height; y += 0.1) ex.add({x, y}, col % 2);
  return ex;
}

// Mean |dx| and |dy| from each point to its nearest neighbor along each axis (the closest
// point in the same row, and in the same column).
std::pair<double, double> axis_spacings(const PointSet& ps) {
  double sx = 0, sy = 0;
  size_t nx = 0, ny = 0;
  for (size_t i = 0; i < ps.size(); ++i) {
    double bx = INFINITY, by = INFINITY;
    for (size_t j = 0; j < ps.size(); ++j) {
      if (i == j) continue;
      const double dx = std::abs(ps[j].x - ps[i].x), dy = std::abs(ps[j].y - ps[i].y);
      if (dy < 1e-6) bx = std::min(bx, dx);
      if (dx < 1e-6) by = std::min(by, dy);
    }
    if (std::isfinite(bx)) sx += bx, ++nx;
    if (std::isfinite(by)) sy += by, ++ny;
  }
  return {sx / static_cast<double>(nx), sy / static_cast<double>(ny)};
}

}  // namespace

TEST_CASE("a rectangular exemplar with no output key gets u x u copies of its rectangle", "[optim][output][aspect]") {
  const PointSet ex = lattice(1.6, 1.0);
  const nlohmann::json spec = resolve_run_config({{"upscale", 2}}, {});
  const OutputShape shape = resolve_output_shape(spec, ex);
  CHECK(shape.rectangle);
  CHECK(shape.width == Approx(3.2));
  CHECK(shape.height == Approx(2.0));
  CHECK(shape.zoom() == 1.0);
  CHECK(shape.describe().find("2 x 2 copies of the rectangular exemplar") != std::string::npos);
  // u^2 exemplars' points at the exemplar's density.
  CHECK(shape.expected_points(ex) == Approx(4.0 * static_cast<double>(ex.size())).epsilon(0.01));

  // A square exemplar keeps the paper's unit square.
  const OutputShape square = resolve_output_shape(spec, lattice(1.0, 1.0));
  CHECK_FALSE(square.rectangle);
  CHECK(square.domain().width() == 1.0);
  CHECK(square.domain().height() == 1.0);
}

TEST_CASE("a synthesis from a 1.6 x 1 exemplar keeps its aspect and its spacing along both axes",
          "[optim][output][aspect][library]") {
  const PointSet ex = lattice(1.6, 1.0);
  SynthesisOptions options;
  options.quick = true;
  // tiled_copy copies the exemplar's structure exactly: the output shows how the run layer
  // shaped it. The unit square squeezed it 1.6 times along x (spacings 0.031 x 0.05).
  const nlohmann::json spec = resolve_run_config({{"method", {{"type", "tiled_copy"}}}, {"evaluate", false}}, {});
  const SynthesisResult r = synthesize(ex, spec, options);
  const Domain d = r.output.domain();
  CHECK(d.width() / d.height() == Approx(1.6));
  CHECK(d.width() == Approx(3.2));
  const auto [sx, sy] = axis_spacings(r.output);
  CHECK(sx == Approx(0.1).epsilon(1e-6));
  CHECK(sy == Approx(0.1).epsilon(1e-6));

  // The Gabor method (quick settings) on the same exemplar: u x u copies of its rectangle at
  // the exemplar's density. u = 3: the quick grid's coarse maps reach about 1 exemplar unit,
  // and a window must hold that margin on both sides and an interior.
  const nlohmann::json gabor = resolve_run_config({{"upscale", 3}, {"evaluate", false}}, {});
  const SynthesisResult g = synthesize(ex, gabor, options);
  CHECK(g.output.domain().width() == Approx(4.8));
  CHECK(g.output.domain().height() == Approx(3.0));
  const double density_ratio = (static_cast<double>(g.output.size()) / g.output.domain().area()) /
                               (static_cast<double>(ex.size()) / ex.domain().area());
  CHECK(density_ratio == Approx(1.0).epsilon(0.1));
}
