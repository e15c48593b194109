// Nothing lost, nothing crashes, configs: every bad config is an InputError
// naming the file (and line) or the key path; never a crash, never another exception.
#include <climits>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

using test::require_input_error;
using test::write_file;

TEST_CASE("a config nested 10^6 levels deep is refused before it recurses", "[config][input]") {
  const auto dir = test::scratch_dir("input_config_deep");
  const size_t depth = 1000000;
  // Crashed with SIGSEGV (stack overflow).
  const std::string f =
      write_file(dir, "deep.json", "{\"seed\": 1,\n \"method\": " + std::string(depth, '[') + std::string(depth, ']') + "}");
  require_input_error([&] { load_config(f); }, {f + ":2:", "nest"});
  const std::string o = write_file(dir, "deep_obj.json", "{\"a\":\n" + [&] {
    std::string s;
    for (int i = 0; i < 200000; ++i) s += "{\"a\":";
    s += "1";
    s += std::string(200000, '}');
    return s;
  }() + "}");
  require_input_error([&] { load_config(o); }, {o + ":2:", "nest"});
  // In a parent: the parent's file is named.
  const std::string child = write_file(dir, "child.json", "{\"parent\": \"deep.json\"}");
  require_input_error([&] { load_config(child); }, {f + ":2:", "nest"});
  // Ordinary nesting reads.
  const std::string ok = write_file(dir, "ok.json", "{\"a\": {\"b\": {\"c\": [[1, 2], [3]]}}}");
  CHECK(load_config(ok)["a"]["b"]["c"][0][1] == 2);
}

TEST_CASE("a config number beyond double or beyond 64 bits is refused with file and line", "[config][input]") {
  const auto dir = test::scratch_dir("input_config_numbers");
  const std::string f = write_file(dir, "big.json", "{\n  \"seed\": 1,\n  \"scale\": 1e400\n}\n");
  require_input_error([&] { load_config(f); }, {f + ":3:", "1e400"});
  const std::string g = write_file(dir, "neg.json", "{\n  \"scale\":\n -1e400}\n");
  require_input_error([&] { load_config(g); }, {g + ":3:", "1e400"});
  // A syntax error names the line too.
  const std::string s = write_file(dir, "syntax.json", "{\n  \"seed\": 1,\n  \"x\": [1 2]\n}\n");
  require_input_error([&] { load_config(s); }, {s + ":3:", "invalid JSON"});
}

TEST_CASE("a directory given as a config or as a parent says so", "[config][input]") {
  const auto dir = test::scratch_dir("input_config_dir");
  fs::create_directories(dir / "d.json");
  const std::string d = (dir / "d.json").string();
  require_input_error([&] { load_config(d); }, {d, "is a directory"});
  const std::string child = write_file(dir, "child.json", "{\"parent\": \"d.json\"}");
  require_input_error([&] { load_config(child); }, {"d.json", "is a directory"});
  const std::string empty_parent = write_file(dir, "empty_parent.json", "{\"parent\": \"\"}");
  require_input_error([&] { load_config(empty_parent); }, {"empty_parent.json", "parent"});
  // A non-string parent names the file as well as the key.
  const std::string num_parent = write_file(dir, "num_parent.json", "{\"parent\": 3}");
  require_input_error([&] { load_config(num_parent); }, {"num_parent.json", "parent"});
}

TEST_CASE("get_int refuses integers beyond the int range with the key path and the range", "[config][input]") {
  const json j = {{"n", 4294967297LL}, {"m", -3000000000LL}, {"f", 1e30}, {"u", 18446744073709551615ULL},
                  {"ok", 2147483647}, {"half", 2.5}};
  // Was 1 (static_cast overflow) or a wrong message.
  require_input_error([&] { get_int(j, "n", "method"); }, {"'method.n'", "2147483647"});
  require_input_error([&] { get_int(j, "m", "method"); }, {"'method.m'", "-2147483648"});
  require_input_error([&] { get_int(j, "f", "method"); }, {"'method.f'", "2147483647"});
  require_input_error([&] { get_int(j, "u", "method"); }, {"'method.u'", "2147483647"});
  require_input_error([&] { get_int(j, "half", "method"); }, {"'method.half'", "integer"});
  CHECK(get_int(j, "ok", "method") == INT_MAX);
}

TEST_CASE("set_override (--set) goes through the same checks", "[config][input]") {
  json c = {{"seed", 1}, {"method", {{"iterations", 10}}}};
  // Was stored as the string "1e400" (the JSON parse failed with out_of_range).
  require_input_error([&] { set_override(c, "method.iterations=1e400"); }, {"method.iterations", "1e400"});
  // Was accepted; writing or merging it later recursed 10^6 levels deep.
  const std::string deep = std::string(1000000, '[') + std::string(1000000, ']');
  require_input_error([&] { set_override(c, "method.x=" + deep); }, {"method.x", "nest"});
  // Integers beyond int reach get_int with their key path.
  set_override(c, "method.iterations=4294967297");
  require_input_error([&] { get_int(c["method"], "iterations", "method"); }, {"'method.iterations'", "2147483647"});
  // An array index beyond 64 bits.
  json a = {{"losses", json::array({json{{"weight", 1.0}}})}};
  require_input_error([&] { set_override(a, "losses.99999999999999999999999.weight=1"); }, {"losses"});
  CHECK(c["seed"] == 1);
}

TEST_CASE("a UTF-8 byte-order mark at the start of a config is skipped", "[config][input]") {
  const auto dir = test::scratch_dir("input_config_bom");
  const std::string f = write_file(dir, "bom.json", "\xEF\xBB\xBF{\"seed\": 3}");
  CHECK(load_config(f)["seed"] == 3);
  const std::string child = write_file(dir, "child.json", "\xEF\xBB\xBF{\"parent\": \"bom.json\", \"x\": 1}");
  CHECK(load_config(child)["seed"] == 3);
}
