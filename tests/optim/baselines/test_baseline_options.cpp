// The baselines' parameters, each declared once in a table (core/config/params.hpp):
// optim/baselines/pcf2017/pcf2017_options.hpp and roveri2015/roveri2015_options.hpp. The
// method's registered defaults and bounds are the table's, its struct's members are the
// defaults, reading and writing agree, a bad value is named, and the method reads every key.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "optim/baselines/pcf2017/pcf2017_options.hpp"
#include "optim/baselines/roveri2015/roveri2015_options.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

namespace {

template <class T>
void check_table(const char* method) {
  INFO(method);
  const json d = T::params().defaults();
  const auto& entry = MethodRegistry::instance().entry(method);
  CHECK(entry.defaults == d);
  CHECK(entry.bounds == T::params().bounds());
  CHECK(T::params().to_json(T::params().read(d)) == d);
  CHECK(T::params().docs().size() == d.size());
}

}  // namespace

TEST_CASE("pcf2017 and roveri2015 declare each key once, in a table", "[optim][baselines][params]") {
  check_table<pcf2017::Pcf2017Options>("pcf2017");
  check_table<roveri2015::Roveri2015Options>("roveri2015");
  // The structs' members are the defaults the methods register.
  const pcf2017::Pcf2017Options p;
  CHECK(p.pcf.bins == 100);
  CHECK(p.descent.iterations == 300);
  CHECK(p.quick_iterations == 30);
  const roveri2015::Roveri2015Options r;
  CHECK(r.roveri.window == roveri2015::WindowKind::Gaussian);
  CHECK(r.quick_scales == 2);
  CHECK(roveri2015::Roveri2015Options::params().defaults()["window"] == "gaussian");
}

TEST_CASE("a baseline's bad parameter is named by its key path", "[optim][baselines][params]") {
  for (const auto& [spec, key] : {std::pair<json, const char*>{json{{"type", "pcf2017"}, {"r_a", 3.0}}, "method.r_a"},
                                  {json{{"type", "pcf2017"}, {"max_step", 0.05}}, "method.max_step"},
                                  {json{{"type", "pcf2017"}, {"bins", 1}}, "method.bins"},
                                  {json{{"type", "roveri2015"}, {"window", "triangle"}}, "method.window"},
                                  {json{{"type", "roveri2015"}, {"scale_factor", 1.0}}, "method.scale_factor"}}) {
    INFO(spec.dump());
    CHECK_THROWS_WITH(MethodRegistry::instance().create(spec, "method"), Contains(key));
  }
  // A key of the merged params that the table does not declare is refused, naming it.
  json extra = pcf2017::Pcf2017Options::params().defaults();
  extra["colour"] = 1;
  CHECK_THROWS_WITH(pcf2017::Pcf2017Options::params().read(extra, "method"), Contains("method.colour"));
}
