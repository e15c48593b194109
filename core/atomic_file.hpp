#pragma once
// Outputs are never half-written: a regular file (or an absent one) is written to
// "<stem>.tmp-<pid><ext>" in the same folder, then renamed over the target (atomic on POSIX);
// an exception before commit() removes the temp. Other targets are never replaced:
//   a symbolic link     -> the file it points to is written that way (the link stays)
//   a device, a FIFO    -> written directly (`convert a.txt /dev/stdout`); a failed write
//                          (/dev/full) is an error naming the path
//   a directory         -> refused
#include <fstream>
#include <functional>
#include <string>

namespace ppsynth {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path, std::ios::openmode mode = std::ios::out);
  ~AtomicFile();  // discards the temp file unless commit() ran
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // flush, close, rename; throws InputError if the write failed

 private:
  std::string path_, tmp_;  // tmp_ empty: written directly
  std::ofstream out_;
  bool committed_ = false;
};

// Fails now, as the write would at the end, when `path` could not be written: it is a
// directory, or its folder is missing, not a folder or not writable (a temporary file is
// created there as the write would, then removed). A device or FIFO is written directly and not
// opened here (opening a FIFO waits for a reader). For a command to call before long work.
void check_writable(const std::string& path);

// Writes `text` to `path` atomically.
void write_text_atomic(const std::string& path, const std::string& text);
// Calls `writer(file_name)` for writers that need a file name (cairo), then renames.
void write_via_temp(const std::string& path, const std::function<void(const std::string&)>& writer);

}  // namespace ppsynth
