#include "optim/gabor/stages/random_tiles.hpp"

#include <random>

namespace ppsynth {

std::pair<double, double> tile_offset(uint64_t seed, int stage, int iteration, int u) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), static_cast<uint32_t>(stage),
                    static_cast<uint32_t>(iteration), 0x7113u};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unif(0.0, 1.0 / u);
  const double ox = unif(rng);
  return {ox, unif(rng)};
}

torch::Tensor roll_torus(const torch::Tensor& points, std::pair<double, double> offset) {
  const auto shift = torch::tensor({{offset.first, offset.second}}, points.options().requires_grad(false));
  const auto s = points - shift;
  return s - torch::floor(s).detach();
}

std::vector<Tile> cut_into_tiles(const torch::Tensor& points, int u, std::pair<double, double> offset) {
  const auto s = roll_torus(points, offset);
  const auto cell = torch::clamp(torch::floor(s.detach() * u), 0, u - 1).to(torch::kInt64);  // N x 2
  const auto id = cell.select(1, 1) * u + cell.select(1, 0);
  std::vector<Tile> tiles;
  for (int64_t t = 0; t < static_cast<int64_t>(u) * u; ++t) {
    const auto rows = torch::nonzero(id == t).flatten();
    if (rows.numel() == 0) continue;
    const auto corner = torch::tensor({{static_cast<double>(t % u), static_cast<double>(t / u)}}, points.options().requires_grad(false));
    tiles.push_back({rows, s.index_select(0, rows) * u - corner});
  }
  return tiles;
}

}  // namespace ppsynth
