#pragma once
// SynthesisMethod: "exemplar in, larger pattern out". The paper's Gabor method and the
// baselines (thesis Chapter 3 and Chapter 4) are all methods, registered by config name and
// chosen with `ppsynth synthesize --method NAME` or the config's "method" object, so every
// runner and report handles a new method with no code change.
//
// This header is torch-free on purpose: baselines in optim/baselines/ build without LibTorch.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/output_shape.hpp"
#include "core/point_set.hpp"
#include "core/registry.hpp"
#include "optim/method/stage_record.hpp"

namespace ppsynth {

// What a method reports while it runs. Apps attach observers (progress line, snapshot
// writer, loss-curve recorder); methods never print or write files themselves.
struct ProgressEvent {
  std::string stage;        // e.g. "class 1/2, sigma 3/4" or "scale 2"
  int stage_index = 0;      // 0-based over the whole run
  int stage_count = 1;
  int iteration = 0;        // within the stage
  int max_iterations = 0;   // cap within the stage (0 = unknown)
  double loss = 0;
  double seconds = 0;       // wall time since the stage began
  int window = 0;           // large outputs: the stage's window (0-based) of `windows`
  int windows = 1;
  bool window_ends = true;  // the window's last stage (snapshots and canvas progress then)
  // Large outputs: the window's grid in output units. A window's snapshot shows this part,
  // not the canvas: a canvas per window would make the snapshots grow with the area squared
  // (docs/lab/large_outputs.md says how much).
  Domain window_grid;
  // At a stage's beginning: why it does what it does, where the stage decides that itself
  // (the border relax: how much its class parks, and whether its band moves). Empty otherwise.
  std::string note;
};

class SynthesisObserver {
 public:
  virtual ~SynthesisObserver() = default;
  // The output before optimization (the initialization), once.
  virtual void on_start(const PointSet& initial) {}
  virtual void on_stage_begin(const ProgressEvent&) {}
  virtual void on_iteration(const ProgressEvent&) {}
  // `current` is the whole output so far (frozen and moving points, with classes/attrs).
  virtual void on_stage_end(const ProgressEvent&, const PointSet& current) {}
  // A resumed run: the iterations run before the checkpoint, in order (their on_iteration
  // events, replayed once), then the run continues with on_iteration as usual.
  virtual void on_resume(const std::vector<ProgressEvent>& earlier) {}
  // During long work between iterations (initialization, a window's set-up), several times a
  // second: a front end's chance to see a stop of its own (Python's Ctrl-C) and set the stop
  // flag it handed the run.
  virtual void on_poll() {}
};

// Thrown by a method that stopped on SynthesisContext::stop (after saving a checkpoint when
// it had the state for one).
class SynthesisInterrupted : public std::runtime_error {
 public:
  SynthesisInterrupted() : std::runtime_error("interrupted; the last checkpoint holds the state") {}
};

// What the caller of a synthesis gives besides its config (the command, Python, bench, tests:
// synthesize() in optim/run/synthesize.hpp), and what the method gets of it as part of its
// SynthesisContext: one type, declared once.
struct SynthesisOptions {
  bool quick = false;                          // tiny grids, few iterations (tests, --quick)
  std::vector<SynthesisObserver*> observers;   // told of every stage and iteration
  // An explicit initialization, else the config's init_file, else the method's initializer.
  const PointSet* initialization = nullptr;
  // Checkpoints, for methods that can resume (SynthesisMethod::can_resume). The method hands
  // its state as opaque bytes to `save_checkpoint` at every stage boundary and at least every
  // `checkpoint_seconds` of wall time (SynthesisContext); the run layer stores them. With
  // `resume_state` (bytes from an earlier save_checkpoint of the same config, seed and
  // exemplar) it continues from there instead of starting; a resume_state of another
  // synthesis, or a damaged one, is a CheckpointError (core/checkpoint_file.hpp) naming
  // `resume_source`, before any work. When `stop` becomes true (a signal), it saves a
  // checkpoint at the end of the current iteration and throws SynthesisInterrupted.
  std::function<void(const std::string& state)> save_checkpoint;
  const std::string* resume_state = nullptr;
  std::string resume_source = "checkpoint";
  const std::atomic<bool>* stop = nullptr;
};

// Everything a method gets besides its own parameters: the caller's options and what the run
// layer resolved from the config.
struct SynthesisContext : SynthesisOptions {
  uint64_t seed = 95;
  // The output's size and shape (core/output_shape.hpp): the paper's u x u unit square, or
  // a rectangle in exemplar units (every method returns a PointSet on output.domain()).
  OutputShape output;
  // Where a method built on LibTorch keeps its tensors: "cpu" or "cuda:N", the config's
  // runtime.device resolved and checked (optim/run/runtime.hpp); whether float32 products
  // there run on TF32 tensor cores and whether CUDA picks deterministic algorithms (both
  // applied process-wide already; the method records them). The baselines run on the CPU.
  std::string device = "cpu";
  bool tf32 = false;
  bool deterministic = true;
  // Optional: the method records what it measured here (wall time per phase, resolved
  // settings such as the grid and sigmas).
  nlohmann::json* stats = nullptr;
  // Optional: a method that works in stages records each finished stage here, typed
  // (optim/method/stage_record.hpp), with the time of the processes before a resume.
  StagesReport* stages = nullptr;

