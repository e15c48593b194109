#pragma once
// The directories ppsynth writes whole (a synthesis run, a report): who may write one, and
// what may be replaced. The rule is the project's: a command never deletes or replaces what
// it did not create unless the user names it and says --force.
//
// A directory is ppsynth's when it holds the marker file `.ppsynth-run` (JSON: kind, state,
// pid), which only RunDirectory writes. Its state is "running" while a process writes it and
// "complete" once every output is in place; nothing else marks it complete.
//
// Opening one for writing (RunDirectory::open):
//   absent                              -> created
//   an empty directory                  -> used (it is not removed on failure)
//   ppsynth's, complete or unfinished   -> refused, naming --force (and --resume for an
//                                          unfinished run); with --force its entries are
//                                          removed and it is used again -- only when its
//                                          marker names the same kind (a gather never
//                                          replaces a run); with --resume an unfinished one
//                                          is used as it is
//   ppsynth's, another process writing  -> refused at once (an advisory lock on the directory,
//                                          released by the kernel when that process dies)
//   anything else (a file, a directory
//   with other files, ".", a parent of
//   the current directory)              -> refused; --force does not change that
// With --resume, anything but an unfinished run's directory is refused, and nothing is created.
// Paths are normalized first: "runs/a/" and "runs/./a" are "runs/a".
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// True for a non-empty name of letters, digits, '_' and '-': names from configs that end up
// in file names must be such names, so that no config can make ppsynth write elsewhere.
bool is_safe_name(const std::string& name);

// `path` lexically normalized, without a trailing slash. Refuses (InputError naming `option`)
// an empty path, the current directory, the root and every parent of the current directory.
std::string normalize_output_dir(const std::string& path, const std::string& option);

enum class RunDirState {
  Absent,      // nothing at the path
  Empty,       // an empty directory
  Unfinished,  // ppsynth's, state "running" (interrupted, or another process is writing it)
  Complete,    // ppsynth's, state "complete"
  Foreign,     // a file, or a directory that is not ppsynth's
};
RunDirState run_dir_state(const std::string& dir);
// True while a process holds the directory open through RunDirectory (its advisory lock):
// an unfinished run that is locked is running, one that is not was interrupted.
bool run_dir_locked(const std::string& dir);
// The marker's JSON, or null when there is none (or it is unreadable or damaged).
nlohmann::json run_dir_marker(const std::string& dir);
// A marker's text read from `source`, checked: an object whose "kind" is a plain name, "state"
// "running" or "complete", and whose known keys ("pid", "updated", "progress", "quick",
// "threads", "processor", "seed") have their types. InputError naming `source` and the key.
nlohmann::json parse_run_dir_marker(const std::string& text, const std::string& source);

// How far an unfinished run got, from its directory's marker, which a run keeps current: the
// stage it began last and when it last saved a checkpoint, e.g. "stage 9/20 (class 3/4
// (id 2), sigma 1/4), checkpoint 4 min ago". "" when the marker holds neither (a run that has
// not begun its first stage). `now`: seconds since the epoch.
std::string run_progress_text(const nlohmann::json& marker, long long now);

struct RunDirOptions {
  std::string kind = "run";       // "run", "report": recorded in the marker, used in messages
  std::string option = "-o";      // the command-line option that named the path (messages)
  bool force = false;             // --force: replace a ppsynth directory (complete or unfinished)
  bool resume = false;            // --resume: continue an unfinished one (refuses anything else)
};

// A directory this process writes, locked for its lifetime.
class RunDirectory {
 public:
  static RunDirectory open(const std::string& path, const RunDirOptions& options);
  RunDirectory(RunDirectory&& other) noexcept;
  RunDirectory& operator=(RunDirectory&&) = delete;
  RunDirectory(const RunDirectory&) = delete;
  ~RunDirectory();  // releases the lock; leaves the files as they are

  const std::string& path() const { return path_; }
  bool created() const { return created_; }  // this process made the directory
  // Merges `info` into the marker (state still "running"): what a resume needs to know.
  void mark_running(const nlohmann::json& info) { write_marker("running", info); }
  // Merges `progress` into the marker's "progress" object: how far an unfinished run is
  // (which stage, when it last saved a checkpoint), for whoever watches it. Dropped once complete.
  void mark_progress(const nlohmann::json& progress) { write_marker("running", {{"progress", progress}}); }
  // Marks the directory complete (atomically), with `info` merged into the marker.
  void mark_complete(const nlohmann::json& info = nlohmann::json::object());
  // After a failure: removes what this process wrote (the directory itself when it created
  // it, else its entries). Never called on a directory another process holds.
  void discard();

 private:
  RunDirectory(std::string path, int lock_fd, bool created, std::string kind);
  void write_marker(const std::string& state, const nlohmann::json& info);
  std::string path_;
  int lock_fd_ = -1;
  bool created_ = false;
  std::string kind_;
};

}  // namespace ppsynth
