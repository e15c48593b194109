#pragma once
// Outputs are never half-written: write to "<path>.tmp-<pid>" in the same folder, then
// rename over the target (atomic on POSIX). An exception before commit() removes the temp.
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
  const std::string& temp_path() const { return tmp_; }
  void commit();  // flush, close, rename; throws InputError if the write failed

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `text` to `path` atomically.
void write_text_atomic(const std::string& path, const std::string& text);
// Calls `writer(temp_path)` for writers that need a file name (cairo), then renames.
void write_via_temp(const std::string& path, const std::function<void(const std::string&)>& writer);
// Temp name used by both.
std::string temp_name_for(const std::string& path);

}  // namespace ppsynth
