// Nothing a user has is lost: the defects found in review as a user meets them, through the real
// binary. Each case names the defect it guards against.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/formats/text_table.hpp"
#include "core/run_directory.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/device_nodes.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
const std::string kQuick = " --quick -q ";

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST_CASE("synthesize and reproduce refuse the current directory and its parents", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_dot");
  write(d / "mine.txt", "the user's file\n");
  fs::create_directories(d / "sub");
  for (const std::string out : {".", "./", "..", "sub/.."}) {
    auto r = run_ppsynth("synthesize " + kLines + kQuick + "-o " + out, "cd " + d.string() + " &&");
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("current directory"));
  }
  auto r = run_ppsynth("reproduce fig04 --quick -q -o .", "cd " + d.string() + " &&");
  CHECK(r.status == 2);
  CHECK(ppsynth::read_file_text((d / "mine.txt").string()) == "the user's file\n");
  CHECK(fs::is_directory(d / "sub"));
}

TEST_CASE("a config's name never acts as a path", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_name");
  fs::create_directories(d / "victim");
  write(d / "victim" / "keep.txt", "keep\n");
  for (const std::string name : {"../victim", "..", "a/b", "."}) {
    write(d / "c.json", "{\"parent\": \"" + kLines + "\", \"name\": \"" + name + "\"}");
    auto r = run_ppsynth("synthesize c.json" + kQuick, "cd " + d.string() + " &&");
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("'name'") || Catch::Contains("name"));
  }
  CHECK(ppsynth::read_file_text((d / "victim" / "keep.txt").string()) == "keep\n");
  CHECK_FALSE(fs::exists(d / "runs"));
}

TEST_CASE("an existing file or a foreign directory is never replaced", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_foreign");
  write(d / "file", "a file\n");
  fs::create_directories(d / "theirs");
  write(d / "theirs" / "notes.txt", "notes\n");
  for (const std::string out : {"file", "theirs", "theirs/"}) {
    for (const std::string force : {"", " --force"}) {
      auto r = run_ppsynth("synthesize " + kLines + kQuick + "-o " + (d / out).string() + force);
      CHECK(r.status == 2);
      CHECK_THAT(r.output, Catch::Contains(out.substr(0, 4)));
    }
  }
  CHECK(ppsynth::read_file_text((d / "file").string()) == "a file\n");
  CHECK(ppsynth::read_file_text((d / "theirs" / "notes.txt").string()) == "notes\n");
  // An empty directory (made by a job script, say) is used, and kept on failure.
  fs::create_directories(d / "empty");
  CHECK(run_ppsynth("synthesize " + kLines + kQuick + "-o " + (d / "empty").string()).status == 0);
  CHECK(fs::exists(d / "empty" / "output.txt"));
}

TEST_CASE("a finished run is replaced only with --force, trailing slash or not", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_force");
  const std::string run = (d / "run").string();
  REQUIRE(run_ppsynth("synthesize " + kLines + kQuick + "-o " + run).status == 0);
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Complete);
  const std::string first = ppsynth::read_file_text(run + "/output.txt");
  auto again = run_ppsynth("synthesize " + kLines + kQuick + "--seed 7 -o " + run + "/");
  CHECK(again.status == 2);
  CHECK_THAT(again.output, Catch::Contains("--force"));
  CHECK(ppsynth::read_file_text(run + "/output.txt") == first);
  REQUIRE(run_ppsynth("synthesize " + kLines + kQuick + "--seed 7 --force -o " + run + "/").status == 0);
  CHECK(ppsynth::read_file_text(run + "/output.txt") != first);
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Complete);
  CHECK_FALSE(fs::exists(run + ".partial"));
}

TEST_CASE("a second run into a directory another process writes refuses at once", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_lock");
  const std::string run = (d / "run").string();
  ppsynth::RunDirectory held = ppsynth::RunDirectory::open(run, {});  // this test process is "the first run"
  auto r = run_ppsynth("synthesize " + kLines + kQuick + "-o " + run);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("another ppsynth process"));
  auto forced = run_ppsynth("synthesize " + kLines + kQuick + "--force -o " + run);
  CHECK(forced.status == 2);  // --force does not take a directory from a live process
  CHECK(ppsynth::run_dir_state(run) == ppsynth::RunDirState::Unfinished);
}

TEST_CASE("a failed run removes only what it wrote", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_fail");
  // The exemplar has a point outside the domain: the run fails before creating anything.
  write(d / "bad.txt", "0.1 0.2\n0.3 1.7\n");
  auto r = run_ppsynth("synthesize --exemplar " + (d / "bad.txt").string() + kQuick + "-o " + (d / "out").string());
  CHECK(r.status == 2);
  CHECK_FALSE(fs::exists(d / "out"));
}

