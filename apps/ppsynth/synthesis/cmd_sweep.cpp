// `ppsynth sweep plan SPEC -o DIR`            expand a sweep spec into DIR/manifest.json
// `ppsynth sweep run DIR --local [-j N]`      run what is not done, N tasks at once
// `ppsynth sweep run DIR --slurm [--dry-run]` the same as a SLURM job array
// `ppsynth sweep status DIR [--json]`         done / running / interrupted / failed / pending
// `ppsynth sweep task DIR --row ID [--manifest HASH]`  one row, by its id (what every executor runs)
// The library: experiments/plan (sweep_plan), experiments/execute (runs, executors). Statistics: `ppsynth gather`.
#include <filesystem>
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/stop_signals.hpp"
#include "core/error.hpp"
#include "optim/run/run_synthesis.hpp"
#include "optim/run/runtime.hpp"
#include "experiments/execute/sweep_executors.hpp"
#include "experiments/execute/sweep_runs.hpp"

namespace {

using namespace ppsynth;
namespace fs = std::filesystem;

struct Opts {
  std::string spec, dir, partition, account, row, manifest;
  std::vector<std::string> sbatch_options;
  bool local = false, slurm = false, dry_run = false, json = false;
  int jobs = 0, runs_per_device = 0, threads = 0, cpus = 0, memory_mb = 0, time_minutes = 0, max_parallel = 0;
};

std::string self_binary() { return fs::read_symlink("/proc/self/exe").string(); }

int plan(const Opts& o) {
  const SweepManifest m = expand_sweep_spec(o.spec);
  const PlanSummary s = plan_sweep(m, o.dir);
  std::printf("sweep %s: %zu runs planned in %s (%zu kept, %zu new, %zu no longer planned)\n", m.name.c_str(), s.rows,
              s.dir.c_str(), s.kept, s.added, s.dropped);
  std::printf("next: ppsynth sweep run %s --local -j N   (or --slurm)\n", s.dir.c_str());
  return 0;
}

int status(const Opts& o) {
  const SweepManifest m = load_sweep(o.dir);
  const auto rows = sweep_status(o.dir, m);
  std::map<std::string, size_t> count;
  for (const auto& r : rows) ++count[row_state_name(r.state)];
  if (o.json) {
    json a = json::array();
    for (const auto& r : rows)
      a.push_back({{"id", r.row->id}, {"state", row_state_name(r.state)}, {"seed", r.row->seed}, {"label", r.row->label},
                   {"dir", r.row->dir}, {"detail", r.detail}});
    std::cout << json{{"sweep", m.name}, {"counts", count}, {"runs", a}}.dump(2) << "\n";
    return 0;
  }
  std::printf("sweep %s (%s): %zu runs: %zu done, %zu running, %zu interrupted, %zu failed, %zu pending\n", m.name.c_str(),
              o.dir.c_str(), rows.size(), count["done"], count["running"], count["interrupted"], count["failed"], count["pending"]);
  std::printf("%-12s  %-11s  %6s  %s\n", "id", "state", "seed", "run");
  for (const auto& r : rows) {
    std::string detail = r.detail.size() > 100 ? r.detail.substr(0, 97) + "..." : r.detail;
    std::printf("%-12s  %-11s  %6llu  %s%s\n", r.row->id.c_str(), row_state_name(r.state),
                static_cast<unsigned long long>(r.row->seed), r.row->label.c_str(),
                detail.empty() ? "" : ("  (" + detail + ")").c_str());
  }
  return 0;
}

int run(const Opts& o) {
  if (o.local == o.slurm) throw InputError("sweep run: choose one executor, --local or --slurm");
  if (o.local) {
    if (o.dry_run) throw InputError("--dry-run is for --slurm");
    check_runtime_environment();  // what every task reads: a bad value fails here once, not in each task
    app::install_stop_handlers();
    LocalExecution how;
    how.binary = self_binary();
    how.jobs = o.jobs;
    how.threads = o.threads;
    how.runs_per_device = o.runs_per_device;
    const ExecutionSummary s = execute_local(o.dir, how, app::stop_flag());
    std::printf("sweep %s: %zu done now, %zu failed, %zu interrupted, %zu done or running before\n", o.dir.c_str(), s.done,
                s.failed, s.interrupted, s.skipped);
    if (app::stop_signal() != 0) return app::exit_code_for_stop();
    return s.failed > 0 ? 1 : 0;
  }
  SlurmExecution how;
  how.binary = self_binary();
  how.partition = o.partition;
  how.account = o.account;
  how.sbatch_options = o.sbatch_options;
  how.cpus = o.cpus;
  how.memory_mb = o.memory_mb;
  how.time_minutes = o.time_minutes;
  how.max_parallel = o.max_parallel;
  const SweepManifest m = load_sweep(o.dir);
  const std::string script = slurm_script(o.dir, m, how);
  if (script.empty()) {
    std::printf("sweep %s: every run is done; nothing to submit\n", o.dir.c_str());
    return 0;
  }
  if (o.dry_run) {
    std::cout << script;
    return 0;
  }
  const std::string job = submit_slurm(o.dir, script);
  std::printf("submitted job array %s (%s/sweep.sbatch); follow it with: ppsynth sweep status %s\n", job.c_str(),
              o.dir.c_str(), o.dir.c_str());
  return 0;
}

int task(const Opts& o) {
  configure_runtime();  // threads, allocator, the Gabor maps' path: optim/run/runtime.hpp
  app::install_stop_handlers();
  try {
    run_sweep_task(o.dir, o.row, o.manifest, app::stop_flag());
  } catch (const RunInterrupted& e) {
    std::cerr << "ppsynth sweep task: stopped by " << app::stop_signal_name()
              << (e.dir.empty() ? std::string(" before its first checkpoint") : "; the checkpoint is in " + e.dir)
              << "; the next task for row " << o.row << " resumes it\n";
    return app::exit_code_for_stop();
  }
  return 0;
}

app::RunFn setup(CLI::App& cmd) {
  auto o = std::make_shared<Opts>();
  cmd.require_subcommand(1);
  auto* p = cmd.add_subcommand("plan", "expand a sweep spec into a manifest of runs");
  p->add_option("spec", o->spec, "sweep spec (JSON)")->required()->check(app::path_text());
  p->add_option("-o,--out", o->dir, "sweep directory (new, empty, or this sweep's to re-plan)")
      ->required()
      ->check(app::path_text());
  auto* r = cmd.add_subcommand("run", "run the sweep's runs that are not done");
  r->add_option("dir", o->dir, "sweep directory")->required()->check(app::path_text());
  r->add_flag("--local", o->local, "run here, -j tasks at once");
  r->add_option("-j,--jobs", o->jobs, "tasks at once (--local; default: 1, or for rows on CUDA the cards' room)")
      ->check(app::whole_number(1, 1024));
  r->add_option("--runs-per-device", o->runs_per_device,
                "rows on CUDA: runs at once per card (--local; default: as many as its memory holds at resources.memory_mb, "
                "at most its share of the cores)")
      ->check(app::whole_number(1, 1024));
  r->add_option("--threads", o->threads, "threads per task (--local; default: PPSYNTH_THREADS, else cores / jobs)")
      ->check(app::whole_number(1, 1024));
  r->add_flag("--slurm", o->slurm, "submit a SLURM job array, one task per run");
  r->add_flag("--dry-run", o->dry_run, "print the job script, submit nothing (--slurm)");
  r->add_option("--partition", o->partition, "SLURM partition (letters, digits, '_', '-', '.')");
  r->add_option("--account", o->account, "SLURM account (letters, digits, '_', '-', '.')");
  r->add_option("--sbatch-option", o->sbatch_options, "an extra #SBATCH option, e.g. --qos=long (repeatable)");
  r->add_option("--cpus", o->cpus, "CPUs per task (default: the spec's resources.cpus)")->check(app::whole_number(1, kMaxSweepCpus));
  r->add_option("--mem-mb", o->memory_mb, "memory per task in MiB (default: the spec's)")
      ->check(app::whole_number(1, kMaxSweepMemoryMb));
  r->add_option("--time-minutes", o->time_minutes, "time limit per task (default: the spec's)")
      ->check(app::whole_number(1, kMaxSweepMinutes));
  r->add_option("--max-parallel", o->max_parallel, "at most this many array tasks at once")->check(app::whole_number(1, 100000));
  auto* s = cmd.add_subcommand("status", "list the sweep's runs and their state");
  s->add_option("dir", o->dir, "sweep directory")->required()->check(app::path_text());
  s->add_flag("--json", o->json, "print JSON");
  auto* t = cmd.add_subcommand("task", "run one row of the sweep (what each worker and array task runs)");
  t->add_option("dir", o->dir, "sweep directory")->required()->check(app::path_text());
  t->add_option("--row", o->row, "the row's id (`ppsynth sweep status` lists them)")->required();
  t->add_option("--manifest", o->manifest, "the plan's hash the task was given (a plan changed since is noted)");
  return [o, p, r, s, t]() -> int {
    if (p->parsed()) return plan(*o);
    if (r->parsed()) return run(*o);
    if (s->parsed()) return status(*o);
    return task(*o);
  };
}

}  // namespace

PPSYNTH_COMMAND("sweep", "plan, run (here or on SLURM) and follow experiments over seeds and configs", setup)
