#include "core/run_directory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

const char* kMarker = ".ppsynth-run";

bool is_prefix_of(const fs::path& a, const fs::path& b) {  // a == b or a is a parent of b
  auto ai = a.begin(), bi = b.begin();
  for (; ai != a.end(); ++ai, ++bi)
    if (bi == b.end() || *ai != *bi) return false;
  return true;
}

std::string explain(const std::string& path, const std::error_code& ec) { return path + ": " + ec.message(); }

}  // namespace

bool is_safe_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::string normalize_output_dir(const std::string& path, const std::string& option) {
  if (path.empty()) throw InputError(option + ": an empty path");
  fs::path p = fs::path(path).lexically_normal();
  std::string s = p.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  p = fs::path(s);
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const fs::path abs = fs::weakly_canonical(fs::absolute(p), ec);
  if (s == "." || s == ".." || s == "/" || (!ec && is_prefix_of(abs, cwd)))
    throw InputError(option + " " + path + ": the current directory or one of its parents cannot be written as a whole; name a new directory");
  return s;
}

bool run_dir_locked(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // releases the shared lock if we got it
  return locked;
}

nlohmann::json parse_run_dir_marker(const std::string& text, const std::string& source) {
  const nlohmann::json m = parse_json_text(text, source, false);
  auto refuse = [&](const std::string& key, const std::string& what) {
    return file_error(source, 0, "key '" + key + "': " + what + " (a damaged marker)");
  };
  if (!m.is_object()) throw file_error(source, 0, "expected a JSON object (a damaged marker)");
  if (!m.contains("kind") || !m["kind"].is_string() || !is_safe_name(m["kind"])) throw refuse("kind", "expected a plain name");
  if (!m.contains("state") || (m["state"] != "running" && m["state"] != "complete"))
    throw refuse("state", "expected \"running\" or \"complete\"");
  auto whole = [&](const nlohmann::json& o, const char* k, const std::string& key) {
    if (o.contains(k) && !(o[k].is_number_integer() && o[k].get<long long>() >= 0)) throw refuse(key, "expected a whole number");
  };
  for (const char* k : {"pid", "updated", "threads", "seed", "runs"}) whole(m, k, k);
  if (m.contains("quick") && !m["quick"].is_boolean()) throw refuse("quick", "expected true or false");
  if (m.contains("processor") && !m["processor"].is_string()) throw refuse("processor", "expected a string");
  if (m.contains("exemplar_format")) {
    const nlohmann::json& f = m["exemplar_format"];
    if (!f.is_string() || f == "auto") throw refuse("exemplar_format", "expected a point format's name");
    try {
      parse_format(f);
    } catch (const InputError&) {
      throw refuse("exemplar_format", "expected a point format's name (gabor, point-synthesis, plain or json)");
    }
  }
  if (m.contains("progress")) {
    const nlohmann::json& p = m["progress"];
    if (!p.is_object()) throw refuse("progress", "expected an object");
    for (const char* k : {"index", "count", "window", "windows", "checkpointed"}) whole(p, k, std::string("progress.") + k);
    if (p.contains("stage") && !p["stage"].is_string()) throw refuse("progress.stage", "expected a string");
  }
  return m;
}

