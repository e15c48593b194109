#include <catch2/catch.hpp>

#include <limits>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"

using namespace ppsynth;

TEST_CASE("apply_defaults merges and names unknown keys", "[config]") {
  json defaults = {{"a", 1}, {"b", {{"c", "x"}, {"d", true}}}};
  json user = {{"b", {{"c", "y"}}}};
  json out = apply_defaults(defaults, user, "");
  CHECK(out["a"] == 1);
  CHECK(out["b"]["c"] == "y");
  CHECK(out["b"]["d"] == true);
  try {
    apply_defaults(defaults, json{{"b", {{"e", 1}}}}, "root");
    FAIL("unknown key accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("root.b.e") != std::string::npos);
  }
  CHECK_THROWS_WITH(apply_defaults(defaults, json{{"a", "str"}}, ""), Catch::Contains("'a'") && Catch::Contains("number"));
}

TEST_CASE("merge: objects merge, a component whose type changes is replaced", "[config]") {
  json parent = {{"seed", 1}, {"method", {{"type", "gabor"}, {"c1", 2.0}, {"grid", {{"res", 64}, {"max_res", 256}}}}}};
  json same = merge(parent, json{{"method", {{"type", "gabor"}, {"grid", {{"res", 32}}}}}});
  CHECK(same["method"]["c1"] == 2.0);
  CHECK(same["method"]["grid"]["res"] == 32);
  CHECK(same["method"]["grid"]["max_res"] == 256);
  CHECK(same["seed"] == 1);
  json other = merge(parent, json{{"method", {{"type", "roveri2015"}}}});
  CHECK(other["method"] == json{{"type", "roveri2015"}});
  CHECK(other["seed"] == 1);
}

TEST_CASE("set_override parses JSON values and paths", "[config]") {
  json c = {{"losses", json::array({json{{"weight", 1.0}}})}, {"seed", 1}};
  set_override(c, "seed=42");
  set_override(c, "losses.0.weight=0.5");
  set_override(c, "name=lines");
  CHECK(c["seed"] == 42);
  CHECK(c["losses"][0]["weight"] == 0.5);
  CHECK(c["name"] == "lines");
  CHECK_THROWS_AS(set_override(c, "losses.3.weight=1"), InputError);
  for (const char* bad : {"a..b=1", ".a=1", "a.=1"})
    CHECK_THROWS_WITH(set_override(c, bad), Catch::Contains("empty key component") && Catch::Contains(bad));
}

TEST_CASE("set_at_key_path sets a value (not text) and names the path it cannot follow", "[config]") {
  json c = {{"losses", json::array({json{{"weight", 1.0}}})}, {"name", "x"}};
  set_at_key_path(c, "description", "123");  // a string stays a string: no JSON parsing
  set_at_key_path(c, "losses.0.weight", 2.5);
  set_at_key_path(c, "method.feature_net.channels", 64);  // objects made on the way
  CHECK(c["description"] == "123");
  CHECK(c["losses"][0]["weight"] == 2.5);
  CHECK(c["method"]["feature_net"]["channels"] == 64);
  CHECK_THROWS_WITH(set_at_key_path(c, "losses.x", 1), Catch::Contains("'x' is not an array index"));
  CHECK_THROWS_WITH(set_at_key_path(c, "name.first", 1), Catch::Contains("below a value that is not an object"));
  CHECK_THROWS_WITH(set_at_key_path(c, "a..b", 1), Catch::Contains("key path 'a..b': empty key component"));
}

namespace {
struct Thing {
  virtual ~Thing() = default;
  virtual int value() const = 0;
};
struct Seven : Thing {
  int v;
  explicit Seven(int v) : v(v) {}
  int value() const override { return v; }
};
using ThingRegistry = Registry<Thing>;
}  // namespace

PPSYNTH_REGISTER(ThingRegistry, "seven", (json{{"v", 7}}), (json{{"v", "int [0, 100]"}}), "test part",
                 [](const json& p, const std::string& key) {
                   // What a range cannot say is the factory's to refuse, under the key path it is given.
                   if (p["v"].get<int>() == 13) throw config_error(key + ".v", "unlucky");
                   return std::make_unique<Seven>(p["v"].get<int>());
                 })

TEST_CASE("registry creates by name with defaults and refuses duplicates", "[config]") {
  auto t = ThingRegistry::instance().create(json{{"type", "seven"}}, "thing");
  CHECK(t->value() == 7);
  CHECK(ThingRegistry::instance().create(json{{"type", "seven"}, {"v", 3}}, "thing")->value() == 3);
  CHECK_THROWS_WITH(ThingRegistry::instance().create(json{{"type", "eight"}}, "thing"), Catch::Contains("thing.type"));
  CHECK_THROWS_WITH(ThingRegistry::instance().create(json{{"type", "seven"}, {"w", 1}}, "thing"), Catch::Contains("thing.w"));
  CHECK_THROWS_AS(ThingRegistry::instance().add("seven", ThingRegistry::Entry{}), std::logic_error);
}

TEST_CASE("a registry hands its factory the key path, and resolves a spec without building the part", "[config]") {
  // The factory's own refusal names the whole key as the caller placed the part.
  CHECK_THROWS_WITH(ThingRegistry::instance().create(json{{"type", "seven"}, {"v", 13}}, "method.things[2]"),
                    Catch::Contains("method.things[2].v") && Catch::Contains("unlucky"));
  // resolve: the declared defaults under the user's keys, "type" kept, bounds checked, no part.
  CHECK(ThingRegistry::instance().resolve(json{{"type", "seven"}}, "thing") == json{{"type", "seven"}, {"v", 7}});
  CHECK(ThingRegistry::instance().resolve(json{{"type", "seven"}, {"v", 13}}, "thing") == json{{"type", "seven"}, {"v", 13}});
  CHECK_THROWS_WITH(ThingRegistry::instance().resolve(json{{"type", "seven"}, {"v", 101}}, "thing"), Catch::Contains("thing.v"));
  json resolved;
  ThingRegistry::instance().create(json{{"type", "seven"}, {"v", 3}}, "thing", &resolved);
  CHECK(resolved == json{{"type", "seven"}, {"v", 3}});
}

TEST_CASE("number lists (seeds, stages): numbers and ranges, in order, without repeats", "[config]") {
  const uint64_t seeds = (uint64_t{1} << 63) - 1;
  CHECK(parse_number_list(json::array({95, "96-98", 95}), "seeds", "seed", seeds) == std::vector<uint64_t>{95, 96, 97, 98});
  CHECK(parse_number_list(json("7-7"), "seeds", "seed", seeds) == std::vector<uint64_t>{7});
  CHECK(parse_number_list(json("95,97-98"), "seeds", "seed", seeds) == std::vector<uint64_t>{95, 97, 98});
  CHECK(parse_number_list(json("95"), "seeds", "seed", seeds) == std::vector<uint64_t>{95});
  CHECK_THROWS_WITH(parse_number_list(json("95,x"), "seeds", "seed", seeds), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json("9--3"), "seeds", "seed", seeds), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array({"9-3"}), "seeds", "seed", seeds), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array({-1}), "seeds", "seed", seeds), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array(), "seeds", "seed", seeds), Catch::Contains("no seeds"));
  // The errors call the numbers what they are.
  CHECK_THROWS_WITH(parse_number_list(json("1-x"), "--stage", "stage", 100000),
                    Catch::Contains("--stage[0]") && Catch::Contains("expected a stage from 0 to 100000"));
}

