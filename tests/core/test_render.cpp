// Rendering: format by extension, atomic writes, disk geometry read back from the PNG.
#include <catch2/catch.hpp>

#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/render/image_grid.hpp"
#include "core/render/canvas.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_frame.hpp"
#include "core/render/plot_points.hpp"
#include "core/render/plot_strips.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

std::string head_bytes(const fs::path& p, size_t n) {
  std::ifstream in(p, std::ios::binary);
  std::string s(n, '\0');
  in.read(&s[0], static_cast<std::streamsize>(n));
  s.resize(static_cast<size_t>(in.gcount()));
  return s;
}

PointSet random_two_class(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  PointSet ps;
  for (size_t i = 0; i < n; ++i) ps.add({u(rng), u(rng)}, static_cast<int>(i % 2));
  return ps;
}

// RGB of pixel (x, y) of a PNG (ARGB32/RGB24 as cairo stores it: native-endian 0xAARRGGBB).
std::array<int, 3> pixel(cairo_surface_t* s, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  const uint32_t v = *reinterpret_cast<const uint32_t*>(data + y * stride + 4 * x);
  return {static_cast<int>((v >> 16) & 255), static_cast<int>((v >> 8) & 255), static_cast<int>(v & 255)};
}

bool is_white(const std::array<int, 3>& c) { return c[0] > 250 && c[1] > 250 && c[2] > 250; }

}  // namespace

TEST_CASE("plots are written as PNG, SVG and PDF by extension", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_formats");
  const PointSet ps = random_two_class(200, 7);
  CurvePlot cp{"loss", "iteration", "loss", true, {{"total", {1, 2, 3, 4}, {10, 1, 0.1, 0.05}, false}}};
  GrayImage im{4, 3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, "ramp"};
  struct Magic {
    const char* ext;
    std::string magic;
  };
  for (const Magic& m : {Magic{".png", "\x89PNG"}, Magic{".svg", "<?xml"}, Magic{".pdf", "%PDF"}}) {
    const fs::path pts = dir / (std::string("points") + m.ext);
    const fs::path pan = dir / (std::string("panels") + m.ext);
    const fs::path cur = dir / (std::string("curves") + m.ext);
    const fs::path grid = dir / (std::string("grid") + m.ext);
    plot_points(pts.string(), ps, PointStyle{});
    plot_panels(pan.string(), {{"a", ps}, {"b", random_two_class(800, 8)}}, PointStyle{}, 200, 0);
    plot_curves(cur.string(), cp);
    plot_curve_grid(grid.string(), {cp, cp, cp}, 2);
    for (const auto& p : {pts, pan, cur, grid}) {
      INFO(p.string());
      REQUIRE(fs::exists(p));
      CHECK(fs::file_size(p) > 200);
      CHECK(head_bytes(p, m.magic.size()) == m.magic);
    }
    const fs::path img = dir / (std::string("images") + m.ext);
    plot_image_grid(img.string(), {im, im}, 2, 64, true, ColorMap::Diverging);
    CHECK(head_bytes(img, m.magic.size()) == m.magic);
  }
  // Nothing but the outputs is left behind (no temp files).
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++files;
    CHECK(e.path().string().find(".tmp-") == std::string::npos);
  }
  CHECK(files == 15);
  fs::remove_all(dir);
}

