#include "core/error.hpp"

namespace ppsynth {

InputError file_error(const std::string& path, long line, const std::string& message) {
  if (line > 0) return InputError(path + ":" + std::to_string(line) + ": " + message);
  return InputError(path + ": " + message);
}

InputError config_error(const std::string& key_path, const std::string& message) {
  return InputError("config key '" + key_path + "': " + message);
}

}  // namespace ppsynth
