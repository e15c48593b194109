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
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <thread>

#include <torch/cuda.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "core/shell_quote.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "models/device_capabilities.hpp"
#include "optim/run/run_options_of.hpp"
#include "optim/run/runtime.hpp"
#include "experiments/execute/sweep_runs.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

// The environment of this process with PPSYNTH_THREADS set to `threads`, and the one card a
// task sees (card >= 0: CUDA_VISIBLE_DEVICES as this process numbers them).
std::vector<std::string> task_environment(int threads, int card) {
  std::vector<std::string> env;
  const char* visible = std::getenv("CUDA_VISIBLE_DEVICES");
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "PPSYNTH_THREADS=", 16) != 0 && (card < 0 || std::strncmp(*e, "CUDA_VISIBLE_DEVICES=", 21) != 0))
      env.emplace_back(*e);
  env.push_back("PPSYNTH_THREADS=" + std::to_string(threads));
  if (card >= 0) {
    // The card as the user's own list names it, when they set one.
    std::vector<std::string> listed;
    for (std::string v = visible ? visible : ""; !v.empty();) {
      const size_t comma = v.find(',');
      listed.push_back(v.substr(0, comma));
      v = comma == std::string::npos ? "" : v.substr(comma + 1);
    }
    env.push_back("CUDA_VISIBLE_DEVICES=" + (card < static_cast<int>(listed.size()) ? listed[card] : std::to_string(card)));
  }
  return env;
}

// Whether a row's runtime.device is a CUDA device here, and whether it may be any card.
// `source`: where the row's config was read, for its errors.
void note_device(const SweepRow& row, const std::string& source, bool cuda_here, LocalWork& work) {
  const std::string device = run_options_of(row.config, source).options.runtime.device.get<std::string>();  // checked there
  const bool cuda = device.rfind("cuda", 0) == 0 || (device == "auto" && cuda_here);
  if (!cuda) return;
  work.on_cuda = true;
  if (device != "cuda" && device != "cuda:0" && device != "auto") work.any_card = false;
}

LocalMachine this_machine() {
  LocalMachine m;
  m.cores = usable_cores();
  m.env_threads = threads_from_environment();
  if (torch::cuda::is_available())
    for (int i = 0, n = static_cast<int>(torch::cuda::device_count()); i < n; ++i)
      m.card_memory_bytes.push_back(cuda_capabilities(i).memory_bytes);
  return m;
}

std::string gib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  return buf;
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

LocalSlots plan_local_slots(const LocalExecution& how, const LocalMachine& machine, const LocalWork& work) {
  LocalSlots s;
  const int cores = std::max(1, machine.cores);
  const int cards = static_cast<int>(machine.card_memory_bytes.size());
  if (!work.on_cuda || cards == 0) {
    s.jobs = how.jobs > 0 ? how.jobs : 1;
    s.reason = how.jobs > 0 ? "-j " + std::to_string(how.jobs) : "one at a time (-j sets more)";
  } else {
    // Every card takes the same count: the smallest card's room, at most its share of the
    // cores (each run keeps a core busy launching its kernels).
    const double smallest = *std::min_element(machine.card_memory_bytes.begin(), machine.card_memory_bytes.end());
    const int core_share = std::max(1, cores / cards);
    if (how.runs_per_device > 0) {
      s.runs_per_device = how.runs_per_device;
      s.reason = std::to_string(s.runs_per_device) + " per card as asked";
    } else if (smallest > 0 && work.run_memory_bytes > 0) {
      // A tenth of the card kept free: LibTorch's allocator and cuDNN's workspaces.
      const int fit = static_cast<int>(0.9 * smallest / work.run_memory_bytes);
      s.runs_per_device = std::clamp(fit, 1, core_share);
      s.reason = std::to_string(s.runs_per_device) + " per card: " + std::to_string(fit) + " runs of " + gib(work.run_memory_bytes) +
                 " (the spec's resources.memory_mb) fit in 90 % of " + gib(smallest) + ", and " + std::to_string(cores) +
                 " cores give each card " + std::to_string(core_share);
    } else {
      s.runs_per_device = 1;
      s.reason = "1 per card: its memory is unknown";
    }
    s.jobs = how.jobs > 0 ? how.jobs : std::max<int>(1, static_cast<int>(std::min<size_t>(
                                                            static_cast<size_t>(cards) * s.runs_per_device, std::max<size_t>(1, work.rows))));
    s.reason += "; " + std::to_string(s.jobs) + " at once on " + std::to_string(cards) + " card" + (cards == 1 ? "" : "s");
    if (cards > 1 && work.any_card)
      for (int slot = 0; slot < s.jobs; ++slot) s.card_of_slot.push_back(slot % cards);
  }
  s.card_of_slot.resize(static_cast<size_t>(s.jobs), -1);
  s.threads = how.threads > 0 ? how.threads : machine.env_threads > 0 ? machine.env_threads : std::max(1, cores / s.jobs);
  return s;
}

