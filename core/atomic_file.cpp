#include "core/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/error.hpp"

namespace ppsynth {

std::string temp_name_for(const std::string& path) {
  // Keep the extension last so writers that look at it (cairo) still see it.
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + ".tmp-" + std::to_string(::getpid()) + p.extension().string()))
      .string();
}

AtomicFile::AtomicFile(std::string path, std::ios::openmode mode)
    : path_(std::move(path)), tmp_(temp_name_for(path_)) {
  out_.open(tmp_, mode | std::ios::out | std::ios::trunc);
  if (!out_) throw file_error(path_, 0, "cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw file_error(path_, 0, "write failed");
  out_.close();
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    std::remove(tmp_.c_str());
    throw file_error(path_, 0, "cannot rename temporary file into place");
  }
  committed_ = true;
}

void write_text_atomic(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

void write_via_temp(const std::string& path, const std::function<void(const std::string&)>& writer) {
  const std::string tmp = temp_name_for(path);
  try {
    writer(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw file_error(path, 0, "cannot rename temporary file into place");
  }
}

}  // namespace ppsynth
