#include "core/generators/lattices.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/generators/generator.hpp"
#include "core/generators/sampling_util.hpp"

namespace ppsynth {

namespace {

struct GridShape {
  size_t cols, rows;
};

GridShape grid_shape(size_t n, const Domain& d) {
  size_t cols = std::max<size_t>(1, static_cast<size_t>(std::ceil(std::sqrt(n * d.width() / d.height()) - 1e-9)));
  size_t rows = std::max<size_t>(1, (n + cols - 1) / cols);
  return {cols, rows};
}

// Which cells get a point: all when they are exactly n, else a seeded random subset.
std::vector<size_t> chosen_cells(size_t n, size_t cells, std::mt19937_64& rng) {
  std::vector<size_t> idx(cells);
  std::iota(idx.begin(), idx.end(), 0);
  if (cells > n) {
    std::shuffle(idx.begin(), idx.end(), rng);
    idx.resize(n);
    std::sort(idx.begin(), idx.end());
  }
  return idx;
}

PointSet grid_points(size_t n, uint64_t seed, const Domain& d, double jitter, const char* who) {
  gen_detail::check_domain(d, who);
  if (!(jitter >= 0 && jitter <= 1)) throw config_error(std::string(who) + ".jitter", "must be in [0, 1]");
  PointSet ps(d);
  if (n == 0) return ps;
  std::mt19937_64 rng(seed);
  const GridShape g = grid_shape(n, d);
  const double cw = d.width() / g.cols, ch = d.height() / g.rows;
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  ps.reserve(n);
  for (size_t c : chosen_cells(n, g.cols * g.rows, rng)) {
    const size_t cx = c % g.cols, cy = c / g.cols;
    double ox = 0, oy = 0;
    if (jitter > 0) {
      ox = jitter * u(rng);
      oy = jitter * u(rng);
    }
    double x = d.x0 + (cx + 0.5 + ox) * cw, y = d.y0 + (cy + 0.5 + oy) * ch;
    ps.add({std::min(std::max(x, d.x0), d.x1), std::min(std::max(y, d.y0), d.y1)});
  }
  return ps;
}

}  // namespace

PointSet jittered_grid_points(size_t n, uint64_t seed, Domain d, double jitter) {
  return grid_points(n, seed, d, jitter, "jittered_grid");
}

PointSet regular_grid_points(size_t n, uint64_t seed, Domain d) {
  return grid_points(n, seed, d, 0.0, "regular_grid");
}

PointSet hexagonal_lattice_exact(size_t cols, size_t rows, Domain d) {
  gen_detail::check_domain(d, "hexagonal_lattice");
  if (cols == 0 || rows == 0 || rows % 2 != 0)
    throw InputError("hexagonal_lattice: need cols >= 1 and an even, positive number of rows");
  PointSet ps(d);
  ps.reserve(cols * rows);
  const double a = d.width() / cols, h = d.height() / rows;
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < cols; ++c)
      ps.add({d.x0 + (c + 0.25 + 0.5 * (r % 2)) * a, d.y0 + (r + 0.5) * h});
  return ps;
}

Domain hexagonal_domain(size_t cols, size_t rows) {
  return Domain{0, 0, 1, rows * std::sqrt(3.0) / (2.0 * cols), true};
}

PointSet hexagonal_lattice_points(size_t n, uint64_t seed, Domain d, bool random_offset) {
  gen_detail::check_domain(d, "hexagonal_lattice");
  if (n == 0) return PointSet(d);
  // n ~ cols * rows with rows * (a sqrt(3)/2) = H, a = W / cols.
  const double ratio = d.height() / d.width();
  // n = cols * rows and rows = ratio * cols * 2 / sqrt(3)  =>  cols = sqrt(n sqrt(3) / (2 ratio)).
  size_t cols = std::max<size_t>(1, static_cast<size_t>(std::lround(std::sqrt(n * std::sqrt(3.0) / (2.0 * ratio)))));
  size_t rows = static_cast<size_t>(std::lround(ratio * cols * 2.0 / std::sqrt(3.0)));
  rows = std::max<size_t>(2, rows + (rows % 2));
  PointSet ps = hexagonal_lattice_exact(cols, rows, d);
  if (random_offset) {
    std::mt19937_64 rng(seed);
    Vec2 off = gen_detail::uniform_in(rng, Domain{0, 0, d.width(), d.height()});
    for (auto& p : ps.positions()) p = gen_detail::wrap({p.x + off.x, p.y + off.y}, d);
  }
  return ps;
}

namespace {
struct JitteredGen : PointGenerator {
  double jitter = 1;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return jittered_grid_points(n, seed, d, jitter);
  }
  static const ParamTable<JitteredGen>& params() {
    static const ParamTable<JitteredGen> t(
        "generator", {param("jitter", &JitteredGen::jitter, "[0, 1]", "how far a point moves in its cell (1: anywhere in it)")});
    return t;
  }
};
struct RegularGen : PointGenerator {
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return regular_grid_points(n, seed, d);
  }
  static const ParamTable<RegularGen>& params() {
    static const ParamTable<RegularGen> t("generator", {});
    return t;
  }
};
struct HexGen : PointGenerator {
  bool random_offset = false;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return hexagonal_lattice_points(n, seed, d, random_offset);
  }
  static const ParamTable<HexGen>& params() {
    static const ParamTable<HexGen> t(
        "generator", {param("random_offset", &HexGen::random_offset, "", "the lattice shifted by a seeded random offset")});
    return t;
  }
};
}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "jittered_grid", ppsynth::JitteredGen::params(),
                        "one uniform point per grid cell (jitter 1 = whole cell)",
                        [](const ppsynth::JitteredGen& g, const std::string&) { return std::make_unique<ppsynth::JitteredGen>(g); })
PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "regular_grid", ppsynth::RegularGen::params(),
                        "cell centers of a regular grid",
                        [](const ppsynth::RegularGen& g, const std::string&) { return std::make_unique<ppsynth::RegularGen>(g); })
PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "hexagonal_lattice", ppsynth::HexGen::params(),
                        "hexagonal (triangular) lattice with torus-compatible spacing; point count close to n",
                        [](const ppsynth::HexGen& g, const std::string&) { return std::make_unique<ppsynth::HexGen>(g); })
