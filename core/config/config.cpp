#include "core/config/config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <set>

#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

json read_json_file(const std::string& path) {
  // BOM, nesting depth, numbers beyond double and syntax errors, each with its line.
  return parse_json_text(read_file_text(path, "config file"), path, /*allow_comments=*/true);
}

json load_chain(const std::string& path, std::set<std::string>& seen) {
  std::error_code ec;  // e.g. a "parent" name too long for the file system (fuzz finding)
  std::string canon = fs::weakly_canonical(path, ec).string();
  if (ec) throw file_error(path, 0, "cannot resolve the config path: " + ec.message());
  if (!seen.insert(canon).second) throw file_error(path, 0, "config parent cycle");
  json j = read_json_file(path);
  if (!j.is_object()) throw file_error(path, 0, "a config must be a JSON object");
  if (j.contains("parent")) {
    if (!j["parent"].is_string() || j["parent"].get<std::string>().empty())
      throw file_error(path, 0, "config key 'parent': expected the path of a config file");
    fs::path parent = fs::path(path).parent_path() / j["parent"].get<std::string>();
    json base = load_chain(parent.string(), seen);
    j.erase("parent");
    return merge(base, j);
  }
  return j;
}

const char* type_name(const json& j) {
  switch (j.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    case json::value_t::null: return "null";
    default: return "a value";
  }
}

bool same_kind(const json& a, const json& b) {
  if (a.is_number() && b.is_number()) return true;
  return std::string(type_name(a)) == type_name(b);
}

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

}  // namespace

json load_config(const std::string& path) {
  std::set<std::string> seen;
  return load_chain(path, seen);
}

json merge(const json& base, const json& over) {
  if (!base.is_object() || !over.is_object()) return over;
  // A component spec whose "type" changes is replaced, not merged: the parent's parameters
  // belong to the parent's component (a gabor method's c1 means nothing to roveri2015).
  if (base.contains("type") && over.contains("type") && base["type"] != over["type"]) return over;
  json out = base;
  for (auto it = over.begin(); it != over.end(); ++it) {
    if (out.contains(it.key()) && out[it.key()].is_object() && it.value().is_object())
      out[it.key()] = merge(out[it.key()], it.value());
    else
      out[it.key()] = it.value();
  }
  return out;
}

json apply_defaults(const json& defaults, const json& user, const std::string& key_path) {
  if (user.is_null()) return defaults;
  if (!user.is_object()) throw config_error(key_path, std::string("expected an object, got ") + type_name(user));
  json out = defaults;
  const bool open = defaults.contains("*");
  if (open) out.erase("*");
  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string kp = join(key_path, it.key());
    if (!defaults.contains(it.key())) {
      if (open) {
        out[it.key()] = it.value();
        continue;
      }
      std::string known;
      for (auto d = defaults.begin(); d != defaults.end(); ++d) known += (known.empty() ? "" : ", ") + d.key();
      throw config_error(kp, "unknown key (known here: " + known + ")");
    }
    const json& d = defaults[it.key()];
    const json& v = it.value();
    if (d.is_object() && d.contains("type") && v.is_object()) {
      // A component spec ({"type": ..., params}): its own registry validates the params
      // when it is created. Same type: user params over the default's; else the user's spec.
      out[it.key()] = (!v.contains("type") || v["type"] == d["type"]) ? merge(d, v) : v;
    } else if (d.is_null()) {
      out[it.key()] = v;
    } else if (!same_kind(d, v)) {
      throw config_error(kp, std::string("expected ") + type_name(d) + ", got " + type_name(v));
    } else if (d.is_object() && !d.empty()) {
      out[it.key()] = apply_defaults(d, v, kp);
    } else {
      if (v.is_number_float() && !std::isfinite(v.get<double>())) throw config_error(kp, "not a finite number");
      out[it.key()] = v;
    }
  }
  return out;
}

void set_override(json& config, const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + assignment + "': expected key.path=value");
  // Keys and string values end up in the resolved config.json: one that is not UTF-8 could
  // not be written (json::dump throws type_error 316; fuzz finding).
  try {
    (void)json(assignment).dump();
  } catch (const json::type_error&) {
    throw InputError("--set: the assignment is not valid UTF-8");
  }
  std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  // A value that is JSON goes through the checks of a config file (nesting, numbers beyond
  // double: "1e400" was kept as a string); text that is not JSON is a string.
  json value;
  bool is_json = true;
  std::string failure;
  try {
    value = json::parse(text);
  } catch (const json::parse_error&) {
    value = text;
    is_json = false;
  } catch (const json::exception& e) {  // out_of_range 406: a number beyond double
    failure = e.what();
  }
  if (is_json) {
    if (const auto flaw = find_json_text_flaw(text, /*allow_comments=*/false))
      throw config_error(key, "--set value: " + flaw->message);
    if (!failure.empty()) throw config_error(key, "--set value: " + failure);
  }
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    throw InputError("--set '" + assignment + "': empty key component");
  set_at_key_path(config, key, std::move(value));
}

