#include "optim/run/run_synthesis.hpp"

#include <ATen/Parallel.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/checkpoint_file.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/processor.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "core/shell_quote.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_observers.hpp"
#include "optim/run/run_spec.hpp"
#include "optim/run/synthesize.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

long long unix_now() { return static_cast<long long>(std::time(nullptr)); }

// Keeps the marker of the run directory telling which stage the run began last, so that
// `ppsynth sweep status` can say how far a running or interrupted run is (run_progress_text).
class MarkerProgress : public SynthesisObserver {
 public:
  explicit MarkerProgress(RunDirectory& dir) : dir_(dir) {}
  void on_stage_begin(const ProgressEvent& e) override {
    nlohmann::json p = {{"stage", e.stage}, {"index", e.stage_index + 1}, {"count", e.stage_count}};
    if (e.windows > 1) p.update({{"window", e.window + 1}, {"windows", e.windows}});
    dir_.mark_progress(p);
  }

 private:
  RunDirectory& dir_;
};

// Runs (or continues, with `resume_state`) the synthesis of `spec` into the open directory `dir`.
RunOutcome execute(const RunSpec& spec, RunDirectory& dir, const std::string& name, const RunRequest& req,
                   const std::string* resume_state) {
  const auto t0 = std::chrono::steady_clock::now();
  const nlohmann::json& r = spec.config;
  RunOutcome o;
  o.config = r;
  o.exemplar = spec.exemplar;
  o.exemplar_format = spec.exemplar_format;
  o.dir = dir.path();
  ProgressLog progress(name, req.quick ? 1 : 10);
  LossRecorder losses;
  SnapshotWriter snaps(o.dir + "/snapshots");
  snaps.set_enabled(spec.options.snapshots);
  MarkerProgress marker_progress(dir);
  SynthesisOptions options;
  options.quick = req.quick;
  options.observers = {&progress, &losses, &snaps, &marker_progress};
  options.observers.insert(options.observers.end(), req.observers.begin(), req.observers.end());
  CheckpointStore checkpoints(checkpoint_file_in(o.dir));
  options.save_checkpoint = checkpoints.saver([&] { dir.mark_progress({{"checkpointed", unix_now()}}); });
  options.resume_state = resume_state;
  options.resume_source = checkpoints.file();
  // Something to resume from: the checkpoint this run continues, or one it saved.
  auto checkpointed = [&] { return resume_state != nullptr || checkpoints.saved(); };
  options.stop = req.stop;
  spdlog::info("[{}] {} points, {} classes -> {:.0f} points, {} ({}), seed {}", name, o.exemplar.size(), o.exemplar.num_classes(),
               spec.shape.expected_points(o.exemplar), spec.shape.describe(), spec.options.method["type"].get<std::string>(), spec.seed);
  try {
    fs::create_directories(o.dir + "/snapshots");
    SynthesisResult res = synthesize(spec, options);
    o.output = std::move(res.output);
    o.initialization = std::move(res.initialization);
    o.stages = std::move(res.stages);
    o.seconds_before_resume = res.seconds_before_resume;
    o.cpu_seconds = res.cpu_seconds;
    o.stats = std::move(res.stats);
    o.metrics = std::move(res.metrics);
    write_run_outputs(o, spec.options, name, req.quick, losses, res.seconds, t0);
    dir.mark_complete({{"seed", spec.seed}});
  } catch (const SynthesisInterrupted&) {
    if (checkpointed()) throw RunInterrupted(o.dir);  // the checkpoint stays for --resume
    dir.discard();  // stopped before its first checkpoint: nothing to resume, nothing kept
    throw RunInterrupted("");
  } catch (...) {
    if (!checkpointed()) dir.discard();  // nothing to resume from: leave nothing behind
    throw;
  }
  checkpoints.remove();  // a finished run needs no checkpoint
  spdlog::info("[{}] wrote {} ({:.1f} s)", name, o.dir, o.seconds);
  return o;
}

}  // namespace

