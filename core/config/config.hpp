#pragma once
// The one config loader of the project. Configs are JSON objects; a config may name a
// "parent" config (path relative to itself) whose keys it overrides (deep merge: objects
// merge, everything else replaces). Defaults are declared once, by the part that uses them
// (see core/registry.hpp); apply_defaults() merges user keys over them and refuses what it
// does not know, naming the key path, e.g. "config key 'losses[1].weight': expected a number".
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

using json = nlohmann::json;

// Reads a JSON config file and resolves its "parent" chain (cycles are errors). Comments and
// a UTF-8 byte-order mark are accepted; nesting deeper than kMaxJsonDepth, numbers beyond
// double and syntax errors are InputErrors naming the file and line (json_text.hpp); a
// directory, a missing file or an empty "parent" name the file.
json load_config(const std::string& path);

// Deep merge: `over` wins; objects merge recursively (except a component spec whose "type"
// differs, which replaces the parent's); arrays and scalars replace.
json merge(const json& base, const json& over);

// Returns defaults overridden by `user`. Unknown keys, and values whose JSON type differs
// from the default's (integers and floats are both numbers; a null default accepts
// anything; an object default with the key "*" accepts any key; an object default with a
// "type" is a component spec, validated later by its registry) are errors naming
// `key_path` + the key.
json apply_defaults(const json& defaults, const json& user, const std::string& key_path);

// Applies one "--set a.b.c=value" override. The value is parsed as JSON when it parses
// ("3", "true", "[0,1]"), else taken as a string. Array elements: "losses.1.weight=2". A JSON
// value goes through the checks of a config file (nesting depth, numbers beyond double).
void set_override(json& config, const std::string& assignment);
// Sets the value at a dotted key path ("method.max_iterations", "losses.1.weight"), creating
// objects on the way as set_override does; the path's flaws are InputErrors naming it.
void set_at_key_path(json& config, const std::string& key, json value);

// Typed getters that name the key on error. get_int refuses a fraction and a value outside
// the int range, naming the range.
double get_number(const json& j, const std::string& key, const std::string& key_path);
int get_int(const json& j, const std::string& key, const std::string& key_path);
std::string get_string(const json& j, const std::string& key, const std::string& key_path);
bool get_bool(const json& j, const std::string& key, const std::string& key_path);

// A list of whole numbers in [0, max] (a sweep's seeds, gather's stages): 95, "95", "96-99",
// "95,97-98", [95, "97-98"] -> in order, without repeats; a range spans at most 100000
// numbers, the list at most 1000000. Digits only (no sign, no space, no exponent); a number
// past `max` is refused, never saturated. Errors name `key` (and the element) and call each
// number a `noun` ("seed").
std::vector<uint64_t> parse_number_list(const json& value, const std::string& key, const std::string& noun, uint64_t max);

}  // namespace ppsynth
