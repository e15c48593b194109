#pragma once
// Errors a user can act on. Every failure caused by input (a file, a config key, a
// parameter) is an InputError whose message names the place: "file:line: what", or
// "config key a.b.c: what". The command catches it, prints it, exits non-zero.
#include <stdexcept>
#include <string>

namespace ppsynth {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

// An input file that is not there: an InputError a front end can tell apart (the Python
// package raises FileNotFoundError for it; the command prints it like any other).
class MissingFileError : public InputError {
 public:
  using InputError::InputError;
};

// "path:line: message" (line <= 0 leaves the line out).
InputError file_error(const std::string& path, long line, const std::string& message);
// After a failed open of the input file `path` (`what`: "file", "config"): a MissingFileError
// "path: no such file" when nothing is there, else an InputError "path: cannot open WHAT".
[[noreturn]] void throw_open_error(const std::string& path, const std::string& what);
// "config key 'a.b': message".
InputError config_error(const std::string& key_path, const std::string& message);

}  // namespace ppsynth