TEST_CASE("number lists near 2^64 are refused, never saturated or looped over", "[config]") {
  // The defect: sscanf("%llu") saturated 2^64 and beyond to 2^64 - 1, and `v <= last` never
  // failed for a range ending there: the loop ran on and allocated until memory was gone.
  const uint64_t max = std::numeric_limits<uint64_t>::max();
  for (const std::string text : {"18446744073709551615", "18446744073709551614-18446744073709551615",
                                 "99999999999999999999", "18446744073709551616-18446744073709551620"})
    CHECK_THROWS_WITH(parse_number_list(json(text), "seeds", "seed", (uint64_t{1} << 63) - 1), Catch::Contains("seeds[0]"));
  // With the whole range allowed, a range ending at 2^64 - 1 ends there.
  CHECK(parse_number_list(json("18446744073709551614-18446744073709551615"), "n", "number", max) ==
        std::vector<uint64_t>{max - 1, max});
  CHECK_THROWS_WITH(parse_number_list(json("18446744073709551616"), "n", "number", max), Catch::Contains("past"));
  CHECK_THROWS_WITH(parse_number_list(json::array({100001}), "--stage", "stage", 100000), Catch::Contains("past 100000"));
  for (const std::string text : {"+5", " 5", "5 ", "1e3", "0x10", "5-", "-5", ""})
    CHECK_THROWS_AS(parse_number_list(json(text), "seeds", "seed", 1000), InputError);
  CHECK_THROWS_WITH(parse_number_list(json("0-100000"), "seeds", "seed", 1000000), Catch::Contains("spans more than"));
}


