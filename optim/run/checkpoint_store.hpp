#pragma once
// Where a synthesis keeps its checkpoint: the bytes that SynthesisOptions::save_checkpoint
// hands over (optim/method/method.hpp), in one file, replaced atomically at every save
// (core/atomic_file.hpp) so that a kill or a full disk during a write keeps the previous
// checkpoint. The run directory (`checkpoint.bin`, optim/run/run_synthesis.hpp), bench and the
// Python binding's checkpoint_dir all keep theirs through it: the one place that reads, writes
// and removes checkpoint files. What the bytes mean is checked elsewhere
// (core/checkpoint_file.hpp, before a resume).
#include <cstddef>
#include <functional>
#include <string>

namespace ppsynth {

// The checkpoint file of a directory that holds one synthesis: DIR/checkpoint.bin.
std::string checkpoint_file_in(const std::string& dir);

class CheckpointStore {
 public:
  explicit CheckpointStore(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  bool exists() const;
  // The bytes of the last save (InputError naming the file when there is none).
  std::string load() const;
  // Replaces the checkpoint atomically; `after` (if given) runs once the file is in place.
  void save(const std::string& bytes);
  // A finished synthesis needs no checkpoint; no error when there is none.
  void remove();
  // The hook for SynthesisOptions::save_checkpoint: save, then `after` (a run directory
  // records its progress in its marker).
  std::function<void(const std::string&)> saver(std::function<void()> after = {});
  bool saved() const { return saved_; }        // has this store saved since it was made
  size_t last_size() const { return last_size_; }

 private:
  std::string file_;
  bool saved_ = false;
  size_t last_size_ = 0;
};

}  // namespace ppsynth
