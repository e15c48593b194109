// Presets (optim/run/presets.hpp): layered under the config's own keys, over the defaults;
// named in the resolved config; unknown names and other methods refused with the key.
#include <catch2/catch.hpp>

#include "core/config/config.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"

using namespace ppsynth;

TEST_CASE("the fast preset sets its keys under the config's own", "[optim][config][preset]") {
  const json plain = resolve_run_config(json::object(), {});
  CHECK(plain["preset"].is_null());
  CHECK(plain["method"]["feature_net"] == json{{"type", "random"}});  // the network's own defaults apply when it is made
  CHECK(plain["method"]["convergence"]["type"] == "loss");

  const json fast = resolve_run_config(json{{"preset", "fast"}}, {});
  const json frag = presets()["fast"]["config"]["method"];
  CHECK(fast["preset"] == "fast");
  for (auto it = frag.begin(); it != frag.end(); ++it) {
    INFO("method." << it.key());
    // every key the preset names arrives in the resolved method, merged with the defaults
    CHECK(merge(fast["method"][it.key()], it.value()) == fast["method"][it.key()]);
  }
  CHECK(fast["method"]["feature_net"]["type"] == "random");  // the defaults fill the rest
  CHECK(fast["method"]["c1"] == plain["method"]["c1"]);

  // The config's own keys and --set win over the preset.
  const json own = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"channels", 64}}}}}},
                                      {"method.convergence.window=70"});
  CHECK(own["method"]["feature_net"]["channels"] == 64);
  CHECK(own["method"]["feature_net"]["precision"] == frag["feature_net"]["precision"]);
  CHECK(own["method"]["convergence"]["window"] == 70);
  CHECK(own["method"]["convergence"]["type"] == frag["convergence"]["type"]);
  // --set preset=fast is the same as the key in the config
  CHECK(resolve_run_config(json::object(), {"preset=fast"}) == fast);
}

TEST_CASE("presets: unknown names and other methods are errors naming the key", "[optim][config][preset]") {
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", "fastest"}}, {}), Catch::Contains("preset") && Catch::Contains("fast"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", 3}}, {}), Catch::Contains("preset"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", "fast"}, {"method", {{"type", "tiled_copy"}}}}, {}),
                    Catch::Contains("preset") && Catch::Contains("tiled_copy"));
}
