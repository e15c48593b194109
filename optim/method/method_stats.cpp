#include "optim/method/method_stats.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ppsynth {

StatsFields::StatsFields(const nlohmann::json& j, std::string path) : j_(j), path_(std::move(path)) {
  if (!j_.is_object())
    throw std::invalid_argument(path_.empty() ? std::string("the stats are not an object") : "'" + path_ + "' is not an object");
}

std::string StatsFields::path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void StatsFields::refuse(const std::string& key, const std::string& what) const {
  throw std::invalid_argument("'" + path(key) + "' " + what);
}

bool StatsFields::has(const std::string& key) const { return j_.contains(key); }

const nlohmann::json& StatsFields::at(const std::string& key) const {
  if (!j_.contains(key)) refuse(key, "is missing");
  return j_[key];
}

int StatsFields::integer(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number_integer() || v.get<int64_t>() < -2147483647 || v.get<int64_t>() > 2147483647)
    refuse(key, "is not an integer");
  return v.get<int>();
}

size_t StatsFields::count(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0)) refuse(key, "is not a count");
  return v.get<size_t>();
}

double StatsFields::number(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) refuse(key, "is not a finite number");
  return v.get<double>();
}

bool StatsFields::flag(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_boolean()) refuse(key, "is not true or false");
  return v.get<bool>();
}

std::string StatsFields::text(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_string()) refuse(key, "is not a string");
  return v.get<std::string>();
}

std::vector<int> StatsFields::integers(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_array()) refuse(key, "is not a list of integers");
  std::vector<int> out;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number_integer() || v[i].get<int64_t>() < -2147483647 || v[i].get<int64_t>() > 2147483647)
      refuse(key + "[" + std::to_string(i) + "]", "is not an integer");
    out.push_back(v[i].get<int>());
  }
  return out;
}

std::vector<double> StatsFields::numbers(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_array()) refuse(key, "is not a list of numbers");
  std::vector<double> out;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
      refuse(key + "[" + std::to_string(i) + "]", "is not a finite number");
    out.push_back(v[i].get<double>());
  }
  return out;
}

std::array<double, 4> StatsFields::box(const std::string& key) const {
  const std::vector<double> v = numbers(key);
  if (v.size() != 4) refuse(key, "is not 4 numbers {x0, y0, x1, y1}");
  return {v[0], v[1], v[2], v[3]};
}

std::map<std::string, double> StatsFields::weights(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_object()) refuse(key, "is not an object of numbers");
  std::map<std::string, double> out;
  for (const auto& [name, w] : v.items()) {
    if (!w.is_number() || !std::isfinite(w.get<double>())) refuse(key + "." + name, "is not a finite number");
    out[name] = w.get<double>();
  }
  return out;
}

const nlohmann::json& StatsFields::value(const std::string& key) const { return at(key); }

StatsFields StatsFields::object(const std::string& key) const { return StatsFields(at(key), path(key)); }

std::vector<StatsFields> StatsFields::objects(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_array()) refuse(key, "is not a list of objects");
  std::vector<StatsFields> out;
  for (size_t i = 0; i < v.size(); ++i) out.emplace_back(v[i], path(key) + "[" + std::to_string(i) + "]");
  return out;
}

std::vector<std::string> StatsFields::others(const std::vector<std::string>& known) const {
  std::vector<std::string> out;
  for (const auto& [key, v] : j_.items())
    if (std::find(known.begin(), known.end(), key) == known.end()) out.push_back(key);
  return out;
}

void StatsFields::refuse_others(const std::vector<std::string>& known) const {
  const std::vector<std::string> extra = others(known);
  if (!extra.empty()) refuse(extra.front(), "is not a key of these stats");
}

void add_to(nlohmann::json& stats, const RectangleStats& r) {
  stats["output"] = r.output;
  stats["canvas"] = r.canvas;
  stats["canvas_points"] = r.canvas_points;
}

RectangleStats rectangle_stats_from(const StatsFields& f) {
  return RectangleStats{f.text("output"), f.box("canvas"), f.count("canvas_points")};
}

}  // namespace ppsynth
