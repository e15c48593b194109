// docs/reference_generated.md is what `ppsynth config --markdown` prints: every command's
// options and every config key with its default and bound, from the command's own
// declarations and registries. A change to either that is not regenerated into the page fails
// here, with the first line that differs.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "tests/support/run_command.hpp"

namespace {

std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string lx, ly;
  for (int line = 1;; ++line) {
    const bool gx = static_cast<bool>(std::getline(x, lx)), gy = static_cast<bool>(std::getline(y, ly));
    if (!gx && !gy) return "";
    if (!gx || !gy || lx != ly)
      return "line " + std::to_string(line) + ": the page has \"" + (gx ? lx : "<end>") + "\", the command prints \"" +
             (gy ? ly : "<end>") + "\"";
  }
}

}  // namespace

TEST_CASE("docs/reference_generated.md is what `ppsynth config --markdown` prints", "[apps][docs]") {
  using namespace ppsynth::test;
  // A build without cairo has no plot commands, so its page would differ: the page is the full build's.
  if (run_ppsynth("plot --help").status != 0) {
    WARN("skipped: this build has no plot commands (built without cairo); the page describes the full build");
    return;
  }
  const CommandResult r = run_ppsynth("config --markdown");
  REQUIRE(r.status == 0);
  std::ifstream in(std::string(PPSYNTH_SOURCE_DIR) + "/docs/reference_generated.md");
  REQUIRE(in.good());
  std::stringstream page;
  page << in.rdbuf();
  INFO("regenerate it: build/ppsynth config --markdown > docs/reference_generated.md");
  INFO(first_difference(page.str(), r.output));
  CHECK(page.str() == r.output);
  // It covers what it claims: each command and each kind of part.
  for (const char* s : {"### `ppsynth synthesize`", "### `ppsynth sweep run`", "#### `method` gabor", "#### `loss` gram",
                        "#### `preset` fast", "| `max_iterations` | `500` |"})
    CHECK(r.output.find(s) != std::string::npos);
}
