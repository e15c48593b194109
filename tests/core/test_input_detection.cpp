// Nothing lost, nothing crashes: format detection must keep every shipped point
// file under ../shared/data detected and read as it was before detection became structural.
// The expected format of each file is the one the old first-match detection chose
// (recorded by running this test against it): the Gabor paper's exemplars are gabor, the
// Point-Synthesis exemplars point-synthesis, the reference outputs and initializations plain.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <catch2/catch.hpp>

#include "core/formats/point_io.hpp"
#include "core/paths.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

TEST_CASE("every shipped point file under shared/data is detected and read as before", "[formats][input]") {
  const fs::path data = fs::path(shared_root()) / "data";
  if (!fs::is_directory(data)) {
    WARN("shared data folder not found under " << shared_root() << "; skipped");
    return;
  }
  // Expected format by folder (relative to data/), as the old detection chose.
  const std::map<std::string, Format> by_folder = {
      {"exemplars/gabor-paper", Format::GaborInt},
      {"exemplars/point-synthesis", Format::PointSynthesis},
      {"reference/lemon_4c_v2", Format::Plain},
      {"reference/lines", Format::Plain},
      {"reference/poisson_n64c2_disk", Format::Plain},
      {"reference/poisson_n64c2_point", Format::Plain},
  };
  std::map<Format, int> seen;
  for (const auto& e : fs::recursive_directory_iterator(data)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = e.path().extension().string();
    if (ext != ".txt" && ext != ".json") continue;
    const std::string folder = fs::relative(e.path().parent_path(), data).generic_string();
    INFO(e.path().string());
    const auto it = by_folder.find(folder);
    REQUIRE(it != by_folder.end());  // a new folder: add its expected format above
    CHECK(detect_format(e.path().string()) == it->second);
    // parse_points reads without validation: reference/poisson_n64c2_point/output_class1.txt
    // holds class 1 alone, which validation refuses (class 0 empty), before and after.
    std::ifstream in(e.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(parse_points(text, e.path().string()).size() > 0);
    if (e.path().filename() != "output_class1.txt") CHECK(read_points(e.path().string()).size() > 0);
    ++seen[it->second];
  }
  // 4 Gabor exemplars, 46 Point-Synthesis exemplars, 13 reference files (as shipped).
  CHECK(seen[Format::GaborInt] == 4);
  CHECK(seen[Format::PointSynthesis] == 46);
  CHECK(seen[Format::Plain] == 13);
}
