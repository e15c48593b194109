// Presets (optim/run/presets.hpp): layered under the config's own keys, over the defaults;
// named in the resolved config; a variant per processor class where a preset has one; unknown
// names and other methods refused with the key.
#include <catch2/catch.hpp>

#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "models/feature_net.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;

TEST_CASE("the fast preset sets its keys under the config's own", "[optim][config][preset]") {
  const json plain = resolve_run_config(json::object(), {});
  CHECK(plain["preset"].is_null());
  CHECK(plain["method"]["feature_net"] == json{{"type", "random"}});  // the network's own defaults apply when it is made
  CHECK(plain["method"]["convergence"]["type"] == "loss");

  const json fast = resolve_run_config(json{{"preset", "fast"}}, {});
  const json frag = preset_fragment("fast")["method"];
  CHECK(fast["preset"] == "fast");
  for (auto it = frag.begin(); it != frag.end(); ++it) {
    INFO("method." << it.key());
    // every key the preset names arrives in the resolved method, merged with the defaults
    CHECK(merge(fast["method"][it.key()], it.value()) == fast["method"][it.key()]);
  }
  CHECK(fast["method"]["feature_net"]["type"] == "random");  // the defaults fill the rest
  CHECK(fast["method"]["map_terms"] == plain["method"]["map_terms"]);  // class_own is on in both (the default)
  CHECK(fast["method"]["c1"] == plain["method"]["c1"]);

  // The config's own keys and --set win over the preset.
  const json own = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"channels", 24}}}}}},
                                      {"method.convergence.window=70"});
  CHECK(own["method"]["feature_net"]["channels"] == 24);
  CHECK(own["method"]["feature_net"]["precision"] == frag["feature_net"]["precision"]);
  CHECK(own["method"]["convergence"]["window"] == 70);
  CHECK(own["method"]["convergence"]["type"] == frag["convergence"]["type"]);
  // --set preset=fast is the same as the key in the config
  CHECK(resolve_run_config(json::object(), {"preset=fast"}) == fast);
}

TEST_CASE("the fast preset by processor class: auto precision, and its float32 variant where bf16 is emulated", "[optim][config][preset][isa]") {
  const json with_units = preset_fragment("fast", true)["method"], without = preset_fragment("fast", false)["method"];
  // One fragment for both but the knobs that buy back bf16's time.
  CHECK(with_units["feature_net"]["precision"] == "auto");
  CHECK(without["feature_net"]["precision"] == "auto");
  CHECK(with_units["convergence"] == without["convergence"]);
  CHECK(with_units["grid"] == without["grid"]);
  CHECK_FALSE(with_units["feature_net"].contains("channels"));  // the paper's 120 filters where bf16 is native
  // Without them, fewer float32 filters, for one class and for several.
  CHECK(with_channels_for_classes(without["feature_net"], 1, "f")["channels"].get<int>() < 120);
  CHECK(with_channels_for_classes(without["feature_net"], 2, "f")["channels"].get<int>() < 120);
  // This process takes the variant of its own processor, and run.json says which and why.
  CHECK(preset_fragment("fast") == preset_fragment("fast", cpu_isa().native_bf16));
  const json fast = resolve_run_config(json{{"preset", "fast"}}, {});
  const json record = preset_record(fast["preset"], fast["runtime"]["device"]);
  CHECK(record["name"] == "fast");
  CHECK(record["variant"] == (cpu_isa().native_bf16 ? "every processor" : "without bf16 units"));
  CHECK(record["reason"].get<std::string>().find(processor_kind()) != std::string::npos);
  const json none = resolve_run_config(json::object(), {});
  CHECK(preset_record(none["preset"], none["runtime"]["device"]).is_null());
}

TEST_CASE("the fast preset's float32 variant: 64 filters for a one-class and a multi-class exemplar", "[optim][config][preset]") {
  // The variant as the run resolves it (whatever this processor is), down to the settings the
  // pipeline makes its network from.
  json method = merge(json{{"type", "gabor"}}, preset_fragment("fast", false)["method"]);
  method["grid"]["res"] = 32;
  const json p = test::method_params(method);
  OutputShape shape;
  shape.upscale = 2;
  CHECK(resolve_gabor_settings(p, test::small_exemplar(1, false), shape, false).feature_net["channels"] == 64);
  CHECK(resolve_gabor_settings(p, test::small_exemplar(2, false), shape, false).feature_net["channels"] == 64);
  // A config's own number holds for both.
  json own = method;
  own["feature_net"]["channels"] = 24;
  const json q = test::method_params(own);
  CHECK(resolve_gabor_settings(q, test::small_exemplar(2, false), shape, false).feature_net["channels"] == 24);
}

TEST_CASE("presets: unknown names and other methods are errors naming the key", "[optim][config][preset]") {
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", "fastest"}}, {}), Catch::Contains("preset") && Catch::Contains("fast"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", 3}}, {}), Catch::Contains("preset"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"preset", "fast"}, {"method", {{"type", "tiled_copy"}}}}, {}),
                    Catch::Contains("preset") && Catch::Contains("tiled_copy"));
  CHECK_THROWS_WITH(preset_fragment("fastest"), Catch::Contains("preset"));
}

TEST_CASE("presets on an ablation's other network: the keys it lacks are left out, the user's are still refused", "[optim][config][preset]") {
  // Fig. 12b's "identity" net and Fig. 10's "fixed_bank" declare no precision or filter count:
  // the fast preset still applies to those panels (before, the run stopped on
  // 'method.feature_net.precision': unknown key).
  for (const bool bf16_units : {true, false}) {
    INFO("bf16 units " << bf16_units);
    CHECK(preset_fragment("fast", bf16_units)["method"]["feature_net"].contains("precision"));
  }
  const json identity = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"type", "identity"}}}}}}, {});
  CHECK(identity["method"]["feature_net"] == json{{"type", "identity"}});
  CHECK(identity["method"]["convergence"]["type"] == preset_fragment("fast")["method"]["convergence"]["type"]);  // the rest of the preset holds
  CHECK(identity["method"]["grid"]["per_sigma"] == true);
  CHECK_NOTHROW(FeatureNetRegistry::instance().resolve(identity["method"]["feature_net"], "method.feature_net"));
  const json bank = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"type", "fixed_bank"}, {"bank", "sobel"}}}}}}, {});
  CHECK_FALSE(bank["method"]["feature_net"].contains("precision"));
  CHECK_NOTHROW(FeatureNetRegistry::instance().resolve(bank["method"]["feature_net"], "method.feature_net"));
  // The default network keeps the preset's keys.
  const json random = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"type", "random"}}}}}}, {});
  CHECK(random["method"]["feature_net"]["precision"] == "auto");
  // A key the user writes that the network lacks is refused, naming it.
  const json own = resolve_run_config(json{{"preset", "fast"}, {"method", {{"feature_net", {{"type", "identity"}, {"precision", "auto"}}}}}}, {});
  CHECK_THROWS_WITH(FeatureNetRegistry::instance().resolve(own["method"]["feature_net"], "method.feature_net"),
                    Catch::Contains("method.feature_net.precision"));
}