TEST_CASE("unknown extension throws naming the path and leaves no file", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_badext");
  const std::string bad = (dir / "points.jpg").string();
  CHECK_THROWS_AS(plot_points(bad, random_two_class(10, 1)), InputError);
  CHECK_THROWS_WITH(plot_points(bad, random_two_class(10, 1)), Catch::Contains(bad));
  CHECK_THROWS_AS(plot_curves((dir / "c").string(), CurvePlot{}), InputError);
  CHECK_THROWS_AS(plot_image_grid((dir / "g.bmp").string(), {GrayImage{1, 1, {0}, ""}}, 1), InputError);
  CHECK(fs::is_empty(dir));
  // A folder that does not exist is an InputError too (cairo cannot write), with no debris.
  CHECK_THROWS_AS(plot_points((dir / "missing" / "p.png").string(), random_two_class(10, 1)), InputError);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("bad plot inputs are InputErrors", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_badinput");
  PointStyle st;
  st.color_attribute = "depth";
  CHECK_THROWS_WITH(plot_points((dir / "p.png").string(), random_two_class(5, 2), st), Catch::Contains("depth"));
  CurvePlot cp{"", "", "", false, {{"s", {1, 2}, {1}, false}}};
  CHECK_THROWS_AS(plot_curves((dir / "c.png").string(), cp), InputError);
  CHECK_THROWS_AS(plot_image_grid((dir / "g.png").string(), {GrayImage{2, 2, {0, 1, 2}, "short"}}, 1), InputError);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("a point with a radius attribute is drawn as a disk at its true radius", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_disk");
  const fs::path png = dir / "disk.png";
  PointSet ps;  // unit square, one disk of radius 0.25 at (0.5, 0.5)
  ps.add_attribute("radius");
  ps.add({0.5, 0.5}, 0, {0.25});
  PointStyle st;
  st.show_frame = false;
  plot_points(png.string(), ps, st, 400);

  cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
  REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
  const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  cairo_surface_flush(s);
  // Locate the disk from the image itself: bounding box of the non-white pixels of the
  // colored disk (tick labels are gray text outside; restrict to colored pixels).
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto c = pixel(s, x, y);
      const bool colored = std::abs(c[0] - c[2]) > 30;  // class 0 is blue; grays have r == b
      if (colored) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  REQUIRE(x1 > x0);
  const double cx = (x0 + x1) / 2.0, cy = (y0 + y1) / 2.0, r_px = (x1 - x0 + 1) / 2.0;
  // Expected: the frame side is the panel size minus the axis margins; the disk diameter is
  // half of it. Measure it independently from a point plot with two corner markers instead
  // of trusting the layout constants: draw points at (0,0) and (1,1) and find their centers.
  PointSet corners;
  corners.add({0.0, 0.0});
  corners.add({1.0, 1.0});
  PointStyle cs;
  cs.show_frame = false;
  cs.point_radius_px = 3;
  const fs::path cpng = dir / "corners.png";
  plot_points(cpng.string(), corners, cs, 400);
  cairo_surface_t* c = cairo_image_surface_create_from_png(cpng.string().c_str());
  REQUIRE(cairo_surface_status(c) == CAIRO_STATUS_SUCCESS);
  int ax0 = w, ax1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto p = pixel(c, x, y);
      if (std::abs(p[0] - p[2]) > 30) ax0 = std::min(ax0, x), ax1 = std::max(ax1, x);
    }
  // Corner markers are clipped to the frame, so the colored extent is the frame width.
  const double frame_px = ax1 - ax0 + 1;
  CHECK(r_px == Approx(0.25 * frame_px).margin(2.0));
  CHECK(cx == Approx(ax0 + 0.5 * frame_px).margin(2.0));

  // Pixels: center and just inside the rim are covered; just outside is white.
  CHECK_FALSE(is_white(pixel(s, static_cast<int>(cx), static_cast<int>(cy))));
  CHECK_FALSE(is_white(pixel(s, static_cast<int>(cx + 0.9 * r_px), static_cast<int>(cy))));
  CHECK(is_white(pixel(s, static_cast<int>(cx + r_px + 3), static_cast<int>(cy))));
  CHECK(is_white(pixel(s, static_cast<int>(cx + 0.75 * r_px), static_cast<int>(cy + 0.75 * r_px))));  // outside: 1.06 r
  CHECK_FALSE(is_white(pixel(s, static_cast<int>(cx + 0.65 * r_px), static_cast<int>(cy + 0.65 * r_px))));  // 0.92 r
  cairo_surface_destroy(s);
  cairo_surface_destroy(c);

  // With --no-disks the same point is a small marker, not a big disk.
  st.draw_disks = false;
  plot_points(png.string(), ps, st, 400);
  s = cairo_image_surface_create_from_png(png.string().c_str());
  CHECK(is_white(pixel(s, static_cast<int>(cx + 0.9 * r_px), static_cast<int>(cy))));
  CHECK_FALSE(is_white(pixel(s, static_cast<int>(cx), static_cast<int>(cy))));
  cairo_surface_destroy(s);
  fs::remove_all(dir);
}

TEST_CASE("auto marker size follows the point count", "[render]") {
  // An output with 4x the points at the same image size must have smaller markers: count
  // the colored pixels of a single point drawn alone vs. one point of a dense set.
  const auto dir = ppsynth::test::scratch_dir("render_autosize");
  auto ink = [&](const PointSet& ps) {
    const fs::path p = dir / "p.png";
    plot_points(p.string(), ps, PointStyle{}, 300);
    cairo_surface_t* s = cairo_image_surface_create_from_png(p.string().c_str());
    long n = 0;
    for (int y = 0; y < cairo_image_surface_get_height(s); ++y)
      for (int x = 0; x < cairo_image_surface_get_width(s); ++x) {
        auto c = pixel(s, x, y);
        if (std::abs(c[0] - c[2]) > 30) ++n;
      }
    cairo_surface_destroy(s);
    return n;
  };
  PointSet sparse, dense;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.1, 0.9);
  for (int i = 0; i < 100; ++i) sparse.add({u(rng), u(rng)});
  for (int i = 0; i < 400; ++i) dense.add({u(rng), u(rng)});
  const double per_point_sparse = ink(sparse) / 100.0, per_point_dense = ink(dense) / 400.0;
  // Marker area scales like 1/N: about 4x smaller (overlaps only reduce the dense count).
  CHECK(per_point_dense < 0.4 * per_point_sparse);
  CHECK(per_point_dense > 0.1 * per_point_sparse);
  fs::remove_all(dir);
}

