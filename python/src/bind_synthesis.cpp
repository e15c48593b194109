// Synthesis from Python on the run library (optim/run): synthesize() in memory, run() and
// resume() into run directories. The synthesis runs on the caller's thread with the GIL
// released; at every iteration a PythonWatch takes the GIL for a moment to hand the progress
// callable its event and to check for Ctrl-C. Either one raising stops the run at the end of
// the iteration -- the method writes its checkpoint first -- and the exception (a
// KeyboardInterrupt for Ctrl-C) is raised when the call returns.
#include <pybind11/stl.h>
#include <torch/torch.h>

#include <atomic>
#include <filesystem>
#include <memory>

#include "bindings.hpp"
#include "json_python.hpp"
#include "core/checkpoint_file.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/processor.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_observers.hpp"
#include "optim/run/run_synthesis.hpp"
#include "optim/run/runtime.hpp"
#include "optim/run/synthesize.hpp"

namespace fs = std::filesystem;

namespace ppsynth::python {

namespace {

// The process-wide settings of optim/run/runtime.hpp, applied at the first synthesis (never at
// import); `threads` > 0 overrides PPSYNTH_THREADS for this and later calls.
int apply_runtime(int threads) {
  configure_runtime();
  if (threads < 0 || threads > 1024) throw InputError("threads: expected 0 (all cores, or PPSYNTH_THREADS) to 1024");
  if (threads > 0) torch::set_num_threads(threads);
  return at::get_num_threads();
}

py::dict event_dict(const ProgressEvent& e) {
  py::dict d;
  d["stage"] = e.stage;
  d["stage_index"] = e.stage_index;
  d["stage_count"] = e.stage_count;
  d["iteration"] = e.iteration;
  d["max_iterations"] = e.max_iterations;
  d["loss"] = e.loss;
  d["seconds"] = e.seconds;
  return d;
}

class PythonWatch : public SynthesisObserver {
 public:
  PythonWatch(py::object progress, bool resumable) : progress_(std::move(progress)), resumable_(resumable) {}
  ~PythonWatch() override {
    py::gil_scoped_acquire gil;  // the Python objects held here go with the GIL
    error_.reset();
    progress_ = py::object();
  }

  void on_iteration(const ProgressEvent& e) override {
    py::gil_scoped_acquire gil;
    if (error_) return;
    if (PyErr_CheckSignals() != 0) {
      error_ = std::make_unique<py::error_already_set>();
    } else if (!progress_.is_none()) {
      try {
        progress_(event_dict(e));
      } catch (py::error_already_set& err) {
        error_ = std::make_unique<py::error_already_set>(std::move(err));
      }
    }
    if (!error_) return;
    stop_.store(true);
    // A method that cannot checkpoint ignores the stop flag: end it here instead.
    if (!resumable_) throw py::error_already_set(*error_);
  }

  // Between iterations (the initialization, a window's set-up): Ctrl-C sets the stop flag,
  // which the method sees at once (SynthesisContext::poll).
  void on_poll() override {
    py::gil_scoped_acquire gil;
    if (error_ || PyErr_CheckSignals() == 0) return;
    error_ = std::make_unique<py::error_already_set>();
    stop_.store(true);
  }

  const std::atomic<bool>* stop() const { return &stop_; }
  bool stopped() const { return error_ != nullptr; }
  // With the GIL: raises what stopped the run.
  [[noreturn]] void raise() { throw py::error_already_set(*error_); }

