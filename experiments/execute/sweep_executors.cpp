#include "experiments/execute/sweep_executors.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/run_directory.hpp"
#include "core/shell_quote.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "optim/run/runtime.hpp"
#include "experiments/execute/sweep_runs.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

// The environment of this process with PPSYNTH_THREADS set to `threads`.
std::vector<std::string> task_environment(int threads) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "PPSYNTH_THREADS=", 16) != 0) env.emplace_back(*e);
  env.push_back("PPSYNTH_THREADS=" + std::to_string(threads));
  return env;
}

// Threads per task: --threads, else the user's PPSYNTH_THREADS, else the cores split between
// the tasks.
int task_threads(const LocalExecution& how) {
  if (how.threads > 0) return how.threads;
  if (const int user = threads_from_environment(); user > 0) return user;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / how.jobs);
}

// A value as an error message shows it: on one line, control characters escaped.
std::string shown(const std::string& value) {
  std::string s;
  for (char c : value.substr(0, 128)) {
    if (c == '\n') s += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) s += "\\x" + std::to_string(static_cast<unsigned char>(c));
    else s += c;
  }
  return "'" + s + "'";
}

// Names SLURM takes in #SBATCH lines that no shell or sbatch reads as anything else.
void check_slurm_name(const std::string& option, const std::string& value) {
  if (value.size() > 128 || !std::all_of(value.begin(), value.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
      }))
    throw InputError(option + " " + shown(value) + ": expected a name of letters, digits, '_', '-' and '.'");
}

pid_t spawn_task(const LocalExecution& how, const std::string& sweep_dir, const std::string& row_id, const std::string& manifest,
                 const std::string& log, const std::vector<std::string>& env) {
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);  // its own group: Ctrl-C reaches only us
  posix_spawnattr_setpgroup(&attr, 0);
  std::vector<std::string> args = {how.binary, "sweep", "task", sweep_dir, "--row", row_id, "--manifest", manifest};
  std::vector<char*> argv, envp;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_copy = env;
  for (auto& e : env_copy) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, how.binary.c_str(), &files, &attr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) throw InputError("cannot start " + how.binary + ": " + std::strerror(rc));
  return pid;
}

}  // namespace

