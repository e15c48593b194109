// Through the real binary: a point reader that is handed a device, a FIFO or a directory stops
// at once with exit 2 naming it (synthesize -e, eval, info); a file name that is not UTF-8
// never ends in exit 3; doctor and bench refuse a --json they could not write before they
// measure anything.
// Each command runs under `timeout` and a memory limit, so that a regression fails the test
// (exit 124, or an allocation error) instead of hanging the suite or taking the machine.
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "core/formats/text_table.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::run_ppsynth;

namespace {

// 30 s and 4 GiB of address space: twice what any of these commands needs when it works.
const std::string kGuard = "ulimit -v 4194304; timeout 30";

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

// 64 points on a jittered 8 x 8 grid of the unit square, as plain text.
std::string small_pattern() {
  std::string t = "# x y\n";
  for (int i = 0; i < 64; ++i) {
    const double x = (i % 8 + 0.3 + 0.05 * (i % 5)) / 8.0, y = (i / 8 + 0.6 - 0.07 * (i % 3)) / 8.0;
    t += ppsynth::format_real(x) + " " + ppsynth::format_real(y) + "\n";
  }
  return t;
}

}  // namespace

TEST_CASE("point readers refuse a device, a FIFO and a directory at once, naming it", "[apps][input-file]") {
  const auto d = ppsynth::test::scratch_dir("cli_input_kinds");
  const std::string good = ppsynth::test::write_file(d, "good.txt", small_pattern());
  const std::string fifo = (d / "pipe.txt").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string folder = (d / "folder.txt").string();
  fs::create_directory(folder);
  struct Kind {
    std::string path, says;
  };
  // Was: /dev/zero read until the kernel killed the process (23 GB); the FIFO blocked forever.
  for (const Kind& k : {Kind{"/dev/zero", "is a character device, not a regular file"},
                        Kind{fifo, "is a FIFO (named pipe), not a regular file"}, Kind{folder, "is a directory"}}) {
    for (const std::string& args :
         {"synthesize --exemplar " + k.path + " --quick -o " + (d / "run").string(),
          "synthesize " + kLines + " --quick --set exemplar=" + k.path + " -o " + (d / "run").string(),
          "eval --exemplar " + k.path + " --output " + good, "eval --exemplar " + good + " --output " + k.path,
          "info " + k.path}) {
      const auto r = run_ppsynth(args, kGuard);
      INFO(args << "\n" << r.output);
      CHECK(r.status == 2);
      CHECK_THAT(r.output, Catch::Contains(k.path + ": ") && Catch::Contains(k.says));
      CHECK_FALSE(fs::exists(d / "run"));
    }
  }
}

TEST_CASE("a file name that is not UTF-8 is shown in JSON or refused clearly, never an internal error", "[apps][input-file]") {
  const auto d = ppsynth::test::scratch_dir("cli_input_utf8");
  const std::string odd = ppsynth::test::write_file(d, "ex\xff.txt", small_pattern());
  const std::string shown = (d / "ex\xef\xbf\xbd.txt").string();  // U+FFFD for the byte 0xff
  // Was exit 3, "internal error" (json::dump's type_error 316).
  const auto info = run_ppsynth("-q info '" + odd + "' --json", kGuard);
  REQUIRE(info.status == 0);
  CHECK(nlohmann::json::parse(info.output)["file"] == shown);
  const std::string eval = "-q eval --exemplar '" + odd + "' --output '" + odd + "' --no-second-order --no-verdict";
  const auto as_json = run_ppsynth(eval + " --json", kGuard);
  REQUIRE(as_json.status == 0);
  CHECK(nlohmann::json::parse(as_json.output)["output"]["path"] == shown);
  const auto to_file = run_ppsynth(eval + " --out " + (d / "e.json").string(), kGuard);
  CHECK(to_file.status == 0);
  CHECK(nlohmann::json::parse(ppsynth::read_file_text((d / "e.json").string()))["exemplar"]["path"] == shown);
  // A run records its exemplar's name in config.json and reads it back: it is refused, named.
  const auto run = run_ppsynth("synthesize --exemplar '" + odd + "' --quick -o " + (d / "run").string(), kGuard);
  INFO(run.output);
  CHECK(run.status == 2);
  CHECK_THAT(run.output, Catch::Contains("config key 'exemplar'") && Catch::Contains("not valid UTF-8"));
  CHECK_FALSE(fs::exists(d / "run"));
}

TEST_CASE("doctor and bench refuse a --json they could not write before measuring", "[apps][doctor][bench][input-file]") {
  const auto d = ppsynth::test::scratch_dir("cli_json_unwritable");
  const std::string file = ppsynth::test::write_file(d, "file.txt", "mine\n");
  const std::string out = file + "/m.json";  // its folder is a regular file: unwritable, even for root
  // Was: the whole measurement, its report printed, then the error.
  const auto doctor = run_ppsynth("doctor --grid 16 --reps 1 --json " + out, kGuard);
  INFO(doctor.output);
  CHECK(doctor.status == 2);
  CHECK_THAT(doctor.output, Catch::Contains(out) && !Catch::Contains("processor:"));
  const std::string tiny = " --reps 1 --skip-setup --set method.grid.res=16 --set method.feature_net.channels=8";
  const auto bench = run_ppsynth("bench " + kLines + tiny + " --json " + out, kGuard);
  INFO(bench.output);
  CHECK(bench.status == 2);
  CHECK_THAT(bench.output, Catch::Contains(out) && !Catch::Contains("ONE FULL ITERATION"));
  // Nor over one of its inputs.
  const std::string ex = ppsynth::test::write_file(d, "ex.txt", small_pattern());
  const auto over_input = run_ppsynth("bench " + kLines + tiny + " --exemplar " + ex + " --json " + ex, kGuard);
  INFO(over_input.output);
  CHECK(over_input.status == 2);
  CHECK_THAT(over_input.output, Catch::Contains("an output never replaces an input"));
  CHECK(ppsynth::read_file_text(ex) == small_pattern());
  CHECK(ppsynth::read_file_text(file) == "mine\n");
}