RunOutcome run_synthesis(const RunSpec& spec, const RunRequest& req) {
  const nlohmann::json& r = spec.config;
  const std::string name = run_name(r);
  if (req.dir.empty() && !is_safe_name(name))
    throw InputError("the run name '" + name + "' (the exemplar's file name) is not a plain name; give the run directory with -o");
  RunDirOptions dir_options;
  dir_options.force = req.force;
  RunDirectory dir = RunDirectory::open(req.dir.empty() ? "runs/" + name : req.dir, dir_options);
  try {
    // What a resume needs, written first: the resolved config, the exemplar as synthesized
    // (a resume reads this copy, so a run directory moved to another machine, or whose
    // exemplar file changed or is gone, continues; the checkpoint's key holds the exemplar's
    // content hash, so an edited copy is refused) and the way it ran.
    write_text_atomic(dir.path() + "/config.json", r.dump(2) + "\n");
    write_points(dir.path() + "/exemplar.txt", spec.exemplar, Format::Plain);
    dir.mark_running({{"quick", req.quick},
                      {"threads", at::get_num_threads()},
                      {"processor", processor_kind()},
                      {"seed", spec.seed},
                      {"exemplar_format", format_name(spec.exemplar_format)}});
  } catch (...) {
    dir.discard();
    throw;
  }
  return execute(spec, dir, name, req, nullptr);
}

RunOutcome run_synthesis(const nlohmann::json& resolved, const RunRequest& req) {
  return run_synthesis(load_run_spec(resolved), req);  // bad input fails here, before anything is created
}

namespace {

// What to do when a run cannot continue from its checkpoint.
std::string afresh_hint(const std::string& dir) {
  return "; `ppsynth synthesize --resume " + shell_quoted(dir) + " --force` starts the run afresh from its config.json";
}

// --resume DIR --force: the run in DIR again from the start, from its config.json (checked as
// any config) and its quick setting; the directory's files are replaced.
RunOutcome restart(const std::string& path, const RunRequest& req) {
  const std::string dir = normalize_output_dir(path, "--resume");
  const RunDirState state = run_dir_state(dir);
  if ((state != RunDirState::Unfinished && state != RunDirState::Complete) || run_dir_marker(dir).value("kind", "") != "run")
    throw InputError("--resume " + dir + " --force: not a run directory of ppsynth; nothing to start afresh");
  RunRequest r = req;
  r.dir = dir;
  r.quick = run_dir_marker(dir).value("quick", false);
  return run_synthesis(resolve_run_config(read_run_config(dir + "/config.json"), {}), r);
}

}  // namespace

RunOutcome resume_synthesis(const std::string& path, const RunRequest& req) {
  if (req.force) return restart(path, req);
  RunDirOptions dir_options;
  dir_options.resume = true;
  dir_options.option = "--resume";
  RunDirectory dir = RunDirectory::open(path, dir_options);
  const nlohmann::json marker = run_dir_marker(dir.path());
  const nlohmann::json config = read_resolved_run_config(dir.path() + "/config.json");
  const CheckpointStore checkpoints(checkpoint_file_in(dir.path()));
  const std::string& checkpoint = checkpoints.file();
  if (!checkpoints.exists())
    throw InputError("--resume " + dir.path() + ": no checkpoint (the run stopped before its first one, or its method (" +
                     config["method"]["type"].get<std::string>() + ") cannot resume)" + afresh_hint(dir.path()));
  const Format exemplar_format = marker.contains("exemplar_format") ? parse_format(marker["exemplar_format"])  // checked with the marker
                                                                    : detect_format(config["exemplar"]);     // runs made before it
  const RunSpec spec = make_run_spec(config, run_exemplar(dir.path(), config), exemplar_format);  // the run's own copy (run_synthesis)
  const std::string bytes = checkpoints.load();
  RunRequest r = req;
  r.quick = marker.value("quick", false);
  try {  // refused before anything runs or prints
    check_checkpoint(bytes, checkpoint, checkpoint_key(spec, r.quick));
  } catch (const CheckpointError& e) {
    throw CheckpointError(e.what() + afresh_hint(dir.path()));
  }
  // A SLURM requeue may land on another node: the resumed run is then not the uninterrupted one.
  if (const std::string differences = made_differently(marker); !differences.empty())
    spdlog::warn("--resume {}: the run started with {}: the result may differ from an uninterrupted run's "
                 "(the same thread count is PPSYNTH_THREADS={})",
                 dir.path(), differences, marker.value("threads", nlohmann::json()).dump());
  const std::string name = run_name(config);
  try {
    return execute(spec, dir, name, r, &bytes);
  } catch (const CheckpointError& e) {
    throw CheckpointError(e.what() + afresh_hint(dir.path()));
  }
}

}  // namespace ppsynth
