#include "core/generators/ccvt.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/config/params.hpp"
#include "core/generators/generator.hpp"
#include "core/generators/sampling_util.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/memory_budget.hpp"
#include "core/log.hpp"
#include "core/neighbors.hpp"

namespace ppsynth {

namespace {

double dist2(Vec2 a, Vec2 b, const Domain& d) {
  Vec2 v = gen_detail::torus_delta(a, b, d);
  return v.x * v.x + v.y * v.y;
}

// Initial capacity-respecting assignment: samples in random order go to the nearest site
// (among its nearest few) that still has room, else to any site with room.
std::vector<std::vector<size_t>> initial_assignment(const std::vector<Vec2>& samples,
                                                    const PointSet& sites, size_t capacity,
                                                    std::mt19937_64& rng) {
  const size_t n = sites.size();
  NeighborIndex index(sites.positions(), sites.domain(), true);
  std::vector<std::vector<size_t>> owned(n);
  std::vector<size_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<size_t> open(n);  // sites with room, for the fallback
  std::iota(open.begin(), open.end(), 0);
  for (size_t s : order) {
    size_t chosen = n;
    for (size_t i : index.knn(samples[s], std::min<size_t>(n, 16)))
      if (owned[i].size() < capacity) {
        chosen = i;
        break;
      }
    if (chosen == n) {
      while (owned[open.back()].size() >= capacity) open.pop_back();
      chosen = open.back();
    }
    owned[chosen].push_back(s);
  }
  return owned;
}

}  // namespace

PointSet ccvt_points(size_t n, uint64_t seed, Domain d, const CcvtOptions& opt) {
  gen_detail::check_domain(d, "ccvt");
  if (opt.points_per_site < 1) throw config_error("ccvt.points_per_site", "must be >= 1");
  if (opt.max_iterations < 0) throw config_error("ccvt.max_iterations", "must be >= 0");
  if (opt.neighbor_sites < 1) throw config_error("ccvt.neighbor_sites", "must be >= 1");
  // n x points_per_site samples (a PointSet row and an owner index each)
  check_memory(static_cast<double>(n) * opt.points_per_site * 120.0,
               "ccvt with " + std::to_string(n) + " sites x points_per_site " + std::to_string(opt.points_per_site));
  std::mt19937_64 rng(seed);
  PointSet sites = uniform_points(n, rng(), d);
  if (n < 2) return sites;
  const size_t capacity = static_cast<size_t>(opt.points_per_site);
  std::vector<Vec2> samples = jittered_grid_points(n * capacity, rng(), d).positions();
  auto owned = initial_assignment(samples, sites, capacity, rng);

  auto move_to_centroids = [&]() {
    for (size_t i = 0; i < n; ++i) {
      Vec2 m{0, 0};
      for (size_t s : owned[i]) {
        Vec2 v = gen_detail::torus_delta(sites[i], samples[s], d);
        m.x += v.x;
        m.y += v.y;
      }
      const double c = static_cast<double>(owned[i].size());
      sites[i] = gen_detail::wrap({sites[i].x + m.x / c, sites[i].y + m.y / c}, d);
    }
  };
  move_to_centroids();

  // changed[i]: site i swapped samples in the previous iteration. A pair of unchanged sites
  // has the same samples and positions as when it was last found stable: it is skipped.
  std::vector<char> changed(n, 1), now(n, 0);
  std::vector<std::pair<double, size_t>> gi, gj;
  for (int it = 0; it < opt.max_iterations; ++it) {
    NeighborIndex index(sites.positions(), d, true);
    std::fill(now.begin(), now.end(), 0);
    size_t swaps = 0;
    for (size_t i = 0; i < n; ++i) {
      for (size_t j : index.knn(sites[i], std::min<size_t>(n, opt.neighbor_sites + 1))) {
        if (j == i || (!changed[i] && !changed[j])) continue;
        // Pairs are visited from both ends (the k-nearest relation is not symmetric).
        // Gain of moving a sample from i to j (and vice versa): positive = closer to the other.
        gi.clear();
        gj.clear();
        for (size_t k = 0; k < owned[i].size(); ++k) {
          Vec2 x = samples[owned[i][k]];
          gi.push_back({dist2(x, sites[i], d) - dist2(x, sites[j], d), k});
        }
        for (size_t k = 0; k < owned[j].size(); ++k) {
          Vec2 x = samples[owned[j][k]];
          gj.push_back({dist2(x, sites[j], d) - dist2(x, sites[i], d), k});
        }
        // Max-heaps (Balzer et al.): pop the best pair while swapping it lowers the energy,
        // i.e. while the two gains sum to > 0.
        std::make_heap(gi.begin(), gi.end());
        std::make_heap(gj.begin(), gj.end());
        while (!gi.empty() && !gj.empty() && gi.front().first + gj.front().first > 0) {
          std::swap(owned[i][gi.front().second], owned[j][gj.front().second]);
          std::pop_heap(gi.begin(), gi.end());
          gi.pop_back();
          std::pop_heap(gj.begin(), gj.end());
          gj.pop_back();
          now[i] = now[j] = 1;
          ++swaps;
        }
      }
    }
    move_to_centroids();
    changed.swap(now);
    spdlog::debug("ccvt: iteration {} swaps {}", it, swaps);
    if (swaps == 0) break;
  }
  return sites;
}

namespace {
struct CcvtGen : PointGenerator {
  CcvtOptions opt;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return ccvt_points(n, seed, d, opt);
  }
};
}  // namespace

}  // namespace ppsynth

namespace ppsynth {
const ParamTable<CcvtOptions>& CcvtOptions::params() {
  using O = CcvtOptions;
  static const ParamTable<O> t("generator", {
      param("points_per_site", &O::points_per_site, "int [1, 1000000]", "each site's capacity: the discrete points it owns"),
      param("max_iterations", &O::max_iterations, "int [0, inf)", "swap rounds at most (it stops sooner when none swaps)"),
      param("neighbor_sites", &O::neighbor_sites, "int [1, 1000]", "the nearest sites each site tries swaps with"),
  });
  return t;
}
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "ccvt", ppsynth::CcvtOptions::params(),
                        "capacity-constrained Voronoi tessellation (Balzer et al. 2009), discrete, toroidal",
                        [](const ppsynth::CcvtOptions& o, const std::string&) {
                          auto g = std::make_unique<ppsynth::CcvtGen>();
                          g->opt = o;
                          return g;
                        })
