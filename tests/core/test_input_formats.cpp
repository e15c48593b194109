// Nothing lost, nothing crashes, point files: every bad input is an InputError
// naming the file and line (never another exception, never a silent read as another
// format). Each case is one defect found in review; the inputs are a few lines each.
#include <climits>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

using test::require_located;
using test::write_file;

// --- 1. detection decides from the structure, and a parse error names the chosen format ---

TEST_CASE("a flaw on line 3 of a Gabor file is reported by the Gabor reader on line 3", "[formats][input]") {
  const auto dir = test::scratch_dir("input_gabor_flaw");
  // Was read as plain text (the flaw broke the all-lines Gabor check): "line 1: point (1000, 18)
  // lies outside the domain".
  const std::string f = write_file(dir, "damaged.txt", "1000 18 7500\n1000 2500 7500\n1000 65x27 7500\n");
  CHECK(detect_format(f) == Format::GaborInt);
  require_located([&] { read_points(f); }, f, 3,
                  {"read as the published integer format (gabor)", "'65x27' is not an integer"});
  // The same with an attribute column (used to go to the Point-Synthesis reader).
  const std::string g = write_file(dir, "damaged4.txt", "1000 18 7500 3\n2000 2500 7500 4\n1000 65x27 7500 5\n");
  CHECK(detect_format(g) == Format::GaborInt);
  require_located([&] { read_points(g); }, g, 3, {"(gabor)", "'65x27' is not an integer"});
}

TEST_CASE("a Gabor file with one coordinate out of range is refused and not read as Point-Synthesis", "[formats][input]") {
  const auto dir = test::scratch_dir("input_gabor_silent");
  // Was read silently as Point-Synthesis (min-max rescaled pixels): a different meaning.
  const std::string f =
      write_file(dir, "silent.txt", "1000 2500 7500 245\n2000 2600 75000 245\n1000 3000 3000 245\n2000 1 2 3\n");
  CHECK(detect_format(f) == Format::GaborInt);
  require_located([&] { read_points(f); }, f, 2, {"(gabor)", "outside the unit square"});
}

TEST_CASE("a plain file with an extra field on line 1 is reported by the plain reader", "[formats][input]") {
  const auto dir = test::scratch_dir("input_plain_first");
  // Was read as Point-Synthesis (4 fields on line 1) and reported on line 2.
  const std::string f = write_file(dir, "p.txt", "0.1 0.2 0.3 0.4\n0.5 0.6\n0.7 0.8\n0.2 0.9\n");
  CHECK(detect_format(f) == Format::Plain);
  require_located([&] { read_points(f); }, f, 1, {"read as plain text (plain)", "header"});
}

TEST_CASE("an ambiguous choice says so and suggests --format", "[formats][input]") {
  const auto dir = test::scratch_dir("input_ambiguous");
  // Lines 1-2 fit both the Gabor and the Point-Synthesis format; line 3 only the latter.
  const std::string f = write_file(dir, "amb.txt", "1000 2000 3000 4\n2000 3000 4000 5\n1000 5000 5000 1.5\n");
  CHECK(detect_format(f) == Format::GaborInt);
  require_located([&] { read_points(f); }, f, 3,
                  {"(gabor)", "'1.5' is not an integer", "point-synthesis", "--format point-synthesis"});
  // No format fits most lines: the guess is named as one, with the way to choose.
  const std::string g = write_file(dir, "junk.txt", "hello world\nfoo bar\n");
  require_located([&] { read_points(g); }, g, 1, {"read as plain text (plain)", "--format"});
  // A format given explicitly is used as given; its name is in the error.
  require_located([&] { read_points(g, ReadOptions{Format::PointSynthesis}); }, g, 1, {"(point-synthesis)"});
  CHECK(read_points(f, ReadOptions{Format::PointSynthesis}).size() == 3);
}

// --- 2. a UTF-8 byte-order mark is skipped ------------------------------------------------

