#pragma once
// One hash for everything ppsynth identifies by content: a sweep row's id, a run's group, a
// checkpoint's key and its checksum. FNV-1a 64: stable across platforms, builds and
// standard libraries (std::hash is not), and any single changed byte changes it (each step
// is a bijection of the running value).
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

uint64_t fnv1a64(const void* data, size_t size, uint64_t h = 1469598103934665603ull);
inline uint64_t fnv1a64(const std::string& bytes) { return fnv1a64(bytes.data(), bytes.size()); }

// The 16 hex digits of fnv1a64(bytes).
std::string content_hash(const std::string& bytes);

// A short stable id of a JSON value: the first 12 hex digits of content_hash(value.dump()).
std::string json_id(const nlohmann::json& value);

}  // namespace ppsynth