namespace {

std::string read_marker_text(const std::string& dir) {
  std::ifstream in(dir + "/" + kMarker, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

nlohmann::json run_dir_marker(const std::string& dir) {
  const std::string path = dir + "/" + kMarker;
  if (!std::ifstream(path)) return nullptr;
  try {
    return parse_run_dir_marker(read_marker_text(dir), path);
  } catch (const InputError&) {
    return nullptr;
  }
}

std::string run_progress_text(const nlohmann::json& marker, long long now) {
  if (!marker.is_object() || !marker.contains("progress") || !marker["progress"].is_object()) return "";
  const nlohmann::json& p = marker["progress"];
  auto number = [&](const char* k) {
    return p.contains(k) && p[k].is_number_integer() ? std::to_string(p[k].get<long long>()) : std::string("?");
  };
  std::string text;
  if (p.contains("index")) {
    text = "stage " + number("index") + "/" + number("count");
    if (p.contains("window")) text += ", window " + number("window") + "/" + number("windows");
    if (p.contains("stage") && p["stage"].is_string() && !p["stage"].get<std::string>().empty())
      text += " (" + p["stage"].get<std::string>() + ")";
  }
  if (const auto c = p.find("checkpointed"); c != p.end() && c->is_number_integer()) {
    const long long ago = std::max(0LL, now - c->get<long long>());
    const std::string when = ago < 120 ? std::to_string(ago) + " s ago"
                             : ago < 7200 ? std::to_string(ago / 60) + " min ago"
                                          : std::to_string(ago / 3600) + " h ago";
    text += (text.empty() ? "" : ", ") + std::string("checkpoint ") + when;
  }
  return text;
}

RunDirState run_dir_state(const std::string& dir) {
  std::error_code ec;
  const auto st = fs::symlink_status(dir, ec);
  if (ec || st.type() == fs::file_type::not_found) return RunDirState::Absent;
  if (st.type() != fs::file_type::directory) return RunDirState::Foreign;
  if (fs::is_empty(dir, ec)) return RunDirState::Empty;
  const nlohmann::json m = run_dir_marker(dir);
  if (m.is_null()) return RunDirState::Foreign;
  return m.value("state", "") == "complete" ? RunDirState::Complete : RunDirState::Unfinished;
}

RunDirectory::RunDirectory(std::string path, int lock_fd, bool created, std::string kind)
    : path_(std::move(path)), lock_fd_(lock_fd), created_(created), kind_(std::move(kind)) {}

RunDirectory::RunDirectory(RunDirectory&& o) noexcept
    : path_(std::move(o.path_)), lock_fd_(o.lock_fd_), created_(o.created_), kind_(std::move(o.kind_)) {
  o.lock_fd_ = -1;
}

RunDirectory::~RunDirectory() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // closing the descriptor releases the lock
}

RunDirectory RunDirectory::open(const std::string& path_in, const RunDirOptions& o) {
  const std::string path = normalize_output_dir(path_in, o.option);
  const std::string what = o.option + " " + path;
  std::error_code ec;
  const auto st = fs::symlink_status(path, ec);
  bool created = false;
  if (o.resume && st.type() != fs::file_type::directory) {  // a resume creates nothing
    const std::string is = st.type() == fs::file_type::not_found ? "no such directory"
                           : st.type() == fs::file_type::symlink ? "not a " + o.kind + " directory (a symbolic link)"
                                                                 : "not a " + o.kind + " directory (a file)";
    throw InputError(what + ": " + is + "; --resume needs the directory of an unfinished " + o.kind +
                     " of ppsynth. Nothing was changed.");
  }
  if (st.type() == fs::file_type::not_found) {
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) {
      fs::create_directories(parent, ec);
      if (ec) throw InputError(o.option + ": cannot create " + explain(parent.string(), ec));
    }
    if (::mkdir(path.c_str(), 0777) == 0) created = true;
    else if (errno != EEXIST) throw InputError(what + ": cannot create the directory: " + std::strerror(errno));
  } else if (st.type() != fs::file_type::directory) {
    throw InputError(what + ": exists and is not a directory (" +
                     (st.type() == fs::file_type::symlink ? "a symbolic link" : "a file") +
                     "); name a new directory. Nothing was changed.");
  }

  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw InputError(what + ": cannot open the directory: " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    const nlohmann::json m = run_dir_marker(path);
    const std::string pid = m.is_object() && m.contains("pid") ? " (pid " + m["pid"].dump() + ")" : "";
    throw InputError(what + ": another ppsynth process" + pid + " is writing this directory; wait for it or name another");
  }
  RunDirectory dir(path, fd, created, o.kind);  // from here the lock is ours; the destructor releases it

  const RunDirState state = run_dir_state(path);
  if (state == RunDirState::Foreign && fs::exists(fs::path(path) / kMarker, ec)) {
    std::string why = "unreadable";
    try {
      parse_run_dir_marker(read_marker_text(path), (fs::path(path) / kMarker).string());
    } catch (const InputError& e) {
      why = e.what();
    }
    throw InputError(what + ": its marker is damaged (" + why + "); ppsynth cannot tell what the directory holds, so it "
                     "changes nothing there: name another directory, or mend or remove it yourself");
  }
  if (o.resume) {
    if (state == RunDirState::Unfinished && run_dir_marker(path).value("kind", o.kind) != o.kind)
      throw InputError(what + ": --resume needs an unfinished " + o.kind + " of ppsynth; this is a " +
                       run_dir_marker(path).value("kind", std::string()) + " of ppsynth");
    if (state != RunDirState::Unfinished) {
      if (created) dir.discard();
      throw InputError(what + ": --resume needs an unfinished " + o.kind + " of ppsynth; this is " +
                       (state == RunDirState::Complete  ? "a finished one (nothing to resume)"
                        : state == RunDirState::Foreign ? "not a ppsynth directory"
                                                        : "empty or absent (start a new run instead)"));
    }
    dir.write_marker("running", nlohmann::json::object());
    return dir;
  }
  switch (state) {
    case RunDirState::Absent:
    case RunDirState::Empty:
      break;
    case RunDirState::Complete:
    case RunDirState::Unfinished: {
      const bool done = state == RunDirState::Complete;
      const std::string kind = run_dir_marker(path).value("kind", o.kind);
      if (kind != o.kind)  // --force replaces only what this kind of command made
        throw InputError(what + ": holds " + (done ? "a finished " : "an unfinished ") + kind + " of ppsynth, not a " +
                         o.kind + "; name another directory. Nothing was changed.");
      if (!o.force)
        throw InputError(what + ": holds " + (done ? "a finished " : "an unfinished ") + kind + " of ppsynth; " +
                         (!done && kind == "run" ? "--resume continues it, " : "") +
                         "--force replaces it (its files are then deleted). Nothing was changed.");
      for (auto& e : fs::directory_iterator(path, ec)) {
        fs::remove_all(e.path(), ec);
        if (ec) throw InputError(what + ": --force: cannot remove " + explain(e.path().string(), ec));
      }
      break;
    }
    case RunDirState::Foreign:
      throw InputError(what + ": exists and is not a ppsynth " + o.kind +
                       " directory (it holds other files); name a new or empty directory. Nothing was changed.");
  }
  dir.write_marker("running", nlohmann::json::object());
  return dir;
}

void RunDirectory::write_marker(const std::string& state, const nlohmann::json& info) {
  nlohmann::json m = run_dir_marker(path_);
  if (!m.is_object()) m = nlohmann::json::object();
  for (const auto& [key, value] : info.items()) {
    if (key == "progress" && value.is_object() && m[key].is_object())
      m[key].update(value);
    else
      m[key] = value;
  }
  if (state == "complete") m.erase("progress");  // a finished run is not on its way anywhere
  m["kind"] = kind_;
  m["state"] = state;
  m["pid"] = static_cast<long>(::getpid());
  m["updated"] = static_cast<long long>(std::time(nullptr));
  write_text_atomic(path_ + "/" + kMarker, m.dump(2) + "\n");
}

void RunDirectory::mark_complete(const nlohmann::json& info) { write_marker("complete", info); }

void RunDirectory::discard() {
  std::error_code ec;
  if (created_) {
    fs::remove_all(path_, ec);
  } else {
    for (auto& e : fs::directory_iterator(path_, ec)) fs::remove_all(e.path(), ec);
  }
}

}  // namespace ppsynth
