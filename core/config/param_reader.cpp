#include <cstdint>

#include "core/config/config.hpp"
#include "core/config/param_bounds.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"

namespace ppsynth {

ParamReader::ParamReader(const nlohmann::json& block, std::string key_path)
    : ParamReader(block, std::move(key_path), std::make_shared<std::set<std::string>>()) {}

ParamReader::ParamReader(const nlohmann::json& block, std::string key_path, std::shared_ptr<std::set<std::string>> read)
    : block_(&block), path_(std::move(key_path)), read_(std::move(read)) {
  if (!block_->is_object()) throw config_error(path_, "expected an object");
}

std::string ParamReader::path_of(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

const nlohmann::json& ParamReader::at(const std::string& key) {
  if (!block_->contains(key))
    throw std::logic_error("'" + path_of(key) + "' is read but not declared (its block's defaults do not hold it)");
  read_->insert(path_of(key));
  return (*block_)[key];
}

ParamReader ParamReader::sub(const std::string& key) {
  if (!block_->contains(key))
    throw std::logic_error("'" + path_of(key) + "' is read but not declared (its block's defaults do not hold it)");
  return ParamReader((*block_)[key], path_of(key), read_);
}

namespace {

void collect_unread(const nlohmann::json& block, const std::string& path, const std::set<std::string>& read,
                    std::vector<std::string>& out) {
  for (auto it = block.begin(); it != block.end(); ++it) {
    const std::string kp = path.empty() ? it.key() : path + "." + it.key();
    if (read.count(kp)) continue;
    if (it->is_object() && !it->empty() && !it->contains("type"))
      collect_unread(*it, kp, read, out);
    else
      out.push_back(kp);
  }
}

}  // namespace

std::vector<std::string> ParamReader::unread() const {
  std::vector<std::string> out;
  collect_unread(*block_, path_, *read_, out);
  return out;
}

void refuse_undeclared(const std::string& key_path) { throw config_error(key_path, "unknown key"); }

namespace param_detail {

namespace {
void check(ParamReader& r, const std::string& key, const std::string& bound) {
  if (!bound.empty()) check_bounds(nlohmann::json{{key, r.at(key)}}, nlohmann::json{{key, bound}}, r.key_path());
}
bool is_none(const nlohmann::json& v) { return v.is_null() || (v.is_string() && v.get<std::string>() == "auto"); }
}  // namespace

int read_int(ParamReader& r, const std::string& key, const std::string& bound) {
  r.at(key);
  const int v = get_int(r.block(), key, r.key_path());
  check(r, key, bound);
  return v;
}

double read_double(ParamReader& r, const std::string& key, const std::string& bound) {
  r.at(key);
  const double v = get_number(r.block(), key, r.key_path());
  check(r, key, bound);
  return v;
}

bool read_bool(ParamReader& r, const std::string& key) {
  r.at(key);
  return get_bool(r.block(), key, r.key_path());
}

std::string read_string(ParamReader& r, const std::string& key) {
  r.at(key);
  return get_string(r.block(), key, r.key_path());
}

std::vector<int> read_int_list(ParamReader& r, const std::string& key, const std::string& bound) {
  const nlohmann::json& v = r.at(key);
  if (!v.is_array()) throw config_error(r.path_of(key), "expected a list of whole numbers");
  check(r, key, bound);  // each element in the bound
  std::vector<int> out;
  for (size_t i = 0; i < v.size(); ++i) {
    const nlohmann::json& e = v[i];
    const bool whole = e.is_number_integer() && (e.is_number_unsigned() ? e.get<uint64_t>() <= INT32_MAX
                                                                        : e.get<int64_t>() >= INT32_MIN && e.get<int64_t>() <= INT32_MAX);
    if (!whole) throw config_error(r.path_of(key) + "[" + std::to_string(i) + "]", "expected a whole number, got " + e.dump());
    out.push_back(e.get<int>());
  }
  return out;
}

std::optional<int> read_optional_int(ParamReader& r, const std::string& key, const std::string& bound) {
  if (is_none(r.at(key))) return std::nullopt;
  if (!r.at(key).is_number()) throw config_error(r.path_of(key), "expected null, \"auto\" or a whole number");
  return read_int(r, key, bound);
}

std::optional<double> read_optional_double(ParamReader& r, const std::string& key, const std::string& bound) {
  if (is_none(r.at(key))) return std::nullopt;
  if (!r.at(key).is_number()) throw config_error(r.path_of(key), "expected null, \"auto\" or a number");
  return read_double(r, key, bound);
}

size_t read_choice(ParamReader& r, const std::string& key, const std::vector<std::string>& names) {
  const nlohmann::json& v = r.at(key);
  for (size_t i = 0; i < names.size(); ++i)
    if (v.is_string() && v.get<std::string>() == names[i]) return i;
  std::string expected;
  for (size_t i = 0; i < names.size(); ++i)
    expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
  throw config_error(r.path_of(key), "expected " + expected + ", got " + v.dump());
}

}  // namespace param_detail

}  // namespace ppsynth
