#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/generators/best_candidate.hpp"
#include "core/generators/ccvt.hpp"
#include "core/generators/generator.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/poisson_disk.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/nearest_neighbor.hpp"

using namespace ppsynth;

TEST_CASE("every registered generator is deterministic and stays in its domain", "[generators]") {
  const Domain d{0.5, -1, 2.5, 0};
  auto names = GeneratorRegistry::instance().names();
  for (const char* must : {"uniform", "poisson_disk", "best_candidate", "jittered_grid", "regular_grid",
                           "hexagonal_lattice", "lloyd", "ccvt", "matern_cluster"})
    CHECK(std::find(names.begin(), names.end(), must) != names.end());
  for (const auto& name : names) {
    INFO(name);
    nlohmann::json spec = {{"type", name}};
    if (name == "ccvt") spec["points_per_site"] = 64;  // keep the test fast
    PointSet a = generate_points(spec, 150, 11, d);
    PointSet b = generate_points(spec, 150, 11, d);
    PointSet c = generate_points(spec, 150, 12, d);
    REQUIRE(a.size() == b.size());
    if (name != "hexagonal_lattice") CHECK(a.size() == 150);
    CHECK(a.size() > 120);
    CHECK(a.size() < 180);
    bool same = true, differs = false;
    for (size_t i = 0; i < a.size(); ++i) {
      CHECK(d.contains(a[i], 0.0));
      same = same && a[i].x == b[i].x && a[i].y == b[i].y;
      if (i < c.size()) differs = differs || a[i].x != c[i].x || a[i].y != c[i].y;
    }
    CHECK(same);
    if (name != "regular_grid" && name != "hexagonal_lattice") CHECK(differs);
  }
}

TEST_CASE("generator parameters are validated by name", "[generators]") {
  CHECK_THROWS_AS(generate_points({{"type", "jittered_grid"}, {"jitter", 2.0}}, 10, 1), InputError);
  CHECK_THROWS_AS(generate_points({{"type", "nope"}}, 10, 1), InputError);
  CHECK_THROWS_AS(generate_points({{"type", "ccvt"}, {"unknown", 1}}, 10, 1), InputError);
  PoissonDiskOptions o;
  o.radius = 0.3;
  o.max_attempts = 2000;
  PointSet few = poisson_disk_points(100, 1, Domain{}, o);
  CHECK(few.size() < 100);  // impossible: reports instead of looping forever
  o.require_all = true;
  CHECK_THROWS_AS(poisson_disk_points(100, 1, Domain{}, o), InputError);
}

TEST_CASE("best candidate follows the published initialization window", "[generators]") {
  PointSet ps = best_candidate_points(256, 95);
  for (const auto& p : ps.positions()) {
    CHECK(p.x >= 0.01);
    CHECK(p.x <= 0.99);
    CHECK(p.y >= 0.01);
    CHECK(p.y <= 0.99);
  }
  CHECK(relative_radius(best_candidate_points(256, 95, Domain{}, {10, 0.0})) > 0.6);
}

TEST_CASE("blue-noise quality orders CCVT > Poisson disk > uniform", "[generators]") {
  Domain torus;
  torus.periodic = true;
  for (uint64_t seed : {1, 2}) {
    CcvtOptions co;
    co.points_per_site = 512;
    const double rr_ccvt = relative_radius(ccvt_points(100, seed, torus, co));
    const double rr_pd = relative_radius(poisson_disk_points(100, seed, torus));
    const double rr_uni = relative_radius(uniform_points(100, seed, torus));
    INFO("ccvt " << rr_ccvt << " poisson disk " << rr_pd << " uniform " << rr_uni);
    CHECK(rr_ccvt > rr_pd);
    CHECK(rr_pd > rr_uni);
    CHECK(rr_ccvt > 0.7);
    CHECK(rr_ccvt < 0.8);
  }
}

TEST_CASE("hexagonal lattice spacing tiles the torus", "[generators]") {
  PointSet ps = hexagonal_lattice_exact(12, 14, hexagonal_domain(12, 14));
  CHECK(ps.size() == 168);
  CHECK(min_nn_distance(ps, true) == Approx(1.0 / 12).epsilon(1e-9));
  CHECK(mean_nn_distance(ps, true) == Approx(1.0 / 12).epsilon(1e-9));
  CHECK_THROWS_AS(hexagonal_lattice_exact(4, 3, Domain{}), InputError);
}