 private:
  py::object progress_;
  bool resumable_;
  std::atomic<bool> stop_{false};
  std::unique_ptr<py::error_already_set> error_;
};

// synthesize(checkpoint_dir=...): the checkpoint of one in-memory synthesis, in a folder the
// caller names, written as ppsynth's own and nothing else: the folder is a ppsynth directory
// of kind "checkpoint" (its marker and lock, core/run_directory.hpp) that holds only the
// marker and checkpoint.bin. A new or empty folder becomes one; a folder holding anything
// else is refused, never written to or emptied. The checkpoint carries the key of its
// synthesis (the run layer refuses another's). A finished synthesis removes the two files,
// and the folder when ppsynth made it.
class CheckpointDir {
 public:
  explicit CheckpointDir(const std::string& dir) {
    RunDirOptions o;
    o.kind = "checkpoint";
    o.option = "checkpoint_dir";
    o.resume = run_dir_state(normalize_output_dir(dir, o.option)) == RunDirState::Unfinished;
    dir_ = std::make_unique<RunDirectory>(RunDirectory::open(dir, o));
    for (const auto& e : fs::directory_iterator(dir_->path()))
      if (const std::string name = e.path().filename().string(); name != ".ppsynth-run" && name != fs::path(checkpoint_file_in("")).filename())
        throw InputError("checkpoint_dir " + dir_->path() + ": holds " + name + ", which ppsynth did not write there; "
                         "name a folder of the checkpoint's own (new or empty)");
    if (!o.resume) dir_->mark_running({{"made_folder", dir_->created()}});
    made_folder_ = run_dir_marker(dir_->path()).value("made_folder", false);
    store_ = std::make_unique<CheckpointStore>(checkpoint_file_in(dir_->path()));
  }
  const std::string& path() const { return dir_->path(); }
  CheckpointStore& store() { return *store_; }

  // The bytes of its checkpoint, or nullopt when there is none yet.
  std::optional<std::string> load() const {
    if (!store_->exists()) return std::nullopt;
    return store_->load();
  }
  // A finished synthesis needs no checkpoint: the marker and checkpoint.bin go (the folder
  // holds nothing else), and the folder too when ppsynth made it.
  void finish() {
    dir_->discard();
    std::error_code ec;
    if (made_folder_) fs::remove(dir_->path(), ec);
  }