TEST_CASE("a UTF-8 byte-order mark at the start of a point file is skipped", "[formats][input]") {
  const auto dir = test::scratch_dir("input_bom");
  const std::string bom = "\xEF\xBB\xBF";
  const std::string plain = write_file(dir, "bom_plain.txt", bom + "# x y\n0.1 0.2\n0.3 0.4\n");
  CHECK(read_points(plain).size() == 2);
  const std::string bare = write_file(dir, "bom_bare.txt", bom + "0.1 0.2\n0.3 0.4\n");
  CHECK(read_points(bare).size() == 2);
  const std::string gabor = write_file(dir, "bom_gabor.txt", bom + "2 1000 2000\n1000 2500 7500\n2000 100 100\n");
  CHECK(detect_format(gabor) == Format::GaborInt);
  CHECK(read_points(gabor).num_classes() == 2);
  const std::string ps = write_file(dir, "bom_ps.txt", bom + "300 600 1 1\n310 610 2 1\n");
  CHECK(read_points(ps).size() == 2);
  const std::string json = write_file(dir, "bom_json.dat", bom + "{\"points\": [[0.1, 0.2, 0]]}");
  CHECK(detect_format(json) == Format::Json);
  CHECK(read_points(json).size() == 1);
  // A BOM elsewhere is still refused, naming the line.
  const std::string mid = write_file(dir, "bom_mid.txt", "# x y\n0.1 0.2\n" + bom + "0.3 0.4\n");
  require_located([&] { read_points(mid); }, mid, 3, {"not a number"});
}

// --- 3. integers beyond what the PointSet stores ---------------------------------------------

TEST_CASE("class labels beyond 32 bits are refused with file and line", "[formats][input]") {
  const auto dir = test::scratch_dir("input_big_labels");
  // 4294968000 = 2^32 + 704: was truncated to label 704.
  const std::string g1 = write_file(dir, "g1.txt", "1000 2500 7500\n4294968000 100 100\n");
  require_located([&] { read_points(g1, ReadOptions{Format::GaborInt}); }, g1, 2, {"4294968000", "range"});
  const std::string g2 = write_file(dir, "g2.txt", "2 1000 4294968000\n1000 2500 7500\n4294968000 100 100\n");
  require_located([&] { read_points(g2); }, g2, 1, {"4294968000", "range"});
  const std::string p = write_file(dir, "p.txt", "# class_labels 1000 4294967297\n# x y class\n0.1 0.2 0\n0.3 0.4 1\n");
  require_located([&] { read_points(p); }, p, 1, {"4294967297", "range"});
  const std::string s = write_file(dir, "s.txt", "300 600 1 1\n310 610 4294967297 1\n");
  require_located([&] { read_points(s); }, s, 2, {"4294967297", "range"});
  const std::string j =
      write_file(dir, "j.json", "{\n  \"class_labels\": [1000,\n    4294967297],\n  \"points\": [[0.1, 0.2, 0], [0.2, 0.2, 1]]\n}\n");
  require_located([&] { read_points(j); }, j, 3, {"4294967297", "range"});
  // The edges of the int range still read.
  const std::string ok = write_file(dir, "ok.txt", "# class_labels -2147483648 2147483647\n# x y class\n0.1 0.2 0\n0.3 0.4 1\n");
  const PointSet ps = read_points(ok);
  CHECK(ps.class_label(0) == INT_MIN);
  CHECK(ps.class_label(1) == INT_MAX);
}

// --- 4. radii ---------------------------------------------------------------------------------

TEST_CASE("radii must be finite and > 0 (refused with file and line)", "[formats][input]") {
  const auto dir = test::scratch_dir("input_radii");
  const std::string p = write_file(dir, "p.txt", "# x y radius\n0.1 0.2 0.01\n0.3 0.4 0\n");
  require_located([&] { read_points(p); }, p, 3, {"radius", "> 0"});
  const std::string n = write_file(dir, "n.txt", "# x y class radius\n0.1 0.2 0 -0.01\n");
  require_located([&] { read_points(n); }, n, 2, {"radius"});
  const std::string g = write_file(dir, "g_disk.txt", "2 1000 2000\n1000 2500 7500 245\n2000 100 100 -3\n");
  require_located([&] { read_points(g); }, g, 3, {"radius"});
  const std::string j = write_file(dir, "j.json",
                                   "{\"attributes\": [\"radius\"],\n \"points\": [[0.1, 0.2, 0, 0.01],\n "
                                   "[0.3, 0.4, 0, 0.0]]}");
  require_located([&] { read_points(j); }, j, 3, {"radius"});
  // Other attributes may be 0 or negative (depth, scale of element patterns).
  const std::string d = write_file(dir, "d.txt", "# x y depth\n0.1 0.2 0\n0.3 0.4 -1\n");
  CHECK(read_points(d).size() == 2);
  // validate() refuses a PointSet built in memory with a zero radius, naming the point.
  PointSet ps;
  ps.add_attribute("radius");
  ps.add({0.5, 0.5}, 0, {0.0});
  CHECK_THROWS_WITH(validate(ps, "mem"), Catch::Contains("mem") && Catch::Contains("point 0") &&
                                               Catch::Contains("radius"));
}

