// RunDirectory: which directories ppsynth may write whole, and what --force may replace.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/config/param_bounds.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/run_directory.hpp"
#include "tests/support/device_nodes.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ppsynth;

TEST_CASE("output directories are normalized and never the current directory or a parent", "[run_directory]") {
  auto d = test::scratch_dir("rundir_norm");
  const auto cwd = fs::current_path();
  fs::current_path(d);
  CHECK(normalize_output_dir("runs/a/", "-o") == "runs/a");
  CHECK(normalize_output_dir("runs/./a//", "-o") == "runs/a");
  CHECK(normalize_output_dir("runs/x/../a", "-o") == "runs/a");
  for (const std::string& bad : std::vector<std::string>{"", ".", "./", "..", "../", "/", "a/..", d.string(), d.parent_path().string()})
    CHECK_THROWS_AS(normalize_output_dir(bad, "-o"), InputError);
  fs::current_path(cwd);
}

TEST_CASE("plain names", "[run_directory]") {
  CHECK(is_safe_name("lines_4c-v2"));
  for (const std::string bad : {"", ".", "..", "a/b", "../x", "a b", "a.json", "é"}) CHECK_FALSE(is_safe_name(bad));
}

TEST_CASE("a run directory: created, locked, marked, replaced only with force", "[run_directory]") {
  auto d = test::scratch_dir("rundir_life");
  const std::string p = (d / "run").string();
  CHECK(run_dir_state(p) == RunDirState::Absent);
  {
    RunDirectory dir = RunDirectory::open(p + "/", {});
    CHECK(dir.path() == p);
    CHECK(run_dir_state(p) == RunDirState::Unfinished);
    // Held by this process: a second open (another open file description) is refused.
    CHECK_THROWS_WITH(RunDirectory::open(p, {}), Catch::Contains("another ppsynth process"));
    RunDirOptions force;
    force.force = true;
    CHECK_THROWS_WITH(RunDirectory::open(p, force), Catch::Contains("another ppsynth process"));
    write_text_atomic(p + "/output.txt", "1\n");
    // Progress is merged key by key while the run is on its way, and dropped once it is complete.
    dir.mark_progress({{"stage", "sigma 1/4"}, {"index", 1}});
    dir.mark_progress({{"checkpointed", 12}});
    CHECK(run_dir_marker(p)["progress"] == nlohmann::json{{"stage", "sigma 1/4"}, {"index", 1}, {"checkpointed", 12}});
    CHECK(run_dir_state(p) == RunDirState::Unfinished);
    dir.mark_complete({{"seed", 3}});
  }
  CHECK(run_dir_state(p) == RunDirState::Complete);
  CHECK(run_dir_marker(p)["seed"] == 3);
  CHECK_FALSE(run_dir_marker(p).contains("progress"));
  CHECK_THROWS_WITH(RunDirectory::open(p, {}), Catch::Contains("--force") && Catch::Contains("finished"));
  CHECK(fs::exists(p + "/output.txt"));
  RunDirOptions force;
  force.force = true;
  {
    RunDirectory again = RunDirectory::open(p, force);
    CHECK_FALSE(fs::exists(p + "/output.txt"));  // the old run's files are gone, the marker is new
    CHECK(run_dir_state(p) == RunDirState::Unfinished);
  }
  // An unfinished run (a killed process): refused without force too, naming it.
  CHECK_THROWS_WITH(RunDirectory::open(p, {}), Catch::Contains("unfinished"));
}

TEST_CASE("foreign paths are refused even with force", "[run_directory]") {
  auto d = test::scratch_dir("rundir_foreign");
  std::ofstream(d / "file") << "x";
  fs::create_directories(d / "theirs");
  std::ofstream(d / "theirs" / "a.txt") << "a";
  fs::create_symlink(d / "theirs", d / "link");
  RunDirOptions force;
  force.force = true;
  for (const std::string name : {"file", "theirs", "link"}) {
    CHECK_THROWS_AS(RunDirectory::open((d / name).string(), {}), InputError);
    CHECK_THROWS_AS(RunDirectory::open((d / name).string(), force), InputError);
  }
  CHECK(read_file_text((d / "theirs" / "a.txt").string()) == "a");
  CHECK(run_dir_state((d / "theirs").string()) == RunDirState::Foreign);
}