  // The checkpoints' interval (SynthesisOptions::save_checkpoint), and which synthesis they
  // belong to (core/checkpoint_file.hpp's key: resolved config, seed, exemplar, quick, method
  // version): written into every checkpoint and compared with resume_state's. Null: neither
  // (a method tested on its own).
  double checkpoint_seconds = 60;
  nlohmann::json checkpoint_key;

  bool stop_requested() const { return stop && stop->load(); }
  // Long work between iterations calls this often (cheap: it looks at the clock); at most
  // every 0.1 s it asks the observers (on_poll) and throws SynthesisInterrupted once `stop` is
  // set, so a stop is seen within a second wherever the method is.
  void poll() const {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_poll_ < std::chrono::milliseconds(100)) return;
    last_poll_ = now;
    for (auto* o : observers) o->on_poll();
    if (stop_requested()) throw SynthesisInterrupted();
  }
  void start(const PointSet& p) const { for (auto* o : observers) o->on_start(p); }
  void stage_begin(const ProgressEvent& e) const { for (auto* o : observers) o->on_stage_begin(e); }
  void iteration(const ProgressEvent& e) const { for (auto* o : observers) o->on_iteration(e); }
  void resumed(const std::vector<ProgressEvent>& earlier) const { for (auto* o : observers) o->on_resume(earlier); }
  void stage_end(const ProgressEvent& e, const PointSet& p) const { for (auto* o : observers) o->on_stage_end(e, p); }

 private:
  mutable std::chrono::steady_clock::time_point last_poll_{};
};

class SynthesisMethod {
 public:
  virtual ~SynthesisMethod() = default;
  // Returns the output pattern on ctx.output.domain(); every point keeps its class and attributes.
  virtual PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) = 0;
  // True when the method honors the checkpoint fields of SynthesisContext. The others run
  // to the end in one go and cannot be resumed (the run layer says so).
  virtual bool can_resume() const { return false; }
  // Part of a checkpoint's key: bump it when a change of the method makes a run continued from
  // an earlier build's checkpoint differ from one never interrupted (another trajectory).
  virtual int version() const { return 1; }
};

// {"type": "gabor" | "roveri2015" | "pcf2017" | ..., params...}
using MethodRegistry = Registry<SynthesisMethod>;

// Refuses an explicit initialization (SynthesisContext::initialization) with a point outside
// `area`, where the method moves its points: an InputError naming the point (1-based), its
// position and the area. `method` begins the message ("pcf2017"); `area_name` says what the
// area is ("the synthesis canvas (the output rectangle in exemplar units, plus the clean
// border's pad)").
void check_initialization_inside(const PointSet& init, const Domain& area, const std::string& method,
                                 const std::string& area_name);

}  // namespace ppsynth
