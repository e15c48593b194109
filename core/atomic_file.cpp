#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

// Where to write for `path`, and whether through a temp file (see the header).
struct Target {
  std::string path;
  bool via_temp = true;
};

Target output_target(const std::string& path) {
  std::error_code ec;
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    const auto st = fs::symlink_status(p, ec);
    switch (st.type()) {
      case fs::file_type::not_found:
      case fs::file_type::regular:
        return {p.string(), true};
      case fs::file_type::symlink: {
        const fs::path to = fs::read_symlink(p, ec);
        if (ec) throw file_error(path, 0, "cannot read the symbolic link: " + ec.message());
        p = to.is_absolute() ? to : p.parent_path() / to;
        continue;
      }
      case fs::file_type::directory:
        throw file_error(path, 0, "is a directory; name a file to write");
      default:  // character or block device, FIFO, socket
        return {p.string(), false};
    }
  }
  throw file_error(path, 0, "too many levels of symbolic links");
}

// Keep the extension last so writers that look at it (cairo) still see it.
std::string temp_name_for(const std::string& path) {
  fs::path p(path);
  return (p.parent_path() / (p.stem().string() + ".tmp-" + std::to_string(::getpid()) + p.extension().string())).string();
}

void rename_into_place(const std::string& tmp, const std::string& path, const std::string& shown) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw file_error(shown, 0, "cannot rename the temporary file into place");
  }
}

}  // namespace

AtomicFile::AtomicFile(std::string path, std::ios::openmode mode) : path_(std::move(path)) {
  const Target t = output_target(path_);
  tmp_ = t.via_temp ? temp_name_for(t.path) : "";
  out_.open(t.via_temp ? tmp_ : t.path, mode | std::ios::out | (t.via_temp ? std::ios::trunc : std::ios::openmode{}));
  if (!out_) throw file_error(path_, 0, "cannot open for writing");
  if (t.via_temp && t.path != path_) path_ = t.path;  // a symbolic link: its target is replaced
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    if (!tmp_.empty()) std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw file_error(path_, 0, "write failed");
  out_.close();
  if (out_.fail()) throw file_error(path_, 0, "write failed");
  if (!tmp_.empty()) rename_into_place(tmp_, path_, path_);
  committed_ = true;
}

void check_writable(const std::string& path) {
  const Target t = output_target(path);
  if (!t.via_temp) return;
  const std::string tmp = temp_name_for(t.path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int err = errno;
    std::string folder = fs::path(t.path).parent_path().string();
    if (folder.empty()) folder = ".";
    if (err == ENOENT) throw file_error(path, 0, "cannot be written: no folder " + folder);
    if (err == ENOTDIR) throw file_error(path, 0, "cannot be written: " + folder + " is not a folder");
    throw file_error(path, 0, std::string("cannot be written: ") + std::strerror(err));
  }
  ::close(fd);
  std::remove(tmp.c_str());
}

void write_text_atomic(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

void write_via_temp(const std::string& path, const std::function<void(const std::string&)>& writer) {
  const Target t = output_target(path);
  if (!t.via_temp) {
    writer(t.path);
    return;
  }
  const std::string tmp = temp_name_for(t.path);
  try {
    writer(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  rename_into_place(tmp, t.path, path);
}

}  // namespace ppsynth
