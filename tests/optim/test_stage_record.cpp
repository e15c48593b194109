// StageRecord (optim/method/stage_record.hpp): run.json's flat form and back, and what a
// malformed record is refused for.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "optim/method/stage_record.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;
using json = nlohmann::json;

TEST_CASE("a stage record is one flat object in run.json, and reads back the same", "[optim][stage_record]") {
  const StageRecord r{"class 1/2 (id 0), border relax", 0, 1.5e-4, 0.25, {{"class", 0}, {"relaxed", false}, {"parked_over_uniform", 1.35}}};
  const json j = to_json(r);
  CHECK(j == json{{"stage", r.stage}, {"iterations", 0}, {"final_loss", 1.5e-4}, {"seconds", 0.25}, {"class", 0},
                  {"relaxed", false}, {"parked_over_uniform", 1.35}});
  const StageRecord back = stage_record_from_json(j);
  CHECK(back.stage == r.stage);
  CHECK(back.iterations == 0);
  CHECK(back.final_loss == r.final_loss);
  CHECK(back.seconds == r.seconds);
  CHECK(back.details == r.details);
  CHECK(to_json(stage_records_from_json(to_json(std::vector<StageRecord>{r, r}))) == json::array({j, j}));
}

TEST_CASE("a malformed stage record is refused, saying which field", "[optim][stage_record]") {
  const json good = to_json(StageRecord{"sigma 1/4", 50, 0.1, 2.0, json::object()});
  for (const auto& [field, bad] : {std::pair<const char*, json>{"stage", 3}, {"iterations", -1}, {"iterations", 2.5},
                                   {"final_loss", "x"}, {"seconds", nullptr}}) {
    json j = good;
    j[field] = bad;
    INFO(j.dump());
    CHECK_THROWS_WITH(stage_record_from_json(j), Contains(field));
  }
  json missing = good;
  missing.erase("seconds");
  CHECK_THROWS_WITH(stage_record_from_json(missing), Contains("seconds"));
  CHECK_THROWS_AS(stage_records_from_json(json::object()), std::invalid_argument);
  CHECK_THROWS_AS(stage_record_from_json(json::array()), std::invalid_argument);
}
