// Point-file formats (core/formats): round trips, the shipped exemplars, detection, and
// every kind of bad input naming file and line.
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/paths.hpp"
#include "tests/support/input_errors.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

using test::require_located;

namespace {

// A fresh folder per test case, removed at the end.
struct TempDir {
  fs::path dir;
  TempDir() {
    static int counter = 0;
    dir = fs::temp_directory_path() /
          ("ppsynth_formats_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string file(const std::string& name, const std::string& text) const {
    return test::write_file(dir, name, text);
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// Random multi-class point set with attributes; `grid` rounds every value to 1e-4 (what the
// Gabor format can hold).
PointSet random_set(unsigned seed, Domain d, bool grid) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  auto q = [&](double v) { return grid ? std::round(v * 10000) / 10000 : v; };
  PointSet ps(d);
  ps.add_attribute("radius");
  ps.add_attribute("depth");
  ps.set_class_labels({1000, 2000, 3000});
  for (int i = 0; i < 40; ++i)
    ps.add({q(d.x0 + u(rng) * d.width()), q(d.y0 + u(rng) * d.height())}, i % 3, {q(u(rng) * 0.05), q(u(rng))});
  return ps;
}

void require_equal(const PointSet& a, const PointSet& b) {
  REQUIRE(a.size() == b.size());
  CHECK(a.num_classes() == b.num_classes());
  CHECK(a.attribute_names() == b.attribute_names());
  for (int k = 0; k < a.num_classes(); ++k) CHECK(a.class_label(k) == b.class_label(k));
  for (size_t i = 0; i < a.size(); ++i) {
    INFO("point " << i);
    CHECK(a[i].x == b[i].x);
    CHECK(a[i].y == b[i].y);
    CHECK(a.cls(i) == b.cls(i));
    CHECK(a.attributes_of(i) == b.attributes_of(i));
  }
}

std::string exemplar_dir(const std::string& sub) {
  return (fs::path(shared_root()) / "data" / "exemplars" / sub).string();
}

}  // namespace

TEST_CASE("plain and json round-trip doubles, classes, labels, attributes and domain exactly", "[formats]") {
  TempDir t;
  Domain d{-0.5, 2.0, 3.25, 4.0, true};
  const PointSet ps = random_set(7, d, false);
  for (const char* name : {"a.txt", "a.json"}) {
    INFO(name);
    write_points(t.path(name), ps);  // Auto: by extension
    CHECK(detect_format(t.path(name)) == (std::string(name) == "a.json" ? Format::Json : Format::Plain));
    const PointSet back = read_points(t.path(name));
    require_equal(ps, back);
    CHECK(back.domain().x0 == d.x0);
    CHECK(back.domain().y1 == d.y1);
    CHECK(back.domain().periodic);
  }
  // Single class without labels: plain writes no class column, reads back as one class.
  PointSet one;
  one.add({0.1, 0.2});
  one.add({0.3, 0.4});
  write_points(t.path("one.txt"), one, Format::Plain);
  require_equal(one, read_points(t.path("one.txt")));
}

TEST_CASE("gabor integer round trip keeps labels and 1e-4 values", "[formats]") {
  TempDir t;
  const PointSet ps = random_set(11, Domain{}, true);
  write_points(t.path("ex.txt"), ps, Format::GaborInt);
  CHECK(detect_format(t.path("ex.txt")) == Format::GaborInt);
  ReadOptions ro;
  ro.attribute_names = {"radius", "depth"};
  require_equal(ps, read_points(t.path("ex.txt"), ro));
  // Without names, the rule names 2 columns scale/depth, and 1 column in a "disk" file radius.
  CHECK(read_points(t.path("ex.txt")).attribute_names() == std::vector<std::string>{"scale", "depth"});
  PointSet disk;
  disk.set_class_labels({1000});
  disk.add_attribute("radius");
  disk.add({0.25, 0.5}, 0, {0.0125});
  disk.add({0.75, 0.5}, 0, {0.02});
  write_points(t.path("my_disk.txt"), disk, Format::GaborInt);
  require_equal(disk, read_points(t.path("my_disk.txt")));
  // Without usable labels the writer uses 1000*(k+1).
  PointSet plain = disk;
  plain.set_class_labels({});
  write_points(t.path("nolabel.txt"), plain, Format::GaborInt);
  CHECK(read_points(t.path("nolabel.txt")).class_label(0) == 1000);
}

TEST_CASE("gabor writer keeps a single class whose rows have the header's shape", "[formats]") {
  // Found by fuzz_gabor_int: "1 2\n2 5 5\n" was written back as "2 5 5", which reads as the
  // header "2 classes: 5, 5". The same holds for label 3 with one attribute column.
  const PointSet two = parse_points("1 2\n2 5 5\n", "fuzz.txt", ReadOptions{Format::GaborInt});
  const std::string text = format_points(two, Format::GaborInt);
  CHECK(text == "1 2\n2 5 5\n");
  require_equal(two, parse_points(text, "back.txt", ReadOptions{Format::GaborInt}));
  PointSet three;
  three.set_class_labels({3});
  three.add_attribute("attr0");
  three.add({0.25, 0.5}, 0, {0.5});
  ReadOptions ro{Format::GaborInt};
  ro.attribute_names = {"attr0"};
  require_equal(three, parse_points(format_points(three, Format::GaborInt), "back3.txt", ro));
  // Labels that cannot look like a header still get no header line.
  three.set_class_labels({1000});
  CHECK(format_points(three, Format::GaborInt).rfind("1000 2500", 0) == 0);
}

TEST_CASE("point-synthesis round trip and axis scaling", "[formats]") {
  TempDir t;
  PointSet ps;
  ps.add_attribute("c3");
  ps.add_attribute("c4");
  ps.set_class_labels({2, 5});
  // Points span the unit square, so min-max rescaling maps them onto themselves.
  ps.add({0, 0}, 0, {1, 0});
  ps.add({1, 1}, 1, {3, 1});
  ps.add({0.375, 0.625}, 1, {2, 0});
  ps.add({0.1, 0.9}, 0, {1, 1});
  write_points(t.path("ps.txt"), ps, Format::PointSynthesis);
  CHECK(detect_format(t.path("ps.txt")) == Format::PointSynthesis);
  require_equal(ps, read_points(t.path("ps.txt")));

  const std::string f = t.file("wide.txt", "100 50 1 1\n300 150 1 1\n200 50 1 1\n300 150 1 1\n");
  ReadOptions per_axis, uniform;
  uniform.scaling = AxisScaling::Uniform;
  const PointSet a = read_points(f, per_axis), b = read_points(f, uniform);  // coincident: warned, kept
  REQUIRE(a.size() == 4);
  CHECK(a.num_classes() == 1);
  CHECK(a.class_label(0) == 1);
  CHECK(a[1].x == 1.0);
  CHECK(a[1].y == 1.0);
  CHECK(a[2].x == 0.5);
  CHECK(b.domain().x1 == 1.0);
  CHECK(b.domain().y1 == 0.5);  // 200 x 100 pixels: aspect kept
  CHECK(b[1].y == 0.5);
  CHECK(b[2].x == 0.5);
}

TEST_CASE("gabor format decodes a hand-written sample exactly", "[formats]") {
  const PointSet ps = parse_points("2 1000 2000\n1000 2500 7500 245\n2000 1 9999 10\n", "sample_disk.txt",
                                   ReadOptions{Format::GaborInt});
  REQUIRE(ps.size() == 2);
  CHECK(ps.class_labels() == std::vector<int>{1000, 2000});
  CHECK(ps[0].x == 0.25);
  CHECK(ps[0].y == 0.75);
  CHECK(ps[1].x == 0.0001);
  CHECK(ps[1].y == 0.9999);
  CHECK(ps.cls(0) == 0);
  CHECK(ps.cls(1) == 1);
  REQUIRE(ps.attribute_names() == std::vector<std::string>{"radius"});
  CHECK(ps.attr(0, 0) == 0.0245);
  CHECK(ps.attr(1, 0) == 0.001);
  // Single class, no header: labels are the CLASS values seen.
  const PointSet one = parse_points("1000 0 10000\n1000 5000 5000\n", "lines.txt");
  CHECK(one.num_classes() == 1);
  CHECK(one.class_label(0) == 1000);
  CHECK(one[0].y == 1.0);
}

TEST_CASE("every shipped exemplar loads with the right detected format", "[formats]") {
  const std::string gabor = exemplar_dir("gabor-paper"), psdir = exemplar_dir("point-synthesis");
  if (!fs::is_directory(gabor) || !fs::is_directory(psdir)) {
    WARN("shared exemplar folders not found under " << shared_root() << "; skipped");
    return;
  }
  int n_gabor = 0;
  for (const auto& e : fs::directory_iterator(gabor)) {
    if (e.path().extension() != ".txt") continue;
    INFO(e.path());
    CHECK(detect_format(e.path().string()) == Format::GaborInt);
    // The name a user writes ("shared:data/..."), as read_points takes it.
    CHECK(detect_format("shared:data/exemplars/gabor-paper/" + e.path().filename().string()) == Format::GaborInt);
    const PointSet ps = read_points(e.path().string());
    CHECK(ps.size() > 0);
    for (int k = 0; k < ps.num_classes(); ++k) CHECK(ps.class_label(k) == 1000 * (k + 1));
    ++n_gabor;
  }
  CHECK(n_gabor == 4);

  // INDEX.md lists every file with its point count and distinct c2 values: compare.
  std::ifstream index(psdir + "/INDEX.md");
  REQUIRE(index);
  const std::regex row(R"(^\|\s*(\S+)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*([\d ]+?)\s*\|$)");
  int n_ps = 0;
  for (std::string line; std::getline(index, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const std::string file = psdir + "/" + m[1].str() + ".txt";
    INFO(file);
    CHECK(detect_format(file) == Format::PointSynthesis);
    for (AxisScaling s : {AxisScaling::PerAxisMinMax, AxisScaling::Uniform}) {
      ReadOptions ro;
      ro.scaling = s;
      const PointSet ps = read_points(file, ro);
      CHECK(ps.size() == std::stoul(m[2].str()));
      CHECK(ps.num_attributes() == std::stoul(m[3].str()) - 3);
      std::istringstream values(m[4].str());
      std::vector<int> labels;
      for (int v; values >> v;) labels.push_back(v);
      CHECK(ps.class_labels() == labels);
      CHECK(ps.num_classes() == static_cast<int>(labels.size()));
      CHECK(std::max(ps.domain().x1, ps.domain().y1) == 1.0);
    }
    ++n_ps;
  }
  CHECK(n_ps == 46);
}

TEST_CASE("detection picks by content and extension; an explicit format overrides", "[formats]") {
  TempDir t;
  CHECK(detect_format(t.file("g.txt", "1000 2500 7500\n")) == Format::GaborInt);
  CHECK(detect_format(t.file("p.txt", "0.25 0.75\n0.5 0.5\n")) == Format::Plain);
  CHECK(detect_format(t.file("h.txt", "# x y\n1 1\n")) == Format::Plain);
  CHECK(detect_format(t.file("s.txt", "300 600 1 1\n")) == Format::PointSynthesis);
  CHECK(detect_format(t.file("j.dat", "  {\"points\": [[0.5, 0.5, 0]]}")) == Format::Json);
  CHECK(detect_format(t.file("j.json", "")) == Format::Json);  // extension decides
  // The same file read as Point-Synthesis: min-max rescaled instead of divided by 10000.
  const std::string f = t.file("two.txt", "1000 2500 7500\n2000 5000 5000\n");
  CHECK(read_points(f)[0].x == 0.25);
  CHECK(read_points(f, ReadOptions{Format::PointSynthesis})[0].x == 0.0);
  CHECK(parse_format("point-synthesis") == Format::PointSynthesis);
  for (Format fm : {Format::Auto, Format::GaborInt, Format::PointSynthesis, Format::Plain, Format::Json})
    CHECK(parse_format(format_name(fm)) == fm);
  CHECK_THROWS_AS(parse_format("csv"), InputError);
  CHECK_THROWS_AS(parse_axis_scaling("stretch"), InputError);
}

TEST_CASE("bad input throws InputError naming file and line", "[formats]") {
  TempDir t;
  struct Case {
    const char* name;
    const char* text;
    Format format;
    long line;
    const char* fragment;
  };
  const Case cases[] = {
      // non-numeric field
      {"nonnum_plain.txt", "# x y\n0.1 0.2\n0.3 zz\n", Format::Auto, 3, "not a number"},
      {"nonnum_gabor.txt", "1000 2500 7500\n1000 25x0 7500\n", Format::GaborInt, 2, "not an integer"},
      {"nonnum_ps.txt", "300 600 1 1\n300 60a 1 1\n", Format::Auto, 2, "not a number"},
      // wrong column count
      {"cols_plain.txt", "# x y radius\n0.1 0.2 0.01\n\n0.3 0.4\n", Format::Auto, 4, "expected 3 columns"},
      {"cols_gabor.txt", "2 1000 2000\n1000 2500 7500\n2000 1 2 3\n", Format::GaborInt, 3, "expected 3 fields"},
      {"cols_ps.txt", "300 600 1 1\n310 610 1 1 0\n", Format::Auto, 2, "expected 4 fields"},
      {"cols_noheader.txt", "0.1 0.2 0 0.5\n", Format::Plain, 1, "header"},
      // NaN / inf
      {"nan_plain.txt", "0.1 0.2\nnan 0.5\n", Format::Auto, 2, "finite"},
      {"inf_ps.txt", "300 600 1 1\ninf 600 1 1\n", Format::PointSynthesis, 2, "finite"},
      {"nan_gabor.txt", "1000 2500 7500\n1000 nan 7500\n", Format::GaborInt, 2, "finite"},
      // class id outside the header
      {"cls_gabor.txt", "2 1000 2000\n1000 2500 7500\n3000 100 100\n", Format::Auto, 3, "not in the header"},
      {"cls_plain.txt", "# class_labels 7 9\n# x y class\n0.1 0.2 1\n0.3 0.4 2\n", Format::Auto, 4, "class_labels"},
      // point outside the domain
      {"out_plain.txt", "# domain 0 0 2 1\n# x y\n1.5 0.5\n2.5 0.5\n", Format::Auto, 4, "outside"},
      {"out_gabor.txt", "1000 2500 7500\n1000 10001 7500\n", Format::GaborInt, 2, "outside"},
      // malformed header lines and JSON syntax
      {"domain_plain.txt", "# domain 0 0 1\n0.1 0.2\n", Format::Auto, 1, "domain"},
      {"syntax.json", "{\n  \"points\": [\n    [0.1, 0.2, 0],\n    [0.3 0.4, 0]\n  ]\n}\n", Format::Auto, 4,
       "invalid JSON"},
      {"out.json", "{\n  \"points\": [\n    [0.1, 0.2, 0],\n    [1.3, 0.4, 0]\n  ]\n}\n", Format::Auto, 4,
       "outside"},
      {"cols.json", "{\"attributes\": [\"radius\"],\n \"points\": [[0.1, 0.2, 0, 0.1],\n [0.3, 0.4, 0]]}",
       Format::Auto, 3, "points[1]"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string f = t.file(c.name, c.text);
    require_located([&] { read_points(f, ReadOptions{c.format}); }, f, c.line, {c.fragment});
  }
  // Empty files, whatever the format; a missing file.
  for (Format fm : {Format::Auto, Format::GaborInt, Format::PointSynthesis, Format::Plain, Format::Json}) {
    INFO(format_name(fm));
    const std::string f = t.file("empty.txt", "\n  \n");
    require_located([&] { read_points(f, ReadOptions{fm}); }, f, 0, {"no points"});
  }
  require_located([&] { read_points(t.path("missing.txt")); }, t.path("missing.txt"), 0, {"no such file"});
  REQUIRE_THROWS_AS(read_points(t.path("missing.txt")), MissingFileError);  // FileNotFoundError in Python
  // A class without points (plain ids 0 and 2) fails validation, naming the file.
  const std::string gap = t.file("gap.txt", "# x y class\n0.1 0.1 0\n0.2 0.2 2\n");
  require_located([&] { read_points(gap); }, gap, 0, {"class 1"});
}

TEST_CASE("write_points is atomic and leaves no temp file", "[formats]") {
  TempDir t;
  PointSet ps;
  ps.add({0.5, 0.5});
  write_points(t.path("out.json"), ps);
  write_points(t.path("out.json"), ps);  // overwrite
  int files = 0;
  for (const auto& e : fs::directory_iterator(t.dir)) {
    (void)e;
    ++files;
  }
  CHECK(files == 1);
  CHECK(detect_format(t.path("out.json")) == Format::Json);
  PointSet bad;
  bad.add_attribute("class");
  bad.add({0.5, 0.5}, 0, {1.0});
  CHECK_THROWS_AS(write_points(t.path("bad.txt"), bad, Format::Plain), InputError);
  CHECK_FALSE(fs::exists(t.path("bad.txt")));
}

TEST_CASE("Plain header: a parenthesized remark after the names is not a column", "[formats]") {
  auto ps = ppsynth::parse_points("# x y  (Poisson-disk initialization, unit square)\n0.25 0.5\n0.75 0.125\n", "init.txt");
  REQUIRE(ps.size() == 2);
  CHECK(ps[1].y == 0.125);
  CHECK(ps.num_attributes() == 0);
}
