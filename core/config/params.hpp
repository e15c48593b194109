#pragma once
// Each parameter of an options block declared once, as data. A block is a struct whose member
// initializers are its defaults (so `X{}` is a configuration) and a table of one line per key:
//
//   struct QuickOptions {
//     int res = 24;
//     int channels = 8;
//     static const ParamTable<QuickOptions>& params();
//   };
//   const ParamTable<QuickOptions>& QuickOptions::params() {
//     static const ParamTable<QuickOptions> t("method.quick", {
//         param("res", &QuickOptions::res, "int [8, 8192]", "method.grid's resolved res"),
//         param("channels", &QuickOptions::channels, "int [1, 4096]", "the filters of a network with a count"),
//     });
//     return t;
//   }
//
// From that table come the block's defaults (defaults(): the members of `X{}` written out), its
// ranges (bounds(), core/config/param_bounds.hpp's notation, which the registries check), its
// doc lines (docs(), the generated reference's: core/config/param_docs.hpp), reading (read():
// types and ranges checked, errors naming the key path) and writing (to_json()). A line is
// param() for a plain member (int, double, bool, string, a list of whole numbers, a part's
// spec kept as JSON, or an optional number whose null or "auto" means "none"), choice() for a
// member set by one of a few names, block() for a nested block with a table of its own.
//
// Reading goes through a ParamReader, which records every key it reads and refuses a key its
// block does not hold: a block read whole (read(json)) is refused when a key of it was not
// read, and a resolver that reads more than its tables (optim/gabor/resolution) checks
// unread() itself, so a key declared but read by no one, or read but declared by no one,
// fails where it is resolved.
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

// Reads the keys of one block of params (the defaults merged under the user's), recording the
// path of each key it reads.
class ParamReader {
 public:
  ParamReader(const nlohmann::json& block, std::string key_path);
  ParamReader(const nlohmann::json&& block, std::string key_path) = delete;  // it keeps a pointer to the block
  const std::string& key_path() const { return path_; }
  std::string path_of(const std::string& key) const;
  const nlohmann::json& block() const { return *block_; }
  // The value of `key`, recorded as read; a key the block does not hold is a std::logic_error:
  // no one declared it.
  const nlohmann::json& at(const std::string& key);
  // A block inside this one (an object; else a config_error naming it), its reads recorded
  // with this one's.
  ParamReader sub(const std::string& key);
  // The keys of the block (dotted paths; a part's spec, an empty object or a list is one key)
  // that were not read.
  std::vector<std::string> unread() const;

 private:
  ParamReader(const nlohmann::json& block, std::string key_path, std::shared_ptr<std::set<std::string>> read);
  const nlohmann::json* block_;
  std::string path_;
  std::shared_ptr<std::set<std::string>> read_;
};

namespace param_detail {
// Typed reads of `key` of the reader's block: the type, then the bound (when not empty).
int read_int(ParamReader& r, const std::string& key, const std::string& bound);
double read_double(ParamReader& r, const std::string& key, const std::string& bound);
bool read_bool(ParamReader& r, const std::string& key);
std::string read_string(ParamReader& r, const std::string& key);
std::vector<int> read_int_list(ParamReader& r, const std::string& key, const std::string& bound);
// null or "auto": none.
std::optional<int> read_optional_int(ParamReader& r, const std::string& key, const std::string& bound);
std::optional<double> read_optional_double(ParamReader& r, const std::string& key, const std::string& bound);
// The index of the value's name in `names`; else a config_error listing them.
size_t read_choice(ParamReader& r, const std::string& key, const std::vector<std::string>& names);
}  // namespace param_detail

// One key of a block T.
template <class T>
struct Param {
  std::string key;
  nlohmann::json bound;  // a bound string, a nested block's bounds (an object), or null: none
  nlohmann::json doc;    // a line, or a nested block's doc lines (an object)
  std::function<nlohmann::json(const T&)> write;
  std::function<void(T&, ParamReader&)> read;
};

template <class T>
class ParamTable {
 public:
  // `key_path`: where the block sits in a config ("method.grid"), for errors when it is read whole.
  ParamTable(std::string key_path, std::vector<Param<T>> params) : path_(std::move(key_path)), params_(std::move(params)) {
    std::set<std::string> keys;
    for (const auto& p : params_)
      if (!keys.insert(p.key).second) throw std::logic_error(path_ + ": key '" + p.key + "' declared twice");
  }
  const std::string& key_path() const { return path_; }
  const std::vector<Param<T>>& params() const { return params_; }

  nlohmann::json to_json(const T& o) const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& p : params_) j[p.key] = p.write(o);
    return j;
  }
  nlohmann::json defaults() const { return to_json(T{}); }
  nlohmann::json bounds() const {
    nlohmann::json b = nlohmann::json::object();
    for (const auto& p : params_)
      if (p.bound.is_string() || (p.bound.is_object() && !p.bound.empty())) b[p.key] = p.bound;
    return b;
  }
  nlohmann::json docs() const {
    nlohmann::json d = nlohmann::json::object();
    for (const auto& p : params_) d[p.key] = p.doc;
    return d;
  }
  // Every declared key of the reader's block, into a T.
  T read(ParamReader& r) const {
    T o;
    for (const auto& p : params_) p.read(o, r);
    return o;
  }
  // A block on its own (defaults merged): a key of it that no line declares is refused, naming
  // it. `key_path`: where the block sits, when not the table's own (a part's spec in a list).
  T read(const nlohmann::json& block) const { return read(block, path_); }
  T read(const nlohmann::json& block, const std::string& key_path) const;

 private:
  std::string path_;
  std::vector<Param<T>> params_;
};

