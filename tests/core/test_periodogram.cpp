// The 2-D periodogram (core/metrics/periodogram.hpp), its heat map and `ppsynth spectrum`:
// repetition (a tiled copy, a lattice) stands out of the ring; white noise does not.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/periodogram.hpp"
#include "core/render/plot_spectrum.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

// `tile` copied kx x ky times side by side (its domain the tile's multiple).
PointSet tiled(const PointSet& tile, int kx, int ky) {
  const Domain& t = tile.domain();
  PointSet out(Domain{t.x0, t.y0, t.x0 + kx * t.width(), t.y0 + ky * t.height()});
  for (int i = 0; i < kx; ++i)
    for (int j = 0; j < ky; ++j)
      for (size_t p = 0; p < tile.size(); ++p) out.add({tile[p].x + i * t.width(), tile[p].y + j * t.height()});
  return out;
}

double peak_ratio(const PointSet& ps, int F = 48) {
  PeriodogramOptions o;
  o.frequencies = F;
  return spectrum_peak(periodogram(ps, o)).ratio;
}

}  // namespace

TEST_CASE("periodogram: white noise is ~1 everywhere, also on a rectangle's non-natural frequencies",
          "[metrics][spectrum]") {
  for (const Domain& d : {Domain{}, Domain{0, 0, 4, 1}, Domain{0, 0, 2.5, 1}}) {
    INFO("domain " << d.width() << " x " << d.height());
    PeriodogramOptions o;
    o.frequencies = 24;
    const Periodogram p = periodogram(uniform_points(3000, 5, d), o);
    CHECK(p.step == Approx(1 / std::max(d.width(), d.height())));
    CHECK(p.at(0, 0) == 0);  // DC removed
    // Mean power near DC (where the domain's window would leak) and over the whole grid.
    double low = 0, all = 0;
    int n_low = 0;
    for (int ky = -p.F; ky <= p.F; ++ky)
      for (int kx = -p.F; kx <= p.F; ++kx) {
        all += p.at(kx, ky);
        if ((kx || ky) && std::abs(kx) <= 3 && std::abs(ky) <= 3) low += p.at(kx, ky), ++n_low;
      }
    CHECK(all / (p.side() * p.side()) == Approx(1.0).epsilon(0.1));
    CHECK(low / n_low < 3.0);
  }
}

TEST_CASE("periodogram: a tiled copy and a lattice have peak ratios far above white noise", "[metrics][spectrum]") {
  const PointSet tile = jittered_grid_points(64, 1);
  const double copy = peak_ratio(tiled(tile, 4, 1));
  const double grid = peak_ratio(regular_grid_points(400, 0));
  for (uint64_t seed : {2, 3, 4}) {
    const double white = peak_ratio(uniform_points(256, seed, Domain{0, 0, 4, 1}));
    const double jittered = peak_ratio(jittered_grid_points(256, seed, Domain{0, 0, 4, 1}));
    INFO("copy " << copy << " lattice " << grid << " uniform " << white << " jittered " << jittered);
    CHECK(white < 60);
    CHECK(copy > 50 * white);
    CHECK(copy > 50 * jittered);
    CHECK(grid > 50 * white);
  }
  // The tile period shows as a peak at a multiple of 1 cycle per unit along x.
  PeriodogramOptions o;
  o.frequencies = 48;
  const SpectrumPeak pk = spectrum_peak(periodogram(tiled(tile, 4, 1), o));
  CHECK(std::abs(pk.fx - std::round(pk.fx)) < 1e-9);
}

TEST_CASE("periodogram: the thread count does not change a value; bad options are refused", "[metrics][spectrum]") {
  const PointSet ps = uniform_points(5000, 9, Domain{0, 0, 3, 1});
  PeriodogramOptions a, b;
  a.frequencies = b.frequencies = 20;
  a.threads = 1;
  b.threads = 3;
  CHECK(periodogram(ps, a).power == periodogram(ps, b).power);
  a.frequencies = 0;
  CHECK_THROWS_WITH(periodogram(ps, a), Catch::Contains("--frequencies"));
  a.frequencies = 8;
  a.step = -1;
  CHECK_THROWS_WITH(periodogram(ps, a), Catch::Contains("--step"));
  CHECK_THROWS_AS(periodogram(PointSet{}, b), InputError);
  // evaluate --spectrum reports both sets' peak ratios.
  EvalOptions eo;
  eo.include_curves = false;
  eo.spectrum = true;
  eo.spectrum_frequency = 16;
  const auto r = evaluate(jittered_grid_points(64, 1), tiled(jittered_grid_points(64, 1), 2, 2), eo);
  CHECK(r["spectrum"]["peak_ratio"]["output"].get<double>() > 10 * r["spectrum"]["peak_ratio"]["exemplar"].get<double>());
}

TEST_CASE("ppsynth spectrum writes a heat map and JSON, never over a file without --force", "[metrics][spectrum]") {
  const auto dir = ppsynth::test::scratch_dir("spectrum_cli");
  const std::string in = (dir / "strip.txt").string(), png = (dir / "s.png").string(),
                    js = (dir / "s.json").string();
  write_points(in, tiled(jittered_grid_points(64, 1), 4, 1));
  auto r = ppsynth::test::run_ppsynth("spectrum " + in + " -o " + png + " --frequencies 32 --json " + js);
  REQUIRE(r.status == 0);
  std::ifstream f(png, std::ios::binary);
  std::string head(4, '\0');
  f.read(&head[0], 4);
  CHECK(head == "\x89PNG");
  const auto j = nlohmann::json::parse(std::ifstream(js));
  CHECK(j["peak_ratio"].get<double>() > 1000);
  CHECK(j["step"].get<double>() == Approx(0.25));
  CHECK(j["frequencies"] == 32);
  const auto size = fs::file_size(png);
  r = ppsynth::test::run_ppsynth("spectrum " + in + " -o " + png + " --frequencies 8");
  CHECK(r.status != 0);
  CHECK(r.output.find("--force") != std::string::npos);
  CHECK(fs::file_size(png) == size);
  CHECK(ppsynth::test::run_ppsynth("spectrum " + in + " -o " + png + " --frequencies 8 --force").status == 0);
  CHECK(fs::file_size(png) != size);
  r = ppsynth::test::run_ppsynth("spectrum " + in + " -o " + (dir / "t.png").string() + " --frequencies 0");
  CHECK(r.status != 0);
  CHECK(r.output.find("--frequencies") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "t.png"));
  // The library call alone: any extension the canvas knows.
  PeriodogramOptions o;
  o.frequencies = 8;
  plot_spectrum((dir / "lib.svg").string(), periodogram(uniform_points(100, 1), o), "white noise", 128);
  CHECK(fs::exists(dir / "lib.svg"));
  fs::remove_all(dir);
}
