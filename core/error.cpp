#include "core/error.hpp"

#include <filesystem>

namespace ppsynth {

InputError file_error(const std::string& path, long line, const std::string& message) {
  if (line > 0) return InputError(path + ":" + std::to_string(line) + ": " + message);
  return InputError(path + ": " + message);
}

void throw_open_error(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (link.type() == fs::file_type::not_found) throw MissingFileError(path + ": no such file");
  if (fs::is_symlink(link) && !fs::exists(path, ec))
    throw MissingFileError(path + ": no such file (a symbolic link to nothing)");
  throw file_error(path, 0, "cannot open " + what + " (unreadable)");
}

InputError config_error(const std::string& key_path, const std::string& message) {
  return InputError("config key '" + key_path + "': " + message);
}

}  // namespace ppsynth