// A key of a block that is not declared: the config_error for read(json) (param_reader.cpp).
[[noreturn]] void refuse_undeclared(const std::string& key_path);

template <class T>
T ParamTable<T>::read(const nlohmann::json& block, const std::string& key_path) const {
  ParamReader r(block, key_path);
  T o = read(r);
  const std::vector<std::string> unread = r.unread();
  if (!unread.empty()) refuse_undeclared(unread.front());
  return o;
}

namespace param_detail {
// A line for the member that `ref` reaches in a T or a const T (param() below).
template <class T, class V, class Ref>
Param<T> member_param(std::string key, Ref ref, std::string bound, std::string doc) {
  Param<T> p;
  p.key = key;
  p.bound = bound.empty() ? nlohmann::json() : nlohmann::json(bound);
  p.doc = std::move(doc);
  p.write = [ref](const T& o) -> nlohmann::json {
    const V& v = ref(o);
    if constexpr (std::is_same_v<V, std::optional<int>> || std::is_same_v<V, std::optional<double>>)
      return v ? nlohmann::json(*v) : nlohmann::json();
    else
      return nlohmann::json(v);
  };
  p.read = [key, ref, bound](T& o, ParamReader& r) {
    V& v = ref(o);
    if constexpr (std::is_same_v<V, int>) v = read_int(r, key, bound);
    else if constexpr (std::is_same_v<V, double>) v = read_double(r, key, bound);
    else if constexpr (std::is_same_v<V, bool>) v = read_bool(r, key);
    else if constexpr (std::is_same_v<V, std::string>) v = read_string(r, key);
    else if constexpr (std::is_same_v<V, std::vector<int>>) v = read_int_list(r, key, bound);
    else if constexpr (std::is_same_v<V, std::optional<int>>) v = read_optional_int(r, key, bound);
    else if constexpr (std::is_same_v<V, std::optional<double>>) v = read_optional_double(r, key, bound);
    else if constexpr (std::is_same_v<V, nlohmann::json>) v = r.at(key);
    else static_assert(sizeof(V) == 0, "param(): a member type the table cannot read");
  };
  return p;
}
}  // namespace param_detail

// A plain member: int, double, bool, std::string, std::vector<int> (whole numbers, each in the
// bound), std::optional<int> / std::optional<double> (null or "auto": none) or nlohmann::json
// (a part's spec or a free value, checked by whoever reads it; no bound). `bound`: "" for none.
template <class T, class V>
Param<T> param(std::string key, V T::*member, std::string bound, std::string doc) {
  return param_detail::member_param<T, V>(std::move(key), [member](auto& o) -> auto& { return o.*member; }, std::move(bound),
                                          std::move(doc));
}

// A member of a member, for a flat block whose keys fill parts' own structs (a method's
// descent options beside its estimator's): param("bins", &Options::pcf, &PcfParams::bins, ...).
template <class T, class S, class V>
Param<T> param(std::string key, S T::*outer, V S::*inner, std::string bound, std::string doc) {
  return param_detail::member_param<T, V>(
      std::move(key), [outer, inner](auto& o) -> auto& { return (o.*outer).*inner; }, std::move(bound), std::move(doc));
}

namespace param_detail {
template <class T, class V, class Ref>
Param<T> member_choice(std::string key, Ref ref, std::vector<std::pair<std::string, V>> names, std::string doc) {
  Param<T> p;
  p.key = key;
  p.doc = std::move(doc);
  p.write = [key, ref, names](const T& o) -> nlohmann::json {
    for (const auto& [name, v] : names)
      if (v == ref(o)) return name;
    throw std::logic_error(key + ": a value with no name");
  };
  p.read = [key, ref, names](T& o, ParamReader& r) {
    std::vector<std::string> words;
    for (const auto& n : names) words.push_back(n.first);
    ref(o) = names[read_choice(r, key, words)].second;
  };
  return p;
}
}  // namespace param_detail

// A member set by one of a few names (an enum, or a bool behind two words): {{"grid", Measure::grid}, ...}.
template <class T, class V>
Param<T> choice(std::string key, V T::*member, std::vector<std::pair<std::string, V>> names, std::string doc) {
  return param_detail::member_choice<T, V>(std::move(key), [member](auto& o) -> auto& { return o.*member; }, std::move(names),
                                           std::move(doc));
}
template <class T, class S, class V>
Param<T> choice(std::string key, S T::*outer, V S::*inner, std::vector<std::pair<std::string, V>> names, std::string doc) {
  return param_detail::member_choice<T, V>(
      std::move(key), [outer, inner](auto& o) -> auto& { return (o.*outer).*inner; }, std::move(names), std::move(doc));
}

// A nested block whose type U declares its own table (U::params()).
template <class T, class U>
Param<T> block(std::string key, U T::*member) {
  Param<T> p;
  p.key = key;
  p.bound = U::params().bounds();
  p.doc = U::params().docs();
  p.write = [member](const T& o) { return U::params().to_json(o.*member); };
  p.read = [key, member](T& o, ParamReader& r) {
    ParamReader sub = r.sub(key);
    o.*member = U::params().read(sub);
  };
  return p;
}

}  // namespace ppsynth