 private:
  std::unique_ptr<RunDirectory> dir_;
  std::unique_ptr<CheckpointStore> store_;
  bool made_folder_ = false;
};

// The package's Stage fields (python/ppsynth/synthesis.py), from the typed records.
py::list stage_list(const std::vector<StageRecord>& stages) {
  py::list l;
  for (const auto& s : stages) {
    py::dict d;
    d["stage"] = s.stage;
    d["iterations"] = s.iterations;
    d["final_loss"] = s.final_loss;
    d["seconds"] = s.seconds;
    d["details"] = pyjson::from_json(s.details);
    l.append(d);
  }
  return l;
}

py::list loss_rows(const LossRecorder& losses) {
  py::list l;
  for (const auto& r : losses.rows()) l.append(py::make_tuple(r.stage_index, r.stage, r.iteration, r.loss, r.seconds));
  return l;
}

py::dict outcome_dict(const RunOutcome& o) {
  py::dict d;
  d["dir"] = o.dir;
  d["exemplar"] = to_python(o.exemplar);
  d["initialization"] = to_python(o.initialization);
  d["output"] = to_python(o.output);
  d["stages"] = stage_list(o.stages);
  d["stats"] = pyjson::from_json(o.stats);
  d["metrics"] = pyjson::from_json(o.metrics);
  d["config"] = pyjson::from_json(o.config);
  d["seconds"] = o.seconds;
  d["cpu_seconds"] = o.cpu_seconds;  // 0: not recorded (synthesis.py makes it None)
  return d;
}

py::dict synthesize_in_memory(const py::dict& exemplar_py, const py::object& config, bool quick,
                              const py::object& initialization_py, const py::object& progress,
                              const std::string& checkpoint_dir, int threads) {
  const json spec = from_python_json(config, "config");
  const PointSet exemplar = from_python(exemplar_py, "exemplar");
  validate(exemplar, "exemplar");
  std::optional<PointSet> init;
  if (!initialization_py.is_none()) {
    init = from_python(initialization_py, "initialization");
    validate(*init, "initialization");
  }
  const int used_threads = apply_runtime(threads);
  const bool resumable = can_resume(spec);
  if (!checkpoint_dir.empty() && !resumable)
    throw InputError("checkpoint_dir: the method " + spec["method"].value("type", std::string("?")) + " cannot checkpoint");

  LossRecorder losses;
  PythonWatch watch(progress, resumable);
  SynthesisOptions options;
  options.quick = quick;
  options.observers = {&losses, &watch};
  options.initialization = init ? &*init : nullptr;
  options.stop = watch.stop();
  std::unique_ptr<CheckpointDir> checkpoints;
  std::optional<std::string> resume_state;
  if (!checkpoint_dir.empty()) {
    checkpoints = std::make_unique<CheckpointDir>(checkpoint_dir);
    resume_state = checkpoints->load();
    options.resume_state = resume_state ? &*resume_state : nullptr;
    options.resume_source = checkpoints->store().file();
    options.save_checkpoint = checkpoints->store().saver();
  }
  SynthesisResult r;
  try {
    py::gil_scoped_release unlocked;
    r = synthesize(exemplar, spec, options);
  } catch (const SynthesisInterrupted&) {
    if (!watch.stopped()) throw;
    watch.raise();
  } catch (const CheckpointError& e) {
    throw CheckpointError(std::string(e.what()) + "; name another checkpoint_dir, or empty " + checkpoints->path() +
                          " to start afresh");
  }
  if (watch.stopped()) watch.raise();  // stopped during the last iteration: the checkpoint stays
  if (checkpoints) checkpoints->finish();

  py::dict d;
  d["output"] = to_python(r.output);
  d["initialization"] = to_python(r.initialization);
  d["stages"] = stage_list(r.stages);
  d["losses"] = loss_rows(losses);
  d["stats"] = pyjson::from_json(r.stats);
  d["metrics"] = pyjson::from_json(r.metrics);
  d["seconds"] = r.seconds;
  d["cpu_seconds"] = r.cpu_seconds;  // 0: not recorded (synthesis.py makes it None)
  d["threads"] = used_threads;
  d["processor"] = processor_kind();
  d["resumed"] = resume_state.has_value();
  return d;
}

py::dict run_into_directory(const py::object& config, const std::string& dir, bool quick, bool force,
                            const py::object& progress, int threads, bool resume) {
  apply_runtime(threads);
  RunRequest req;
  req.dir = dir;
  req.quick = quick;
  req.force = force;
  json spec;
  if (!resume) spec = from_python_json(config, "config");
  else spec = read_run_config(dir + "/config.json");
  PythonWatch watch(progress, can_resume(spec));
  req.stop = watch.stop();
  req.observers = {&watch};
  RunOutcome o;
  try {
    py::gil_scoped_release unlocked;
    o = resume ? resume_synthesis(dir, req) : run_synthesis(spec, req);
  } catch (const RunInterrupted&) {
    if (!watch.stopped()) throw;
    watch.raise();
  }
  if (watch.stopped()) watch.raise();
  return outcome_dict(o);
}

}  // namespace

void bind_synthesis(py::module_& m) {
  m.def("load_config", [](const std::string& path) { return load_config(path); }, py::arg("path"));
  m.def(
      "resolve_config",
      [](const py::object& config, const std::vector<std::string>& assignments, const py::dict& values) {
        json c = from_python_json(config, "config");
        for (auto kv : values) {
          const std::string key = py::str(kv.first);
          set_at_key_path(c, key, from_python_json(kv.second, "overrides['" + key + "']"));
        }
        return resolve_run_config(std::move(c), assignments);
      },
      py::arg("config"), py::arg("assignments"), py::arg("values"));
  m.def("load_exemplar", [](const py::object& config) { return to_python(load_exemplar(from_python_json(config, "config"))); });
  m.def("synthesize", &synthesize_in_memory, py::arg("exemplar"), py::arg("config"), py::arg("quick"),
        py::arg("initialization"), py::arg("progress"), py::arg("checkpoint_dir"), py::arg("threads"));
  m.def(
      "run",
      [](const py::object& config, const std::string& dir, bool quick, bool force, const py::object& progress, int threads) {
        return run_into_directory(config, dir, quick, force, progress, threads, false);
      },
      py::arg("config"), py::arg("dir"), py::arg("quick"), py::arg("force"), py::arg("progress"), py::arg("threads"));
  m.def(
      "resume",
      [](const std::string& dir, const py::object& progress, int threads) {
        return run_into_directory(py::none(), dir, false, false, progress, threads, true);
      },
      py::arg("dir"), py::arg("progress"), py::arg("threads"));
  m.def("threads", [] { return at::get_num_threads(); }, "the intra-op thread count LibTorch uses now");
}

}  // namespace ppsynth::python
