// core/config/params.hpp: a block declared once as a table of one line per key. Its defaults,
// ranges, doc lines, reading and writing all come from the table; reading names the key path
// of a bad value; a ParamReader refuses a key its block does not hold and lists the keys no
// one read.
#include <catch2/catch.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config/param_bounds.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;
using json = nlohmann::json;

namespace {

struct Inner {
  int count = 3;
  static const ParamTable<Inner>& params() {
    static const ParamTable<Inner> t("part.inner", {param("count", &Inner::count, "int [1, 10]", "how many")});
    return t;
  }
};

enum class Shape { round, square };

struct Toy {
  double rate = 0.5;
  bool on = true;
  std::string name = "toy";
  std::vector<int> order;
  std::optional<double> margin;
  Shape shape = Shape::round;
  json spec = {{"type", "x"}};
  Inner inner;
  static const ParamTable<Toy>& params() {
    static const ParamTable<Toy> t("part", {
        param("rate", &Toy::rate, "(0, 1]", "a rate"),
        param("on", &Toy::on, "", "on or off"),
        param("name", &Toy::name, "", "a name"),
        param("order", &Toy::order, "int [0, 9]", "an order"),
        param("margin", &Toy::margin, "[0, inf)", "null or \"auto\": none"),
        choice("shape", &Toy::shape, {{"round", Shape::round}, {"square", Shape::square}}, "a shape"),
        param("spec", &Toy::spec, "", "a part's spec"),
        block("inner", &Toy::inner),
    });
    return t;
  }
};

}  // namespace

TEST_CASE("a table: defaults from the struct's members, bounds, docs, read and written back", "[core][params]") {
  const json d = Toy::params().defaults();
  CHECK(d == json{{"rate", 0.5}, {"on", true}, {"name", "toy"}, {"order", json::array()}, {"margin", nullptr},
                  {"shape", "round"}, {"spec", {{"type", "x"}}}, {"inner", {{"count", 3}}}});
  CHECK(Toy::params().bounds() ==
        json{{"rate", "(0, 1]"}, {"order", "int [0, 9]"}, {"margin", "[0, inf)"}, {"inner", {{"count", "int [1, 10]"}}}});
  CHECK(Toy::params().docs()["inner"]["count"] == "how many");
  CHECK(Toy::params().docs()["margin"] == "null or \"auto\": none");
  CHECK(unbounded_numbers(d, Toy::params().bounds()).empty());
  json b = d;
  b["rate"] = 1;
  b["order"] = {2, 0};
  b["margin"] = 0.25;
  b["shape"] = "square";
  b["inner"]["count"] = 7;
  const Toy t = Toy::params().read(b);
  CHECK(t.rate == 1.0);
  CHECK(t.order == std::vector<int>{2, 0});
  CHECK(t.margin == 0.25);
  CHECK(t.shape == Shape::square);
  CHECK(t.inner.count == 7);
  CHECK(Toy::params().to_json(t) == b);
  b["margin"] = "auto";
  CHECK_FALSE(Toy::params().read(b).margin.has_value());
  // The registry's bound check lets an optional's none through; the table reads it as none.
  CHECK_NOTHROW(check_bounds(b, Toy::params().bounds(), "part"));
}

TEST_CASE("a table names the key path of a bad value", "[core][params]") {
  for (const auto& [key, bad] : {std::pair<const char*, json>{"rate", 0}, {"rate", "fast"}, {"on", 1}, {"name", 2},
                                 {"order", json{1, 10}}, {"order", json{1.5}}, {"order", 3}, {"margin", -1},
                                 {"margin", "wide"}, {"shape", "oval"}}) {
    json b = Toy::params().defaults();
    b[key] = bad;
    INFO(key << " = " << bad.dump());
    CHECK_THROWS_AS(Toy::params().read(b), InputError);
    CHECK_THROWS_WITH(Toy::params().read(b), Contains(std::string("part.") + key));
  }
  json b = Toy::params().defaults();
  b["inner"]["count"] = 11;
  CHECK_THROWS_WITH(Toy::params().read(b), Contains("part.inner.count") && Contains("int [1, 10]"));
  b = Toy::params().defaults();
  b["shape"] = "oval";
  CHECK_THROWS_WITH(Toy::params().read(b), Contains("expected \"round\" or \"square\", got \"oval\""));
}

TEST_CASE("reading records its keys: a key read but not declared, or declared but not read, is caught", "[core][params]") {
  // Read but not declared: the block lacks a key the table (or a resolver) reads.
  json lacking = Toy::params().defaults();
  lacking.erase("on");
  CHECK_THROWS_AS(Toy::params().read(lacking), std::logic_error);
  CHECK_THROWS_WITH(Toy::params().read(lacking), Contains("part.on"));
  const json defaults = Toy::params().defaults();
  ParamReader r(defaults, "part");
  CHECK_THROWS_AS(r.at("colour"), std::logic_error);
  // Declared but not read: a key of the block that nothing read is listed (dotted, inside
  // blocks too); a block read whole refuses it, naming it.
  Toy::params().read(r);
  CHECK(r.unread().empty());
  json more = Toy::params().defaults();
  more["colour"] = 1;
  more["inner"]["size"] = 2;
  ParamReader r2(more, "part");
  Toy::params().read(r2);
  CHECK(r2.unread() == std::vector<std::string>{"part.colour", "part.inner.size"});
  CHECK_THROWS_WITH(Toy::params().read(more), Contains("part.colour") && Contains("unknown key"));
  // A part's spec is one key: read whole, its inner keys are not listed.
  ParamReader r3(defaults, "part");
  r3.at("spec");
  for (const std::string& k : r3.unread()) CHECK(k.rfind("part.spec", 0) != 0);
}

TEST_CASE("a table refuses a key declared twice", "[core][params]") {
  struct Twice {
    int a = 0;
  };
  CHECK_THROWS_AS(ParamTable<Twice>("twice", {param("a", &Twice::a, "", ""), param("a", &Twice::a, "", "")}), std::logic_error);
}
