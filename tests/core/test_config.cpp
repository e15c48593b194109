#include <catch2/catch.hpp>

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
                 [](const json& p) { return std::make_unique<Seven>(p["v"].get<int>()); })

TEST_CASE("registry creates by name with defaults and refuses duplicates", "[config]") {
  auto t = ThingRegistry::instance().create(json{{"type", "seven"}}, "thing");
  CHECK(t->value() == 7);
  CHECK(ThingRegistry::instance().create(json{{"type", "seven"}, {"v", 3}}, "thing")->value() == 3);
  CHECK_THROWS_WITH(ThingRegistry::instance().create(json{{"type", "eight"}}, "thing"), Catch::Contains("thing.type"));
  CHECK_THROWS_WITH(ThingRegistry::instance().create(json{{"type", "seven"}, {"w", 1}}, "thing"), Catch::Contains("thing.w"));
  CHECK_THROWS_AS(ThingRegistry::instance().add("seven", ThingRegistry::Entry{}), std::logic_error);
}

TEST_CASE("number lists (seeds, stages): numbers and ranges, in order, without repeats", "[config]") {
  CHECK(parse_number_list(json::array({95, "96-98", 95}), "seeds", "seed") == std::vector<uint64_t>{95, 96, 97, 98});
  CHECK(parse_number_list(json("7-7"), "seeds", "seed") == std::vector<uint64_t>{7});
  CHECK(parse_number_list(json("95,97-98"), "seeds", "seed") == std::vector<uint64_t>{95, 97, 98});
  CHECK(parse_number_list(json("95"), "seeds", "seed") == std::vector<uint64_t>{95});
  CHECK_THROWS_WITH(parse_number_list(json("95,x"), "seeds", "seed"), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json("9--3"), "seeds", "seed"), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array({"9-3"}), "seeds", "seed"), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array({-1}), "seeds", "seed"), Catch::Contains("seeds[0]"));
  CHECK_THROWS_WITH(parse_number_list(json::array(), "seeds", "seed"), Catch::Contains("no seeds"));
  // The errors call the numbers what they are.
  CHECK_THROWS_WITH(parse_number_list(json("1-x"), "--stage", "stage"), Catch::Contains("--stage[0]") && Catch::Contains("expected a stage >= 0"));
}