TEST_CASE("ppsynth plot and plot-pcf write images; a bad extension fails cleanly", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_cli");
  const fs::path pts = dir / "pts.txt", other = dir / "other.txt";
  {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    std::ofstream a(pts), b(other);
    a << "# x y class\n";
    b << "# x y class\n";
    for (int i = 0; i < 60; ++i) a << u(rng) << " " << u(rng) << " " << (i % 2) << "\n";
    for (int i = 0; i < 240; ++i) b << u(rng) << " " << u(rng) << " " << (i % 2) << "\n";
  }
  const std::string bin = PPSYNTH_BINARY;
  auto run = [&](const std::string& args) {
    return std::system((bin + " -q " + args + " > " + (dir / "log.txt").string() + " 2>&1").c_str());
  };
  CHECK(run("plot " + pts.string() + " -o " + (dir / "a.png").string()) == 0);
  CHECK(head_bytes(dir / "a.png", 4) == "\x89PNG");
  CHECK(run("plot " + pts.string() + " -o " + (dir / "b.pdf").string() + " --compare " + other.string()) == 0);
  CHECK(head_bytes(dir / "b.pdf", 4) == "%PDF");
  CHECK(run("plot-pcf --exemplar " + pts.string() + " --output " + other.string() + " -o " + (dir / "pcf.svg").string()) == 0);
  CHECK(head_bytes(dir / "pcf.svg", 5) == "<?xml");
  CHECK(run("plot " + pts.string() + " -o " + (dir / "c.gif").string()) != 0);
  CHECK_FALSE(fs::exists(dir / "c.gif"));
  CHECK(run("plot " + pts.string() + " -o " + (dir / "d.png").string() + " --color-attr nope") != 0);
  CHECK_FALSE(fs::exists(dir / "d.png"));
  fs::remove_all(dir);
}

TEST_CASE("a blank cell (empty title, empty set) of a panel grid draws nothing", "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_blank");
  const fs::path png = dir / "grid.png";
  const int px = 200;
  auto blank_half_is_white = [&](const std::string& title) {
    plot_panels(png.string(), {{"a", random_two_class(20, 3)}, {title, PointSet()}}, PointStyle{}, px, 2);
    cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
    REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
    cairo_surface_flush(s);
    bool white = true;  // the second cell, above the legend strip
    for (int y = 0; y < px - 10 && white; ++y)
      for (int x = px + 5; x < 2 * px - 5 && white; ++x) white = is_white(pixel(s, x, y));
    cairo_surface_destroy(s);
    return white;
  };
  CHECK(blank_half_is_white(""));
  CHECK_FALSE(blank_half_is_white("empty output"));  // a titled empty set still gets its frame
  // A blank cell has no attributes and is not asked for the color attribute.
  PointSet colored;
  colored.add_attribute("depth");
  colored.add({0.5, 0.5}, 0, {1.0});
  PointStyle by_depth;
  by_depth.color_attribute = "depth";
  CHECK_NOTHROW(plot_panels(png.string(), {{"a", colored}, {"", PointSet()}}, by_depth, px, 2));
}

// --- rendering limits --------------------------------------------------------------------

