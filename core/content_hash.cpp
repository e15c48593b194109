#include "core/content_hash.hpp"

#include <cstdio>

namespace ppsynth {

uint64_t fnv1a64(const void* data, size_t size, uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

std::string content_hash(const std::string& bytes) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(fnv1a64(bytes)));
  return buf;
}

std::string json_id(const nlohmann::json& value) { return content_hash(value.dump()).substr(0, 12); }

}  // namespace ppsynth
