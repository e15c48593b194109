#include "optim/run/checkpoint_store.hpp"

#include <filesystem>
#include <ios>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace ppsynth {

std::string checkpoint_file_in(const std::string& dir) { return dir + "/checkpoint.bin"; }

bool CheckpointStore::exists() const { return std::filesystem::exists(file_); }

std::string CheckpointStore::load() const {
  if (!exists()) throw InputError(file_ + ": no checkpoint");
  return read_file_text(file_);
}

void CheckpointStore::save(const std::string& bytes) {
  AtomicFile f(file_, std::ios::binary);
  f.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  f.commit();
  saved_ = true;
  last_size_ = bytes.size();
}

void CheckpointStore::remove() {
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

std::function<void(const std::string&)> CheckpointStore::saver(std::function<void()> after) {
  return [this, after = std::move(after)](const std::string& bytes) {
    save(bytes);
    if (after) after();
  };
}

}  // namespace ppsynth
