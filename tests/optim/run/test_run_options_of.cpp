// A run config as its readers take it (optim/run/run_options_of.hpp): seed, method type and
// runtime through RunOptions' table, a bad value an InputError naming the file and the key, an
// older run's config (keys it predates, keys since retired) still read.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_options_of.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

namespace {
const char* kFile = "runs/a/config.json";
json resolved() { return resolve_run_config(json{{"exemplar", "x.txt"}, {"seed", 7}, {"runtime", {{"device", "auto"}}}}, {}); }
}  // namespace

TEST_CASE("a run config read typed: seed, method type, runtime", "[run][run_options_of]") {
  const TypedRunOptions t = run_options_of(resolved(), kFile);
  CHECK(t.seed == 7);
  CHECK(t.method_type == "gabor");
  CHECK(t.options.runtime.device == "auto");
  CHECK(t.options.upscale == 2);

  // Made before "runtime" and "output" existed, with a key since retired: their defaults.
  json older = resolved();
  older.erase("runtime");
  older.erase("output");
  older["retired_key"] = 1;
  CHECK(run_options_of(older, kFile).options.runtime.device == "cpu");
}

TEST_CASE("a run config's bad values name the file and the key", "[run][run_options_of]") {
  const auto refused = [](const char* key, json value, const char* named) {
    json c = resolved();
    c[json::json_pointer(key)] = std::move(value);
    CHECK_THROWS_AS(run_options_of(c, kFile), InputError);
    CHECK_THROWS_WITH(run_options_of(c, kFile), Contains(kFile) && Contains(named));
  };
  refused("/seed", "95", "seed");
  refused("/seed", -1, "seed");
  refused("/seed", 1.5, "seed");
  refused("/method/type", 3, "method");
  refused("/runtime/device", 5, "runtime.device");
  refused("/runtime/device", "gpu", "runtime.device");
  refused("/runtime", "cuda", "runtime");
  refused("/upscale", "two", "upscale");
}