// --- 6. other paths that ended as a non-InputError -------------------------------------------

TEST_CASE("a directory given as a point file says so", "[formats][input]") {
  const auto dir = test::scratch_dir("input_dir_points");
  fs::create_directories(dir / "pts.txt");
  const std::string f = (dir / "pts.txt").string();
  // Was "empty file: no points".
  require_located([&] { read_points(f); }, f, 0, {"is a directory"});
  require_located([&] { detect_format(f); }, f, 0, {"is a directory"});
}

TEST_CASE("a JSON point file nested very deep is refused with file and line", "[formats][input]") {
  const auto dir = test::scratch_dir("input_deep_points");
  const size_t depth = 1000000;
  const std::string text = "{\"points\":\n" + std::string(depth, '[') + std::string(depth, ']') + "}";
  const std::string f = write_file(dir, "deep.json", text);
  require_located([&] { read_points(f); }, f, 2, {"nest"});
}

TEST_CASE("JSON point numbers: an integer beyond 64 bits is refused with the line", "[formats][input]") {
  const auto dir = test::scratch_dir("input_json_numbers");
  const std::string f = write_file(dir, "big.json", "{\"points\": [[0.1, 0.2, 0],\n [0.2, 0.3, 18446744073709551615]]}");
  require_located([&] { read_points(f); }, f, 2, {"points[1]", "class"});
  const std::string g = write_file(dir, "inf.json", "{\"points\": [[0.1, 0.2, 0],\n [0.2, 1e400, 0]]}");
  require_located([&] { read_points(g); }, g, 2, {"1e400"});
}

TEST_CASE("a domain or extent beyond the range of a double is refused with the file", "[formats][input]") {
  const auto dir = test::scratch_dir("input_huge_domain");
  // Was read; the metrics then failed without naming the file ("nearest_other: no other point").
  const std::string p = write_file(dir, "p.txt", "# domain -1e308 -1e308 1e308 1e308\n# x y\n0 0\n1 1\n");
  require_located([&] { read_points(p); }, p, 1, {"domain"});
  const std::string j = write_file(dir, "j.json", "{\"domain\": [-1e308, 0, 1e308, 1],\n \"points\": [[0, 0.5, 0]]}");
  require_located([&] { read_points(j); }, j, 1, {"domain"});
  // Was read silently with every middle point collapsed onto x = 0 (inf / inf scaling).
  const std::string s = write_file(dir, "s.txt", "1e308 0 1 1\n-1e308 5 1 1\n0 10 1 1\n");
  require_located([&] { read_points(s); }, s, 0, {"range of a double"});
}

TEST_CASE("an attribute name given twice is refused with the file, by every reader that takes names", "[formats][input]") {
  const auto dir = test::scratch_dir("input_attribute_twice");
  ReadOptions twice;
  twice.attribute_names = {"depth", "depth"};
  const std::string g = write_file(dir, "two_attrs.txt", "1000 18 7500 3 4\n2000 2500 7500 4 5\n");
  require_located([&] { read_points(g, twice); }, g, 0, {"duplicate attribute column 'depth'"});
  twice.format = Format::PointSynthesis;
  const std::string p = write_file(dir, "tu.txt", "10 20 0 1 2\n30 40 1 2 3\n50 10 0 3 4\n");
  require_located([&] { read_points(p, twice); }, p, 0, {"duplicate attribute column 'depth'"});
  // JSON names its own columns: the line of its "attributes" key.
  const std::string j = write_file(dir, "pts.json",
                                   "{\n\"attributes\": [\"a\", \"a\"],\n\"points\": [[0.1, 0.2, 0, 1, 2]]\n}\n");
  require_located([&] { read_points(j); }, j, 2, {"duplicate attribute column 'a'"});
}
