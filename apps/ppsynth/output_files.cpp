#include "apps/ppsynth/output_files.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/paths.hpp"

namespace ppsynth::app {

namespace {

namespace fs = std::filesystem;

// The file a path names, links followed as far as it exists: "a/../x", "./x" and a link to x
// are x.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal();
  const fs::path p = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : p;
}

// One file under two names: the same resolved path, or the same inode (a hard link).
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec) && !ec) return true;
  return resolved(a) == resolved(b);
}

std::string named(const NamedPath& p) { return p.option + " " + p.path; }

}  // namespace

void check_output_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs, bool force) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    if (out.path.empty()) continue;
    std::error_code ec;
    const fs::file_type type = fs::status(out.path, ec).type();  // links followed
    const bool regular = type == fs::file_type::regular;
    // A device or FIFO is written into, not replaced (core/atomic_file.hpp): /dev/stdout may
    // well be the terminal an input is read from too.
    if (type != fs::file_type::not_found && type != fs::file_type::none && !regular) {
      if (type == fs::file_type::directory)
        throw InputError(named(out) + " is a directory; name a file. Nothing was written.");
      continue;
    }
    for (const NamedPath& in : inputs)
      if (!in.path.empty() && same_file(out.path, resolve_data_path(in.path)))
        throw InputError(named(out) + " is the input " + named(in) +
                         ": an output never replaces an input, not even with --force. Nothing was written.");
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && same_file(out.path, outputs[j].path))
        throw InputError(named(out) + " and " + named(outputs[j]) + " are the same file; name two files. Nothing was written.");
    if (regular && !force) throw InputError(named(out) + " exists; --force replaces it. Nothing was written.");
  }
}

void check_inputs_outside(const NamedPath& directory, const std::vector<NamedPath>& inputs) {
  if (directory.path.empty()) return;
  std::error_code ec;
  if (!fs::is_directory(directory.path, ec)) return;
  const fs::path dir = resolved(directory.path);
  for (const NamedPath& in : inputs) {
    if (in.path.empty()) continue;
    const fs::path file = resolved(resolve_data_path(in.path));
    // `file` lies in `dir` when `dir` is a prefix of it, component by component.
    auto f = file.begin();
    bool inside = true;
    for (auto d = dir.begin(); d != dir.end() && inside; ++d, ++f) inside = f != file.end() && *d == *f;
    if (inside)
      throw InputError(named(directory) + " holds the input " + named(in) +
                       ": the directory's files are replaced, and an input never is, not even with --force. Nothing "
                       "was changed.");
  }
}

}  // namespace ppsynth::app