ExecutionSummary execute_local(const std::string& sweep_dir, const LocalExecution& how, const std::atomic<bool>* stop) {
  if (how.jobs < 1 || how.jobs > 1024) throw InputError("-j " + std::to_string(how.jobs) + ": expected 1 to 1024 tasks at once");
  const SweepManifest m = load_sweep(sweep_dir);
  const SweepLock lock(sweep_dir, "run it");
  const std::string manifest = sweep_manifest_hash(m);
  const int threads = task_threads(how);
  const auto env = task_environment(threads);
  ExecutionSummary sum;
  std::deque<size_t> queue;
  for (const auto& s : sweep_status(sweep_dir, m)) {
    const size_t i = static_cast<size_t>(s.row - m.rows.data());
    if (s.state == RowState::Done || s.state == RowState::Running) ++sum.skipped;
    else queue.push_back(i);
  }
  spdlog::info("sweep {}: {} runs to do, {} done or running; {} at once, {} thread{} each", m.name, queue.size(),
               sum.skipped, how.jobs, threads, threads == 1 ? "" : "s");
  std::map<pid_t, std::pair<size_t, std::chrono::steady_clock::time_point>> running;
  bool stopping = false;
  auto stop_all = [&] {
    if (stopping) return;
    stopping = true;
    spdlog::warn("sweep {}: stopping {} running task(s) (each writes a checkpoint where it has reached one)", m.name, running.size());
    for (auto& [pid, info] : running) ::kill(pid, SIGTERM);
  };
  while (!running.empty() || (!queue.empty() && !stopping)) {
    if (stop && stop->load()) stop_all();
    while (!stopping && !queue.empty() && static_cast<int>(running.size()) < how.jobs) {
      const size_t i = queue.front();
      queue.pop_front();
      const std::string log = (fs::path(sweep_dir) / "logs" / (m.rows[i].id + ".log")).string();
      running[spawn_task(how, sweep_dir, m.rows[i].id, manifest, log, env)] = {i, std::chrono::steady_clock::now()};
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;  // a signal: the loop head sees the stop flag
      throw InputError(std::string("waiting for the sweep's tasks: ") + std::strerror(errno));
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const auto [i, started] = it->second;
    running.erase(it);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const SweepRow& row = m.rows[i];
    if (code == 0) {
      ++sum.done;
      spdlog::info("[{}] {}: done ({:.0f} s)", row.id, row.label, s);
    } else if (code == 130 || code == 143) {
      ++sum.interrupted;
      // Stopped before its first checkpoint, a row has nothing to resume: say so, not "kept".
      const bool saved = fs::exists(checkpoint_file_in((fs::path(sweep_dir) / row.dir).string()));
      spdlog::warn("[{}] {}: interrupted after {:.0f} s; {}", row.id, row.label, s,
                   saved ? "its checkpoint is kept" : "before its first checkpoint: the next task starts it afresh");
    } else {
      ++sum.failed;
      spdlog::error("[{}] {}: failed (exit {}); see {}/logs/{}.log", row.id, row.label, code, sweep_dir, row.id);
    }
  }
  return sum;
}

std::string compress_indices(const std::vector<size_t>& v) {
  std::string s;
  for (size_t a = 0; a < v.size();) {
    size_t b = a;
    while (b + 1 < v.size() && v[b + 1] == v[b] + 1) ++b;
    s += (s.empty() ? "" : ",") + std::to_string(v[a]) + (b > a ? "-" + std::to_string(v[b]) : "");
    a = b + 1;
  }
  return s;
}

std::string slurm_script(const std::string& sweep_dir, const SweepManifest& m, const SlurmExecution& how) {
  if (!how.partition.empty()) check_slurm_name("--partition", how.partition);
  if (!how.account.empty()) check_slurm_name("--account", how.account);
  for (const auto& o : how.sbatch_options)
    if (o.empty() || !std::all_of(o.begin(), o.end(), [](char c) { return c >= 0x20 && c != 0x7f; }))
      throw InputError("--sbatch-option " + shown(o) + ": one printable option per line (no newline or control character)");
  if (how.cpus) check_sweep_resource("--cpus", how.cpus);
  if (how.memory_mb) check_sweep_resource("--mem-mb (memory)", how.memory_mb);
  if (how.time_minutes) check_sweep_resource("--time-minutes", how.time_minutes);
  if (how.max_parallel < 0 || how.max_parallel > 100000)
    throw InputError("--max-parallel " + std::to_string(how.max_parallel) + ": expected 1 to 100000");
  if (!is_safe_name(m.name)) throw InputError("sweep name '" + m.name + "': not a plain name");  // load_sweep checked it
  std::vector<size_t> todo;
  for (const auto& s : sweep_status(sweep_dir, m))
    if (s.state != RowState::Done) todo.push_back(static_cast<size_t>(s.row - m.rows.data()));
  if (todo.empty()) return "";
  const std::string dir = fs::absolute(sweep_dir).lexically_normal().string();
  if (dir.find_first_of(" \t\n'\"") != std::string::npos)
    throw InputError(dir + ": #SBATCH lines cannot hold a path with spaces or quotes; plan the sweep in a plain path");
  const int cpus = how.cpus > 0 ? how.cpus : m.resources.cpus;
  const int mem = how.memory_mb > 0 ? how.memory_mb : m.resources.memory_mb;
  const int minutes = how.time_minutes > 0 ? how.time_minutes : m.resources.time_minutes;
  std::string s = "#!/bin/bash\n";
  s += "# ppsynth sweep " + m.name + ": one run of " + dir + "/manifest.json per array task (the index picks its id below).\n";
  s += "# Written by `ppsynth sweep run --slurm`. A task that runs again (requeue, resubmission) resumes its\n";
  s += "# checkpoint; a finished run is skipped. `ppsynth sweep status " + dir + "` lists the runs.\n";
  s += "#SBATCH --job-name=ppsynth-" + m.name + "\n";
  s += "#SBATCH --array=" + compress_indices(todo) + (how.max_parallel > 0 ? "%" + std::to_string(how.max_parallel) : "") + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(cpus) + "\n";
  s += "#SBATCH --mem=" + std::to_string(mem) + "M\n";
  s += "#SBATCH --time=" + std::to_string(minutes) + "\n";
  s += "#SBATCH --output=" + dir + "/logs/slurm-%A_%a.out\n";
  s += "#SBATCH --open-mode=append\n";  // a requeued task's log keeps what the earlier attempt printed
  s += "#SBATCH --requeue\n";
  // SIGTERM to the task 120 s before the time limit: it checkpoints at the end of its iteration.
  s += "#SBATCH --signal=B:TERM@120\n";
  if (!how.partition.empty()) s += "#SBATCH --partition=" + how.partition + "\n";
  if (!how.account.empty()) s += "#SBATCH --account=" + how.account + "\n";
  for (const auto& o : how.sbatch_options) s += "#SBATCH " + o + "\n";
  s += "export PPSYNTH_THREADS=\"${PPSYNTH_THREADS:-${SLURM_CPUS_PER_TASK:-" + std::to_string(cpus) + "}}\"\n";
  // The array index picks a row's id (12 hex digits, checked): a plan changed after the
  // submission never makes a task run another row (sweep_runs.hpp).
  s += "rows=(";
  for (size_t i = 0; i < m.rows.size(); ++i) s += (i ? " " : "") + m.rows[i].id;
  s += ")\n";
  s += "exec " + shell_quoted(how.binary) + " sweep task " + shell_quoted(dir) + " --row \"${rows[$SLURM_ARRAY_TASK_ID]}\" --manifest " +
       sweep_manifest_hash(m) + "\n";
  return s;
}

std::string submit_slurm(const std::string& sweep_dir, const std::string& script) {
  const std::string path = (fs::path(sweep_dir) / "sweep.sbatch").string();
  write_text_atomic(path, script);
  const std::string cmd = "sbatch --parsable " + shell_quoted(path) + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) throw InputError("cannot run sbatch");
  std::string out;
  std::array<char, 512> buf{};
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), p)) > 0;) out.append(buf.data(), n);
  const int st = ::pclose(p);
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  if (st != 0) throw InputError("sbatch " + path + " failed: " + out);
  return out.substr(0, out.find(';'));  // --parsable: "jobid[;cluster]"
}

}  // namespace ppsynth