ExecutionSummary execute_local(const std::string& sweep_dir, const LocalExecution& how, const std::atomic<bool>* stop) {
  if (how.jobs < 0 || how.jobs > 1024) throw InputError("-j " + std::to_string(how.jobs) + ": expected 1 to 1024 tasks at once");
  if (how.runs_per_device < 0 || how.runs_per_device > 1024)
    throw InputError("--runs-per-device " + std::to_string(how.runs_per_device) + ": expected 1 to 1024");
  const SweepManifest m = load_sweep(sweep_dir);
  const SweepLock lock(sweep_dir, "run it");
  const std::string manifest = sweep_manifest_hash(m);
  ExecutionSummary sum;
  std::deque<size_t> queue;
  LocalWork work;
  work.run_memory_bytes = m.resources.memory_mb * 1024.0 * 1024.0;
  const LocalMachine machine = this_machine();
  for (const auto& s : sweep_status(sweep_dir, m)) {
    const size_t i = static_cast<size_t>(s.row - m.rows.data());
    if (s.state == RowState::Done || s.state == RowState::Running) {
      ++sum.skipped;
    } else {
      queue.push_back(i);
      note_device(m.rows[i], (fs::path(sweep_dir) / "manifest.json").string() + " rows[" + std::to_string(i) + "].config",
                  !machine.card_memory_bytes.empty(), work);
    }
  }
  work.rows = queue.size();
  const LocalSlots slots = plan_local_slots(how, machine, work);
  const int threads = slots.threads;
  spdlog::info("sweep {}: {} runs to do, {} done or running; {} at once, {} thread{} each", m.name, queue.size(),
               sum.skipped, slots.jobs, threads, threads == 1 ? "" : "s");
  if (slots.runs_per_device > 0) spdlog::info("sweep {}: rows on CUDA: {}", m.name, slots.reason);
  std::vector<std::vector<std::string>> env_of_slot;
  for (int card : slots.card_of_slot) env_of_slot.push_back(task_environment(threads, card));
  std::vector<bool> slot_busy(static_cast<size_t>(slots.jobs), false);
  struct Running {
    size_t row;
    std::chrono::steady_clock::time_point started;
    size_t slot;
  };
  std::map<pid_t, Running> running;
  bool stopping = false;
  auto stop_all = [&] {
    if (stopping) return;
    stopping = true;
    spdlog::warn("sweep {}: stopping {} running task(s) (each writes a checkpoint where it has reached one)", m.name, running.size());
    for (auto& [pid, info] : running) ::kill(pid, SIGTERM);
  };
  while (!running.empty() || (!queue.empty() && !stopping)) {
    if (stop && stop->load()) stop_all();
    while (!stopping && !queue.empty() && static_cast<int>(running.size()) < slots.jobs) {
      const size_t i = queue.front();
      queue.pop_front();
      const size_t slot = static_cast<size_t>(std::find(slot_busy.begin(), slot_busy.end(), false) - slot_busy.begin());
      slot_busy[slot] = true;
      const std::string log = (fs::path(sweep_dir) / "logs" / (m.rows[i].id + ".log")).string();
      running[spawn_task(how, sweep_dir, m.rows[i].id, manifest, log, env_of_slot[slot])] = {i, std::chrono::steady_clock::now(), slot};
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
    const auto [i, started, slot] = it->second;
    slot_busy[slot] = false;
    running.erase(it);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const SweepRow& row = m.rows[i];
    if (code == 0) {
      ++sum.done;
      double cpu = 0;  // the run's CPU time: what its work cost, however many ran beside it
      try {
        cpu = read_run_record((fs::path(sweep_dir) / row.dir / "run.json").string()).cpu_seconds;
      } catch (const InputError&) {
        // an unreadable run.json is `sweep status`'s to report; this line then gives the wall time alone
      }
      if (cpu > 0)
        spdlog::info("[{}] {}: done ({:.0f} s; CPU {:.0f} s)", row.id, row.label, s, cpu);
      else
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