TEST_CASE("outputs never replace a device, FIFO or symbolic link", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_targets");
  const std::string ex = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
  write(d / "pts.txt", "# x y\n0.1 0.2\n0.5 0.5\n");
  // Copies of /dev/full and /dev/null in the scratch directory (a regression replaces only
  // the copies): a full device fails with an error naming it; both stay devices.
  const auto devices = ppsynth::test::scratch_dir("safety_targets_dev");
  const auto full = ppsynth::test::scratch_dev_full(devices), null = ppsynth::test::scratch_dev_null(devices);
  if (full && null) {
    auto r = run_ppsynth("convert " + (d / "pts.txt").string() + " " + *full);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(*full));
    CHECK(fs::is_character_file(*full));
    CHECK(run_ppsynth("convert " + (d / "pts.txt").string() + " " + *null).status == 0);
    CHECK(fs::is_character_file(*null));
  } else {
    WARN("mknod not permitted here: the device part of this test did not run");
  }
  // A FIFO is written into, not replaced.
  const std::string fifo = (d / "fifo").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  auto through = run_ppsynth("convert " + (d / "pts.txt").string() + " " + fifo + " & timeout 30 cat " + fifo + " > " +
                             (d / "from_fifo.txt").string() + "; wait; true");
  CHECK(fs::is_fifo(fifo));
  CHECK_THAT(ppsynth::read_file_text((d / "from_fifo.txt").string()), Catch::Contains("0.5"));
  // A symbolic link stays a link; the file it points to gets the new content (with --force:
  // the file exists).
  write(d / "target.txt", "old\n");
  fs::create_symlink(d / "target.txt", d / "link.txt");
  CHECK(run_ppsynth("convert " + (d / "pts.txt").string() + " " + (d / "link.txt").string()).status == 2);
  CHECK(run_ppsynth("convert " + (d / "pts.txt").string() + " " + (d / "link.txt").string() + " --force").status == 0);
  CHECK(fs::is_symlink(d / "link.txt"));
  CHECK_THAT(ppsynth::read_file_text((d / "target.txt").string()), Catch::Contains("0.5"));
  // A directory is refused.
  auto dir = run_ppsynth("convert " + (d / "pts.txt").string() + " " + d.string());
  CHECK(dir.status == 2);
  CHECK_THAT(dir.output, Catch::Contains("is a directory"));
}

TEST_CASE("impossible parameters are refused with their key, before any work", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_params");
  const std::string out = " -o " + (d / "x").string();
  struct Case {
    std::string set, key;
  };
  for (const Case& c : {Case{"method.convergence.check_every=0", "method.convergence.check_every"},
                        Case{"method.convergence.window=-5", "method.convergence.window"},
                        Case{"method.convergence.check_every=2.5", "method.convergence.check_every"},
                        Case{"method.max_iterations=3000000000", "method.max_iterations"},
                        Case{"method.k=0", "method.k"},
                        Case{"method.optimizer.lr=[0.1,-1]", "method.optimizer.lr[1]"},
                        Case{"method.feature_net.kernel_size=0", "method.feature_net.kernel_size"},
                        Case{"upscale=0", "upscale"},
                        Case{"upscale=100000", "upscale"}}) {
    auto r = run_ppsynth("synthesize " + kLines + kQuick + "--set " + c.set + out);
    INFO(c.set << ": " << r.output);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(c.key));
    CHECK_FALSE(fs::exists(d / "x"));
  }
}

TEST_CASE("sizes are checked against memory before allocating", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_memory");
  auto gen = run_ppsynth("generate uniform -n 100000000 -o " + (d / "p.txt").string(), "PPSYNTH_MEMORY_LIMIT_MB=64");
  CHECK(gen.status == 2);
  CHECK_THAT(gen.output, Catch::Contains("100000000 points") && Catch::Contains("GiB"));
  CHECK_FALSE(fs::exists(d / "p.txt"));
  auto grid = run_ppsynth("synthesize " + kLines + " -q --set method.grid.res=8192 --set upscale=8 -o " + (d / "g").string());
  CHECK(grid.status == 2);
  CHECK_THAT(grid.output, Catch::Contains("65536 x 65536"));
  CHECK_FALSE(fs::exists(d / "g"));
}

TEST_CASE("the thread count is validated and recorded", "[apps][safety]") {
  auto d = ppsynth::test::scratch_dir("safety_threads");
  auto bad = run_ppsynth("synthesize " + kLines + kQuick + "-o " + (d / "a").string(), "PPSYNTH_THREADS=two");
  CHECK(bad.status == 2);
  CHECK_THAT(bad.output, Catch::Contains("PPSYNTH_THREADS"));
  REQUIRE(run_ppsynth("synthesize " + kLines + kQuick + "-o " + (d / "b").string(), "PPSYNTH_THREADS=1").status == 0);
  CHECK_THAT(ppsynth::read_file_text((d / "b" / "run.json").string()), Catch::Contains("\"threads\": 1"));
}
