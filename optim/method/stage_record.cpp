#include "optim/method/stage_record.hpp"

#include <cmath>
#include <stdexcept>

namespace ppsynth {

namespace {
constexpr const char* kFields[] = {"stage", "iterations", "final_loss", "seconds"};
}  // namespace

nlohmann::json to_json(const StageRecord& r) {
  nlohmann::json j = r.details.is_object() ? r.details : nlohmann::json::object();
  j["stage"] = r.stage;
  j["iterations"] = r.iterations;
  j["final_loss"] = r.final_loss;
  j["seconds"] = r.seconds;
  return j;
}

nlohmann::json to_json(const std::vector<StageRecord>& records) {
  nlohmann::json list = nlohmann::json::array();
  for (const StageRecord& r : records) list.push_back(to_json(r));
  return list;
}

StageRecord stage_record_from_json(const nlohmann::json& j) {
  if (!j.is_object()) throw std::invalid_argument("a stage record is not an object");
  StageRecord r;
  if (!j.contains("stage") || !j["stage"].is_string()) throw std::invalid_argument("a stage record's 'stage' is not a label");
  r.stage = j["stage"].get<std::string>();
  if (!j.contains("iterations") || !j["iterations"].is_number_integer() || j["iterations"].get<int64_t>() < 0 ||
      j["iterations"].get<int64_t>() > 1000000000)
    throw std::invalid_argument("stage '" + r.stage + "': 'iterations' is not a count");
  r.iterations = j["iterations"].get<int>();
  for (const char* k : {"final_loss", "seconds"})
    if (!j.contains(k) || !j[k].is_number() || !std::isfinite(j[k].get<double>()))
      throw std::invalid_argument("stage '" + r.stage + "': '" + k + "' is not a finite number");
  r.final_loss = j["final_loss"].get<double>();
  r.seconds = j["seconds"].get<double>();
  r.details = j;
  for (const char* k : kFields) r.details.erase(k);
  return r;
}

std::vector<StageRecord> stage_records_from_json(const nlohmann::json& list) {
  if (!list.is_array()) throw std::invalid_argument("the stage records are not a list");
  std::vector<StageRecord> records;
  for (const auto& j : list) records.push_back(stage_record_from_json(j));
  return records;
}

}  // namespace ppsynth