TEST_CASE("disks of radius 1e30, 1e300, inf or < 0 are drawn clipped, promptly", "[render][limits]") {
  // A huge disk used to make cairo flatten an arc of 1e32 px (it never returned).
  const auto dir = ppsynth::test::scratch_dir("render_huge_disk");
  const fs::path png = dir / "huge.png";
  for (double r : {1e30, 1e300, std::numeric_limits<double>::infinity()}) {
    INFO("radius " << r);
    PointSet ps;
    ps.add_attribute("radius");
    ps.add({0.5, 0.5}, 0, {r});
    ps.add({0.2, 0.8}, 0, {0.01});
    plot_points(png.string(), ps, PointStyle{}, 80);
    cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
    REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
    // The disk covers the whole frame: its center pixel is tinted, not white.
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    CHECK_FALSE(is_white(pixel(s, w / 2 + 8, h / 2)));
    cairo_surface_destroy(s);
  }
  // A disk far outside the frame whose rim crosses it, NaN and negative radii, in a vector file.
  PointSet odd;
  odd.add_attribute("radius");
  odd.add({0.5, 0.5}, 0, {std::nan("")});
  odd.add({0.4, 0.4}, 0, {-3.0});
  odd.add({0.6, 0.6}, 1, {1e-300});
  PointSet far(Domain{0, 0, 1, 1});
  far.add_attribute("radius");
  far.add({1e20, 0.5}, 0, {1e20 - 0.5});  // outside the domain: rim through x = 0.5
  CHECK_NOTHROW(plot_points((dir / "odd.pdf").string(), odd, PointStyle{}, 80));
  CHECK_NOTHROW(plot_points((dir / "far.png").string(), far, PointStyle{}, 80));
  CHECK_NOTHROW(plot_panels((dir / "both.svg").string(), {{"a", odd}, {"b", far}}, PointStyle{}, 80));
  fs::remove_all(dir);
}

TEST_CASE("tick positions terminate for ranges below the precision of their values", "[render][limits]") {
  // [1e20, 1e20 + one ulp] with 5 ticks: a step of 5000 does not move 1e20; the loop never ended.
  const double lo = 1e20, hi = std::nextafter(1e20, 1e21);
  const auto t = render::nice_ticks(lo, hi, 5);
  CHECK(t.size() <= 64);
  CHECK(render::nice_ticks(0, 1e-320, 5).size() <= 64);
  CHECK(render::nice_ticks(-1e308, 1e308, 5).size() <= 64);
  const auto dir = ppsynth::test::scratch_dir("render_ticks");
  CurvePlot cp{"extreme", "x", "y", false, {{"s", {lo, hi, 1e300}, {-1e308, 1e308, 0}, false}}};
  CHECK_NOTHROW(plot_curves((dir / "c.png").string(), cp, 200, 150));
  cp.log_y = true;
  cp.series[0].y = {1e-320, 1e308, 1};
  CHECK_NOTHROW(plot_curves((dir / "l.png").string(), cp, 200, 150));
  fs::remove_all(dir);
}

TEST_CASE("a PCF grid of 30 classes (465 pairs) renders within cairo's limits", "[render][limits]") {
  // 1 + 30 classes + 435 cross pairs = 466 panels: 156 rows of 260 px at 3 columns, beyond
  // cairo's 32767 px; it failed after a whole synthesis. Now the grid is laid out to fit.
  const auto dir = ppsynth::test::scratch_dir("render_big_grid");
  std::vector<double> r(100), g(100);
  for (int k = 0; k < 100; ++k) r[k] = 0.01 + 2.49 * k / 99, g[k] = 1 - std::exp(-r[k] * r[k]);
  std::vector<CurvePlot> plots;
  for (int i = 0; i < 466; ++i)
    plots.push_back({"cross " + std::to_string(i), "r / r_max", "g(r)", false,
                     {{"exemplar", r, g, true}, {"output", r, g, false}}});
  const fs::path png = dir / "pcf.png";
  CHECK(curve_grid_fits(466, 3, 360, 260));
  CHECK_NOTHROW(plot_curve_grid(png.string(), plots, 3));
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
  REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
  CHECK(cairo_image_surface_get_width(s) <= render::kMaxImageSide);
  CHECK(cairo_image_surface_get_height(s) <= render::kMaxImageSide);
  cairo_surface_destroy(s);
  // Any count: the layout says up front what is shown; beyond capacity the first panels are
  // drawn with a title saying how many were left out.
  for (size_t n : {size_t(1), size_t(466), size_t(5000), size_t(1000000)}) {
    const CurveGridLayout l = curve_grid_layout(n, 3, 360, 260);
    INFO("n " << n);
    CHECK(l.shown <= n);
    CHECK(l.shown >= 1);
    CHECK(l.width <= render::kMaxImageSide);
    CHECK(l.height <= render::kMaxImageSide);
    CHECK(static_cast<double>(l.width) * l.height <= render::kMaxImagePixels);
    CHECK(curve_grid_fits(n, 3, 360, 260) == (l.shown == n));
  }
  CHECK_FALSE(curve_grid_fits(1000000, 3, 360, 260));
  std::vector<CurvePlot> many(3000, plots[0]);
  const fs::path svg = dir / "many.svg";
  CHECK_NOTHROW(plot_curve_grid(svg.string(), many, 3, 360, 260));
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.size() > 1000);
  fs::remove_all(dir);
}