void set_at_key_path(json& config, const std::string& key, json value) {
  json* node = &config;
  size_t start = 0;
  while (true) {
    size_t dot = key.find('.', start);
    std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw InputError("key path '" + key + "': empty key component");
    const bool last = dot == std::string::npos;
    if (node->is_array()) {
      size_t idx = 0;
      try {
        idx = std::stoul(part);
      } catch (...) {
        throw config_error(key, "'" + part + "' is not an array index");
      }
      if (idx >= node->size()) throw config_error(key, "array index " + part + " out of range");
      node = &(*node)[idx];
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object()) throw config_error(key, "'" + part + "' is below a value that is not an object");
      node = &(*node)[part];
    }
    if (last) {
      *node = std::move(value);
      return;
    }
    start = dot + 1;
  }
}

double get_number(const json& j, const std::string& key, const std::string& key_path) {
  if (!j.contains(key) || !j[key].is_number()) throw config_error(join(key_path, key), "expected a number");
  return j[key].get<double>();
}

int get_int(const json& j, const std::string& key, const std::string& key_path) {
  const double v = get_number(j, key, key_path);
  constexpr long long lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (v != std::floor(v)) throw config_error(join(key_path, key), "expected an integer in " + range);
  // Compare exact integers where the JSON holds them (a double cannot hold every int64).
  const json& x = j[key];
  const bool in_range = x.is_number_unsigned() ? x.get<unsigned long long>() <= static_cast<unsigned long long>(hi)
                        : x.is_number_integer() ? (x.get<long long>() >= lo && x.get<long long>() <= hi)
                                                : (v >= static_cast<double>(lo) && v <= static_cast<double>(hi));
  if (!in_range) {
    std::ostringstream s;
    s << "integer " << x.dump() << " is out of range: expected an integer in " << range;
    throw config_error(join(key_path, key), s.str());
  }
  return static_cast<int>(v);
}

std::string get_string(const json& j, const std::string& key, const std::string& key_path) {
  if (!j.contains(key) || !j[key].is_string()) throw config_error(join(key_path, key), "expected a string");
  return j[key].get<std::string>();
}

bool get_bool(const json& j, const std::string& key, const std::string& key_path) {
  if (!j.contains(key) || !j[key].is_boolean()) throw config_error(join(key_path, key), "expected a boolean");
  return j[key].get<bool>();
}

std::vector<uint64_t> parse_number_list(const json& value, const std::string& key, const std::string& noun, uint64_t max) {
  constexpr uint64_t kMaxRange = 100000;
  constexpr size_t kMaxCount = 1000000;
  std::vector<uint64_t> out;
  std::set<uint64_t> seen;
  const json list = value.is_array() ? value : json::array({value});
  for (size_t i = 0; i < list.size(); ++i) {
    const auto& s = list[i];
    const std::string kp = key + "[" + std::to_string(i) + "]";
    const auto bad = [&](const std::string& why) {
      return config_error(kp, why + ": expected a " + noun + " from 0 to " + std::to_string(max) + ", a range \"first-last\" (at most " +
                                  std::to_string(kMaxRange) + " " + noun + "s) or a list of both separated by commas (\"95,97-98\")");
    };
    const auto add = [&](uint64_t v) {
      if (seen.insert(v).second) out.push_back(v);
      if (out.size() > kMaxCount) throw config_error(key, "more than " + std::to_string(kMaxCount) + " " + noun + "s");
    };
    // Digits only, at most `max`; saturation (strtoull, sscanf) would turn 2^64 and beyond into a bound.
    const auto number = [&](const std::string& text, const std::string& part) {
      if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw bad("'" + part.substr(0, 40) + "' is not a whole number or a range of them");
      uint64_t v = 0;
      for (char c : text) {
        const uint64_t d = static_cast<uint64_t>(c - '0');
        if (d > max || v > (max - d) / 10) throw bad(text.substr(0, 40) + " is past " + std::to_string(max));
        v = v * 10 + d;
      }
      return v;
    };
    if (s.is_number_unsigned() || (s.is_number_integer() && s.get<long long>() >= 0)) {
      if (s.get<uint64_t>() > max) throw bad(s.dump() + " is past " + std::to_string(max));
      add(s.get<uint64_t>());
      continue;
    }
    if (!s.is_string()) throw bad(s.dump().substr(0, 40));
    const std::string text = s.get<std::string>();
    for (size_t a = 0, comma; a <= text.size(); a = comma + 1) {  // "95,97-98": each part a number or a range
      comma = std::min(text.find(',', a), text.size());
      const std::string part = text.substr(a, comma - a);
      const size_t dash = part.find('-');
      const uint64_t first = number(part.substr(0, dash), part);
      const uint64_t last = dash == std::string::npos ? first : number(part.substr(dash + 1), part);
      if (last < first) throw bad("the range " + part + " runs backwards");
      if (last - first >= kMaxRange) throw bad("the range " + part + " spans more than " + std::to_string(kMaxRange) + " " + noun + "s");
      for (uint64_t v = first;; ++v) {  // ends at `last` without stepping past it (last may be UINT64_MAX)
        add(v);
        if (v == last) break;
      }
    }
  }
  if (out.empty()) throw config_error(key, "no " + noun + "s");
  return out;
}

}  // namespace ppsynth
