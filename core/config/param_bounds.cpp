#include "core/config/param_bounds.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"

namespace ppsynth {

namespace {

struct Interval {
  bool integer = false;
  double lo = -INFINITY, hi = INFINITY;
  bool lo_open = true, hi_open = true;
};

double parse_end(std::string s, const std::string& bound) {
  s.erase(0, s.find_first_not_of(' '));
  s.erase(s.find_last_not_of(' ') + 1);
  if (s == "inf" || s == "+inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty()) throw std::logic_error("malformed parameter bound '" + bound + "'");
  return v;
}

Interval parse_interval(const std::string& bound) {
  Interval iv;
  std::string s = bound;
  if (s.rfind("int ", 0) == 0) {
    iv.integer = true;
    s = s.substr(4);
  }
  const size_t comma = s.find(',');
  if (s.size() < 5 || (s.front() != '[' && s.front() != '(') || (s.back() != ']' && s.back() != ')') ||
      comma == std::string::npos)
    throw std::logic_error("malformed parameter bound '" + bound + "'");
  iv.lo_open = s.front() == '(';
  iv.hi_open = s.back() == ')';
  iv.lo = parse_end(s.substr(1, comma - 1), bound);
  iv.hi = parse_end(s.substr(comma + 1, s.size() - comma - 2), bound);
  return iv;
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string shown(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os << v;
  return os.str();
}

// "0 or int [8, 8192]" -> {"0", "int [8, 8192]"}: a bound's alternatives.
std::vector<std::string> alternatives(const std::string& bound) {
  std::vector<std::string> alts;
  size_t from = 0;
  for (size_t at; (at = bound.find(" or ", from)) != std::string::npos; from = at + 4) alts.push_back(bound.substr(from, at - from));
  alts.push_back(bound.substr(from));
  return alts;
}

bool is_interval(const std::string& alt) { return alt.rfind("int ", 0) == 0 || alt.front() == '[' || alt.front() == '('; }

bool within(const Interval& iv, double x) {
  const bool below = iv.lo_open ? !(x > iv.lo) : !(x >= iv.lo);
  const bool above = iv.hi_open ? !(x < iv.hi) : !(x <= iv.hi);
  return !(below || above) && (!iv.integer || x == std::floor(x));
}

// A bound's alternatives as intervals (one number n as [n, n]); std::logic_error when malformed.
std::vector<Interval> parse_bound(const std::string& bound) {
  std::vector<Interval> intervals;
  for (const std::string& alt : alternatives(bound))
    if (alt.empty()) throw std::logic_error("malformed parameter bound '" + bound + "'");
    else if (is_interval(alt)) intervals.push_back(parse_interval(alt));
    else intervals.push_back({false, parse_end(alt, bound), parse_end(alt, bound), false, false});
  return intervals;
}

void check_value(const nlohmann::json& v, const std::string& bound, const std::string& kp) {
  // null or "auto" (an optional parameter's "none", core/config/params.hpp) is not a number to bound
  if (v.is_null() || (v.is_string() && v.get<std::string>() == "auto")) return;
  const std::vector<Interval> intervals = parse_bound(bound);
  if (!v.is_number()) throw config_error(kp, "expected a number in " + bound);
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw config_error(kp, "not a finite number");
  for (const Interval& iv : intervals)
    if (within(iv, x)) return;
  if (intervals.size() == 1 && intervals[0].integer && x != std::floor(x))
    throw config_error(kp, "expected a whole number in " + bound + ", got " + shown(x));
  throw config_error(kp, shown(x) + " is outside the allowed range " + bound);
}

}  // namespace

void check_bounds(const nlohmann::json& params, const nlohmann::json& bounds, const std::string& key_path) {
  if (!bounds.is_object() || !params.is_object()) return;
  for (auto it = bounds.begin(); it != bounds.end(); ++it) {
    if (!params.contains(it.key())) continue;
    const std::string kp = join(key_path, it.key());
    const nlohmann::json& v = params[it.key()];
    if (it.value().is_object()) {
      check_bounds(v, it.value(), kp);
    } else if (it.value().is_string()) {
      if (v.is_array()) {  // a list of numbers: every element in the bound
        for (size_t i = 0; i < v.size(); ++i) check_value(v[i], it.value(), kp + "[" + std::to_string(i) + "]");
      } else {
        check_value(v, it.value(), kp);
      }
    } else {
      throw std::logic_error("malformed parameter bound at '" + kp + "'");
    }
  }
}

std::vector<std::string> unbounded_numbers(const nlohmann::json& defaults, const nlohmann::json& bounds,
                                           const std::string& key_path) {
  std::vector<std::string> out;
  if (!defaults.is_object()) return out;
  for (auto it = defaults.begin(); it != defaults.end(); ++it) {
    const std::string kp = join(key_path, it.key());
    const nlohmann::json* b = bounds.is_object() && bounds.contains(it.key()) ? &bounds[it.key()] : nullptr;
    const nlohmann::json& d = it.value();
    if (d.is_object() && !d.contains("type")) {  // a nested group (a component spec has its own registry)
      auto sub = unbounded_numbers(d, b ? *b : nlohmann::json::object(), kp);
      out.insert(out.end(), sub.begin(), sub.end());
    } else if (d.is_number() || (d.is_array() && !d.empty() && d.front().is_number())) {
      if (!b || !b->is_string()) out.push_back(kp);
      else parse_bound(b->get<std::string>());  // malformed bounds surface here too
    }
  }
  return out;
}

}  // namespace ppsynth