TEST_CASE("discard removes what the run wrote and nothing else", "[run_directory]") {
  auto d = test::scratch_dir("rundir_discard");
  {
    RunDirectory created = RunDirectory::open((d / "new").string(), {});
    write_text_atomic((d / "new" / "a.txt").string(), "a");
    created.discard();
  }
  CHECK_FALSE(fs::exists(d / "new"));
  fs::create_directories(d / "empty");
  {
    RunDirectory given = RunDirectory::open((d / "empty").string(), {});
    write_text_atomic((d / "empty" / "a.txt").string(), "a");
    given.discard();
  }
  CHECK(fs::is_directory(d / "empty"));  // the user made it: it stays, empty
  CHECK(fs::is_empty(d / "empty"));
}

TEST_CASE("atomic writes never replace a special file or follow a directory", "[run_directory]") {
  auto d = test::scratch_dir("atomic_targets");
  const auto devices = test::scratch_dir("atomic_targets_dev");
  const auto full = test::scratch_dev_full(devices), null = test::scratch_dev_null(devices);
  if (full && null) {
    CHECK_THROWS_WITH(write_text_atomic(*full, "x\n"), Catch::Contains(*full));
    CHECK(fs::is_character_file(*full));
    CHECK_NOTHROW(write_text_atomic(*null, "x\n"));
    CHECK(fs::is_character_file(*null));
  } else {
    WARN("mknod not permitted here: the device part of this test did not run");
  }
  CHECK_THROWS_WITH(write_text_atomic(d.string(), "x\n"), Catch::Contains("is a directory"));
  std::ofstream(d / "t.txt") << "old";
  fs::create_symlink("t.txt", d / "l.txt");  // relative link
  write_text_atomic((d / "l.txt").string(), "new");
  CHECK(fs::is_symlink(d / "l.txt"));
  CHECK(read_file_text((d / "t.txt").string()) == "new");
  std::vector<std::string> left;
  for (auto& e : fs::directory_iterator(d)) left.push_back(e.path().filename().string());
  CHECK(left.size() == 2);  // no temp file left behind
}

TEST_CASE("parameter bounds", "[config][bounds]") {
  const nlohmann::json b = {{"n", "int [1, inf)"}, {"x", "(0, 1]"}, {"g", {{"w", "[0, 10)"}}}, {"l", "(0, inf)"}};
  CHECK_NOTHROW(check_bounds({{"n", 3}, {"x", 1.0}, {"g", {{"w", 0}}}, {"l", {0.1, 2}}}, b, "m"));
  CHECK_THROWS_WITH(check_bounds({{"n", 0}}, b, "m"), Catch::Contains("m.n") && Catch::Contains("int [1, inf)"));
  CHECK_THROWS_WITH(check_bounds({{"n", 2.5}}, b, "m"), Catch::Contains("m.n") && Catch::Contains("whole number"));
  CHECK_THROWS_WITH(check_bounds({{"x", 0}}, b, "m"), Catch::Contains("m.x"));
  CHECK_THROWS_WITH(check_bounds({{"g", {{"w", 10}}}}, b, "m"), Catch::Contains("m.g.w"));
  CHECK_THROWS_WITH(check_bounds({{"l", {1, -1}}}, b, "m"), Catch::Contains("m.l[1]"));
  CHECK_THROWS_WITH(check_bounds({{"n", "3"}}, b, "m"), Catch::Contains("expected a number"));
  CHECK_THROWS_AS(check_bounds({{"n", 1}}, {{"n", "[1, 2"}}, "m"), std::logic_error);
  // Alternatives: one number or an interval ("0" asks for the automatic choice).
  const nlohmann::json res = {{"res", "0 or int [8, 8192]"}};
  CHECK_NOTHROW(check_bounds({{"res", 0}}, res, "grid"));
  CHECK_NOTHROW(check_bounds({{"res", 8}}, res, "grid"));
  CHECK_THROWS_WITH(check_bounds({{"res", 5}}, res, "grid"), Catch::Contains("grid.res") && Catch::Contains("0 or int [8, 8192]"));
  CHECK_THROWS_WITH(check_bounds({{"res", 8.5}}, res, "grid"), Catch::Contains("grid.res"));
  CHECK_THROWS_AS(check_bounds({{"res", 8}}, {{"res", "0 or "}}, "grid"), std::logic_error);
  CHECK(unbounded_numbers({{"n", 1}, {"s", "x"}, {"g", {{"w", 2}, {"v", 3}}}, {"c", {{"type", "t"}, {"q", 1}}}}, b) ==
        std::vector<std::string>{"g.v"});
}
