#include "optim/run/run_synthesis.hpp"

#include <ATen/Parallel.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/formats/text_table.hpp"
#include "core/output_shape.hpp"
#include "core/processor.hpp"
#include "core/run_directory.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_observers.hpp"
#include "optim/run/synthesize.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

const char* kCheckpoint = "checkpoint.bin";

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

// Runs (or continues, with `resume_state`) the synthesis into the open directory `dir`.
RunOutcome execute(RunOutcome o, RunDirectory& dir, const std::string& name, const RunRequest& req,
                   const std::string* resume_state) {
  const auto t0 = std::chrono::steady_clock::now();
  const nlohmann::json& r = o.config;
  o.dir = dir.path();
  ProgressLog progress(name, req.quick ? 1 : 10);
  LossRecorder losses;
  SnapshotWriter snaps(o.dir + "/snapshots");
  snaps.set_enabled(r["snapshots"].get<bool>());
  MarkerProgress marker_progress(dir);
  SynthesisOptions options;
  options.quick = req.quick;
  options.observers = {&progress, &losses, &snaps, &marker_progress};
  options.observers.insert(options.observers.end(), req.observers.begin(), req.observers.end());
  bool checkpointed = resume_state != nullptr;
  options.save_checkpoint = [&](const std::string& bytes) {
    AtomicFile f(o.dir + "/" + kCheckpoint, std::ios::binary);
    f.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.commit();
    checkpointed = true;
    dir.mark_progress({{"checkpointed", unix_now()}});
  };
  options.resume_state = resume_state;
  options.stop = req.stop;
  const OutputShape shape = resolve_output_shape(r, o.exemplar);
  spdlog::info("[{}] {} points, {} classes -> {:.0f} points, {} ({}), seed {}", name, o.exemplar.size(), o.exemplar.num_classes(),
               shape.expected_points(o.exemplar), shape.describe(), r["method"]["type"].get<std::string>(), r["seed"].get<uint64_t>());
  try {
    fs::create_directories(o.dir + "/snapshots");
    SynthesisResult res = synthesize(o.exemplar, r, options);
    o.output = std::move(res.output);
    o.initialization = std::move(res.initialization);
    o.stats = std::move(res.stats);
    o.metrics = std::move(res.metrics);
    write_run_outputs(o, name, req.quick, losses, res.seconds, t0);
    dir.mark_complete({{"seed", r["seed"]}});
  } catch (const SynthesisInterrupted&) {
    throw RunInterrupted(o.dir);  // the checkpoint stays for --resume
  } catch (...) {
    if (!checkpointed) dir.discard();  // nothing to resume from: leave nothing behind
    throw;
  }
  std::error_code ec;
  fs::remove(o.dir + "/" + kCheckpoint, ec);  // a finished run needs no checkpoint
  spdlog::info("[{}] wrote {} ({:.1f} s)", name, o.dir, o.seconds);
  return o;
}

}  // namespace

RunOutcome run_synthesis(const nlohmann::json& r, const RunRequest& req) {
  RunOutcome o;
  o.config = r;
  o.exemplar = load_exemplar(r);  // bad input fails here, before anything is created
  const std::string name = run_name(r);
  if (req.dir.empty() && !is_safe_name(name))
    throw InputError("the run name '" + name + "' (the exemplar's file name) is not a plain name; give the run directory with -o");
  RunDirOptions dir_options;
  dir_options.force = req.force;
  RunDirectory dir = RunDirectory::open(req.dir.empty() ? "runs/" + name : req.dir, dir_options);
  try {
    // What a resume needs, written first: the resolved config and the way it ran.
    write_text_atomic(dir.path() + "/config.json", r.dump(2) + "\n");
    dir.mark_running(
        {{"quick", req.quick}, {"threads", at::get_num_threads()}, {"processor", processor_kind()}, {"seed", r["seed"]}});
  } catch (...) {
    dir.discard();
    throw;
  }
  return execute(std::move(o), dir, name, req, nullptr);
}

std::string run_progress_text(const nlohmann::json& marker, long long now) {
  if (!marker.is_object() || !marker.contains("progress") || !marker["progress"].is_object()) return "";
  const nlohmann::json& p = marker["progress"];
  std::string text;
  if (p.contains("index")) {
    text = "stage " + std::to_string(p.value("index", 0)) + "/" + std::to_string(p.value("count", 0));
    if (p.contains("window"))
      text += ", window " + std::to_string(p.value("window", 0)) + "/" + std::to_string(p.value("windows", 0));
    if (const std::string label = p.value("stage", ""); !label.empty()) text += " (" + label + ")";
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

RunOutcome resume_synthesis(const std::string& path, const RunRequest& req) {
  RunDirOptions dir_options;
  dir_options.resume = true;
  dir_options.option = "--resume";
  RunDirectory dir = RunDirectory::open(path, dir_options);
  const nlohmann::json marker = run_dir_marker(dir.path());
  RunOutcome o;
  o.config = read_run_json(dir.path() + "/config.json");
  o.exemplar = load_exemplar(o.config);
  const std::string checkpoint = dir.path() + "/" + kCheckpoint;
  if (!fs::exists(checkpoint))
    throw InputError("--resume " + dir.path() + ": no checkpoint (the run stopped before its first one, or its method (" +
                     o.config["method"].value("type", "?") + ") cannot resume); start it again with --force");
  const std::string bytes = read_file_text(checkpoint);
  // A SLURM requeue may land on another node: the resumed run is then not the uninterrupted one.
  if (const std::string differences = made_differently(marker); !differences.empty())
    spdlog::warn("--resume {}: the run started with {}: the result may differ from an uninterrupted run's "
                 "(the same thread count is PPSYNTH_THREADS={})",
                 dir.path(), differences, marker.value("threads", nlohmann::json()).dump());
  RunRequest r = req;
  r.quick = marker.value("quick", false);
  const std::string name = run_name(o.config);
  return execute(std::move(o), dir, name, r, &bytes);
}

}  // namespace ppsynth