TEST_CASE("an image beyond the size limit is an InputError before any allocation", "[render][limits]") {
  const auto dir = ppsynth::test::scratch_dir("render_too_big");
  CurvePlot cp{"t", "x", "y", false, {{"s", {0, 1}, {0, 1}, false}}};
  CHECK_THROWS_WITH(plot_curves((dir / "c.png").string(), cp, 30000, 30000), Catch::Contains("limit"));
  std::vector<std::pair<std::string, PointSet>> panels(60, {"p", random_two_class(10, 1)});
  CHECK_THROWS_WITH(plot_panels((dir / "p.png").string(), panels, PointStyle{}, 8000, 0), Catch::Contains("--columns"));
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("rectangular domains: frames keep their aspect, rows shrink to them; many points get a larger plot",
          "[render]") {
  const auto dir = ppsynth::test::scratch_dir("render_rect");
  PointSet strip(Domain{0, 0, 4, 1});
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 256; ++i) strip.add({4 * u(rng), u(rng)});
  const fs::path png = dir / "strip.png";
  plot_points(png.string(), strip, PointStyle{}, 600);
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
  const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  cairo_surface_destroy(s);
  CHECK(w == 614);
  CHECK(h < w / 2);  // a 4 x 1 frame, not a square cell with a blank band
  // Few points: the default size; 100,000 on a 10 x 10 domain: larger, within the cap.
  PointSet few = random_two_class(100, 1);
  CHECK(readable_plot_px({&few}, 600) == 600);
  PointSet many(Domain{0, 0, 10, 10});
  for (int i = 0; i < 100000; ++i) many.add({10 * u(rng), 10 * u(rng)});
  const int big = readable_plot_px({&many}, 600);
  CHECK(big > 1200);
  CHECK(big <= 2400);
  fs::remove_all(dir);
}

TEST_CASE("strip plots letter long labels and list them whole; any group count fits", "[render][limits]") {
  const auto dir = ppsynth::test::scratch_dir("render_strips");
  auto size_of = [](const fs::path& png) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(png.string().c_str());
    REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
    const std::pair<int, int> wh{cairo_image_surface_get_width(s), cairo_image_surface_get_height(s)};
    cairo_surface_destroy(s);
    return wh;
  };
  StripPlot plain{"all: pcf_mse", "pcf_mse", {{"a", {1, 2, 3}}, {"b", {2, 3}}}, 1.0, "reference", {}, ""};
  plot_strips((dir / "plain.png").string(), plain);
  CHECK(size_of(dir / "plain.png") == std::pair<int, int>{360, 380});
  // Two labels that differ only at their end: the legend holds both whole, so the image is
  // wider than the columns need and taller by the legend's extra row.
  StripPlot sweep = plain;
  sweep.groups = {{"lemon_4c_v2 (preset fast) [method.border_relax.separation=0]", {1, 2}},
                  {"lemon_4c_v2 (preset fast) [method.border_relax.separation=1]", {2, 3}}};
  plot_strips((dir / "keyed.png").string(), sweep);
  const auto keyed = size_of(dir / "keyed.png");
  CHECK(keyed.first > 360);
  CHECK(keyed.first >= render::measure_text(sweep.groups[0].label, render::kChartLegendFont) + 2 * render::kChartPad);
  CHECK(keyed.second > 380);
  // 2,000 groups of long labels: within the side limit, no throw.
  StripPlot many = plain;
  many.groups.clear();
  for (int g = 0; g < 2000; ++g) many.groups.push_back({"a configuration with a long label, number " + std::to_string(g), {1.0 * g}});
  CHECK_NOTHROW(plot_strips((dir / "many.png").string(), many));
  const auto big = size_of(dir / "many.png");
  CHECK(big.first <= render::kMaxImageSide);
  CHECK(big.second <= render::kMaxImageSide);
  fs::remove_all(dir);
}
