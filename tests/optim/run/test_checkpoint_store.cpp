// The one checkpoint store of the run directory, bench and the Python binding.
#include <catch2/catch.hpp>

#include <filesystem>

#include "core/error.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;

TEST_CASE("a checkpoint store saves, replaces, loads and removes one file", "[optim][checkpoint][run]") {
  const auto dir = test::scratch_dir("checkpoint_store");
  CheckpointStore store(checkpoint_file_in(dir.string()));
  CHECK(store.file() == dir.string() + "/checkpoint.bin");
  CHECK_FALSE(store.exists());
  CHECK_FALSE(store.saved());
  CHECK_THROWS_AS(store.load(), InputError);
  CHECK_THROWS_WITH(store.load(), Catch::Contains(store.file()));

  int after = 0;
  auto save = store.saver([&] { ++after; });
  save(std::string("first\0bytes", 11));
  CHECK(store.saved());
  CHECK(after == 1);
  CHECK(store.load() == std::string("first\0bytes", 11));  // binary, whole
  save("second");
  CHECK(after == 2);
  CHECK(store.load() == "second");  // replaced, not appended
  CHECK(store.last_size() == 6);
  // The atomic write leaves no temporary file beside the checkpoint.
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);

  store.remove();
  CHECK_FALSE(store.exists());
  store.remove();  // none: no error
}
