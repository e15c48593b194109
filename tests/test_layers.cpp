// The floors of the house (cmake/layers.txt), as the build checks them before compiling
// (cmake/check_layers.cmake): the source tree passes, and a fixture tree with an include that
// runs up a floor, or with a cycle inside one, fails with the files that make it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

ppsynth::test::CommandResult check_floors(const fs::path& root, const fs::path& layers) {
  return ppsynth::test::run_program(std::string("\"") + PPSYNTH_CMAKE + "\"",
                                    "-DROOT=\"" + root.string() + "\" -DLAYERS=\"" + layers.string() + "\" -P \"" +
                                        PPSYNTH_SOURCE_DIR + "/cmake/check_layers.cmake\"");
}

// Two floors, low below high; each file includes what `low_b` and `high` say.
fs::path fixture(const std::string& name, const std::string& low_b_includes) {
  const fs::path root = ppsynth::test::scratch_dir(name);
  write(root / "layers.txt", "# bottom first\nlow\nhigh   # on top\n");
  write(root / "low/a.hpp", "#pragma once\n#include <vector>\n");
  write(root / "low/a.cpp", "#include \"low/a.hpp\"\n");
  write(root / "low/b.hpp", "#pragma once\n#include \"low/a.hpp\"\n");
  write(root / "low/b.cpp", "#include \"low/b.hpp\"\n" + low_b_includes);
  write(root / "high/c.hpp", "#pragma once\n#include \"low/b.hpp\"\n");
  write(root / "high/c.cpp", "#include \"high/c.hpp\"\n#include \"low/a.hpp\"\n");
  return root;
}

}  // namespace

TEST_CASE("the source tree keeps its floors", "[layers]") {
  const auto r = check_floors(PPSYNTH_SOURCE_DIR, fs::path(PPSYNTH_SOURCE_DIR) / "cmake/layers.txt");
  INFO(r.output);
  CHECK(r.status == 0);
}

TEST_CASE("an include that runs up a floor fails the check, naming both files", "[layers]") {
  const fs::path ok = fixture("layers_ok", "");
  const auto clean = check_floors(ok, ok / "layers.txt");
  INFO(clean.output);
  CHECK(clean.status == 0);

  const fs::path up = fixture("layers_up", "#include \"high/c.hpp\"\n");
  const auto r = check_floors(up, up / "layers.txt");
  INFO(r.output);
  CHECK(r.status != 0);
  CHECK_THAT(r.output, Catch::Contains("low/b.cpp includes \"high/c.hpp\": floor high is above low"));
}

TEST_CASE("an include cycle inside one floor fails the check", "[layers]") {
  // a.cpp includes b.hpp, which includes a.hpp: modules a and b include each other.
  const fs::path root = fixture("layers_cycle", "");
  write(root / "low/a.cpp", "#include \"low/a.hpp\"\n#include \"low/b.hpp\"\n");
  const auto r = check_floors(root, root / "layers.txt");
  INFO(r.output);
  CHECK(r.status != 0);
  CHECK_THAT(r.output, Catch::Contains("include cycle inside a floor: low/a.cpp includes low/b"));
}

TEST_CASE("a floors file that names no folder of the tree is refused", "[layers]") {
  const fs::path root = fixture("layers_missing", "");
  write(root / "layers.txt", "low\nmiddle\nhigh\n");
  const auto r = check_floors(root, root / "layers.txt");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, Catch::Contains("floor 'middle' is no folder"));
}
