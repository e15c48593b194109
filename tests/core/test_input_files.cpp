// Readers that stop: every point file, config and run record is read through read_file_text,
// which takes regular files only, up to kMaxInputFileBytes, and looks before it opens (a FIFO
// never blocks, /dev/zero is never read). And writers that know before the work: check_writable.
// And file names of any bytes in JSON: shown_text, first_non_utf8.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <iterator>
#include <optional>
#include <string>

#include <catch2/catch.hpp>

#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("point and config readers refuse a device, a FIFO and a directory before reading", "[formats][input-file]") {
  const auto dir = test::scratch_dir("input_file_kinds");
  const std::string fifo = (dir / "pipe.txt").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Was: /dev/zero read until the machine's memory was gone, the FIFO waited for a writer forever.
  struct Case {
    std::string path, says;
  };
  for (const Case& c : {Case{"/dev/zero", "is a character device, not a regular file"},
                        Case{fifo, "is a FIFO (named pipe), not a regular file"},
                        Case{dir.string(), "is a directory"}}) {
    INFO(c.path);
    for (const std::string& e : {input_error_of([&] { read_points(c.path); }), input_error_of([&] { detect_format(c.path); }),
                                 input_error_of([&] { load_config(c.path); }), input_error_of([&] { read_file_text(c.path); }),
                                 input_error_of([&] { check_input_file(c.path); })}) {
      CHECK_THAT(e, Catch::StartsWith(c.path + ": ") && Catch::Contains(c.says));
    }
  }
  // A link to a device is the device.
  fs::create_symlink("/dev/zero", dir / "zero.txt");
  CHECK_THAT(input_error_of([&] { read_points((dir / "zero.txt").string()); }), Catch::Contains("character device"));
  // Missing stays a MissingFileError (Python's FileNotFoundError).
  CHECK_THROWS_AS(read_points((dir / "missing.txt").string()), MissingFileError);
}

TEST_CASE("a file past the size bound is refused before it is read, naming the file and the bound", "[formats][input-file]") {
  const auto dir = test::scratch_dir("input_file_large");
  // A sparse file one byte past the bound: no disk space, no read.
  const std::string big = (dir / "big.txt").string();
  const int fd = ::open(big.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  REQUIRE(fd >= 0);
  const bool sized = ::ftruncate(fd, static_cast<off_t>(kMaxInputFileBytes + 1)) == 0;
  ::close(fd);
  if (!sized) {
    WARN("this file system cannot hold a sparse file past 2 GiB: the bound was not tried");
    return;
  }
  CHECK_THAT(input_error_of([&] { read_points(big); }), Catch::StartsWith(big + ": ") && Catch::Contains("2 GiB"));
  CHECK_THAT(input_error_of([&] { load_config(big); }), Catch::Contains("2 GiB"));
  fs::remove(big);
}

TEST_CASE("a regular file reads byte for byte as before", "[formats][input-file]") {
  const auto dir = test::scratch_dir("input_file_regular");
  std::string text = "# x y\n0.25 0.5\n";
  text += '\0';
  text += "\xff\n";
  const std::string f = test::write_file(dir, "a.txt", text);
  CHECK(read_file_text(f) == text);
  CHECK(read_file_text(test::write_file(dir, "empty.txt", "")).empty());
}

TEST_CASE("check_writable fails before the work where the write would fail after it", "[atomic][input-file]") {
  const auto dir = test::scratch_dir("check_writable");
  const std::string file = test::write_file(dir, "file.txt", "mine\n");
  // The folder is a regular file (root writes everywhere else).
  const std::string under_file = file + "/m.json";
  CHECK_THAT(input_error_of([&] { check_writable(under_file); }),
             Catch::StartsWith(under_file + ": ") && Catch::Contains("is not a folder"));
  const std::string no_folder = (dir / "nosuch" / "m.json").string();
  CHECK_THAT(input_error_of([&] { check_writable(no_folder); }), Catch::Contains("no folder"));
  CHECK_THAT(input_error_of([&] { check_writable(dir.string()); }), Catch::Contains("is a directory"));
  // A writable name passes and leaves nothing behind; a device or FIFO is not opened.
  const std::string fifo = (dir / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(input_error_of([&] { check_writable((dir / "new.json").string()); }).empty());
  CHECK(input_error_of([&] { check_writable(file); }).empty());
  CHECK(input_error_of([&] { check_writable(fifo); }).empty());
  CHECK(input_error_of([&] { check_writable("/dev/null"); }).empty());
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 2);  // file.txt, pipe
  CHECK(read_file_text(file) == "mine\n");
}

TEST_CASE("file names of any bytes go into a JSON report; a config that would record one is refused", "[config][input-file]") {
  const std::string name = "ex\xff" "a.txt";
  CHECK_FALSE(is_utf8(name));
  CHECK(is_utf8("caf\xc3\xa9.txt"));
  const json shown = shown_text(name);
  CHECK(shown.get<std::string>() == "ex\xef\xbf\xbd" "a.txt");  // U+FFFD
  CHECK_NOTHROW(json{{"path", shown}}.dump());
  CHECK(shown_text("plain.txt") == "plain.txt");
  CHECK(first_non_utf8(json{{"exemplar", "a.txt"}, {"method", {{"init", name}}}}) == std::optional<std::string>("method.init"));
  CHECK(first_non_utf8(json{{"runs", {"a", name}}}) == std::optional<std::string>("runs[1]"));
  CHECK_FALSE(first_non_utf8(json{{"exemplar", "caf\xc3\xa9.txt"}}).has_value());
}
