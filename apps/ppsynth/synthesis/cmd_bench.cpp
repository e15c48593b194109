// `ppsynth bench [CONFIG] [--exemplar FILE] [--reps N] [--json FILE] [--set k=v ...]`
// Times one synthesis iteration of the Gabor method split into phases (min and median over
// repetitions), the set-up per sigma (exemplar maps, features, loss targets), the same
// binary's own 120 -> 120 7x7 convolution throughput in float32 and in bfloat16 channels-last
// (the bf16 network's fast path; on a CPU without bf16 units, where oneDNN emulates it, timed
// once on a small map), the iteration's convolution floor on each (network FLOPs / that
// throughput) and the iteration's ratio to each, and the peak resident memory. It opens with
// the machine report (`ppsynth doctor`): processor class, ISA caps, bf16 units, threads, BLAS. Then whole
// iterations as a run takes them, through the library's synthesize() (optimizer step,
// convergence bookkeeping, and a checkpoint written after every iteration: the worst case).
// A benchmark: it prints numbers; no test asserts on them.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_options_of.hpp"
#include "core/memory_budget.hpp"
#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/per_point_sum.hpp"
#include "models/network_precision.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/steps/initializer.hpp"
#include "optim/run/machine_report.hpp"
#include "optim/run/runtime.hpp"
#include "optim/run/synthesize.hpp"

namespace {

using namespace ppsynth;
using Clock = std::chrono::steady_clock;

struct Timing {
  std::vector<double> s;
  double min() const { return *std::min_element(s.begin(), s.end()); }
  double median() const {
    auto v = s;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
};

// Waits for the work queued on a CUDA device (runtime.device), so a phase is timed to its end.
void wait_for_device() {
  if (torch::cuda::is_available()) torch::cuda::synchronize();
}

template <class F>
Timing time_it(int reps, F&& f) {
  f();  // warm-up
  wait_for_device();
  Timing t;
  for (int r = 0; r < reps; ++r) {
    auto a = Clock::now();
    f();
    wait_for_device();
    t.s.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  return t;
}

// FLOPs of forward + input gradient of every convolution the net runs on a 1 x C x R x R input.
double net_flops(int in_channels, int channels, int ksize, int depth, int R) {
  double f = 0;
  auto conv = [&](int cin, int cout, int hout) { f += 2.0 * cin * cout * ksize * ksize * double(hout) * hout; };
  conv(in_channels, channels, R);
  conv(channels, channels, R);
  int h = R;
  for (int b = 1; b < depth; ++b) {
    h = (h + 1) / 2;
    conv(channels, channels, h);
  }
  return 2 * f;  // backward to the input costs as much as forward
}

struct Opts {
  std::string config, exemplar, json_out;
  std::vector<std::string> sets;
  std::string device;
  int reps = 5;
  bool skip_setup = false;
};

// What the bench times: the config's Gabor pipeline on the paper's u x u output, set to its
// finest sigma (every config's most expensive stage, on the grid every config shares at its
// end; per-sigma grids make the coarser ones cheaper), on the config's device.
struct Subject {
  json r;                      // the resolved run config
  TypedRunOptions run;         // r read through its table
  torch::Device device = torch::kCPU;
  PointSet ex, start;
  GaborSettings s;
  std::unique_ptr<GaborPipeline> pipe;
  torch::Tensor ex_pts, moving, ex_w, out_w;
  int u = 1;
  int bench_sigma = 0;         // the finest sigma's index
  double sigma = 0;
  int R = 0;                   // its output grid
  Clock::time_point t0;        // before the settings were resolved (the first set-up's start)
};

Subject make_subject(const Opts& o) {
  json c = o.config.empty() ? json::object() : load_config(o.config);
  if (!o.exemplar.empty()) c["exemplar"] = o.exemplar;
  if (!o.device.empty()) c["runtime"]["device"] = o.device;
  Subject b;
  b.r = resolve_run_config(c, o.sets);
  b.run = run_options_of(b.r, o.config.empty() ? "bench's config" : o.config);
  // Before any work (the initializer alone can take a minute): the figures' file must be
  // writable, and neither the config nor the exemplar. An earlier --json is replaced.
  if (!o.json_out.empty()) {
    app::check_output_files({{"--json", o.json_out}}, {{"config", o.config}, {"exemplar", b.run.options.exemplar}}, /*force=*/true);
    check_writable(o.json_out);
  }
  if (b.run.method_type != "gabor") throw InputError("bench: only the gabor method is benchmarked");
  b.device = torch::Device(apply_device_settings(b.run.options.runtime).device);
  const json& p = b.run.options.method;
  b.ex = load_exemplar(b.r);
  b.u = b.run.options.upscale;
  const uint64_t seed = b.run.seed;
  b.t0 = Clock::now();
  OutputShape shape;  // the paper's u x u output: the bench times its iteration
  shape.upscale = b.u;
  b.s = resolve_gabor_settings(p, b.ex, shape, false);
  b.pipe = std::make_unique<GaborPipeline>(b.s, seed, b.device);
  auto init = InitializerRegistry::instance().create(p["init"], "method.init");
  b.start = init->initialize(b.ex.size() * b.u * b.u, 0, seed, Domain{});
  b.ex_pts = positions_tensor(b.ex).to(b.device);
  b.moving = positions_tensor(b.start).to(b.device).set_requires_grad(true);
  // Map weights (disks, multi-attribute scenes): the output carries the exemplar's values u^2 times.
  b.ex_w = b.s.attr_cols.empty() ? torch::Tensor() : normalized_attributes(b.ex, b.s.attr_cols).to(b.device);
  b.out_w = b.ex_w.defined() ? b.ex_w.repeat({b.u * b.u, 1}) : torch::Tensor();
  b.bench_sigma = static_cast<int>(b.s.sigmas.size()) - 1;
  b.sigma = b.s.sigmas.back();
  b.R = b.s.sigma_out_res[b.bench_sigma];
  b.pipe->set_grid(b.bench_sigma);
  return b;
}

// The set-up: exemplar maps -> features -> targets; the first (with the settings' resolution)
// and, unless skipped, each sigma's. Leaves the pipeline at the finest sigma.
struct SetupTimes {
  double first = 0;
  std::vector<double> each;
};

SetupTimes time_setup(Subject& b, bool skip_each) {
  SetupTimes t;
  auto a = Clock::now();
  b.pipe->set_targets(b.ex_pts, b.ex_w, b.sigma);
  t.first = std::chrono::duration<double>(Clock::now() - a).count() + std::chrono::duration<double>(a - b.t0).count();
  if (!skip_each)
    for (size_t i = 0; i < b.s.sigmas.size(); ++i) {
      b.pipe->set_grid(static_cast<int>(i));
      auto c = Clock::now();
      b.pipe->set_targets(b.ex_pts, b.ex_w, b.s.sigmas[i]);
      t.each.push_back(std::chrono::duration<double>(Clock::now() - c).count());
    }
  b.pipe->set_grid(b.bench_sigma);
  b.pipe->set_targets(b.ex_pts, b.ex_w, b.sigma);
  return t;
}

// A backward phase's times less its forward's median (the backward is timed with its forward).
void subtract(Timing& backward, const Timing& forward) {
  const double fwd = forward.median();
  for (auto& x : backward.s) x = std::max(0.0, x - fwd);
}

// One iteration by phase, then whole forward + backward passes.
struct PhaseTimes {
  std::vector<std::pair<std::string, Timing>> phases;
  Timing full;
  int map_channels = 0;  // the network's input channels (the floor's FLOPs)
};

PhaseTimes time_phases(Subject& b, int reps, std::mt19937_64& rng) {
  GaborPipeline& pipe = *b.pipe;
  GaborMapsOptions mo;
  mo.res = b.R;  // the finest sigma's grid (the pipeline's)
  mo.upscale = b.u;
  mo.k = b.s.k;
  GaborFeatureMaps maps_mod(mo);
  maps_mod->to(b.device);
  auto pts = wrap_unit(b.moving.detach());
  auto jit = pipe.draw_jitter(rng);
  auto grid = jit.defined() ? maps_mod->grid() + jit : maps_mod->grid();
  PhaseTimes t;
  auto& phases = t.phases;
  phases.push_back({"neighbor search (k-NN)", time_it(reps, [&] {
                      b.device.is_cpu() ? grid_knn(pts, grid, b.s.k) : grid_knn_tensor_ops(pts, grid, b.s.k);
                    })});
  torch::Tensor maps;
  phases.push_back({"Gabor maps forward", time_it(reps, [&] {
                      torch::NoGradGuard ng;
                      maps = pipe.output_maps(pts, b.out_w, b.sigma, jit);
                    })});
  phases.push_back({"Gabor maps backward", time_it(reps, [&] {
                      auto p2 = pts.clone().set_requires_grad(true);
                      auto m = pipe.output_maps(p2, b.out_w, b.sigma, jit);
                      m.backward(torch::ones_like(m));
                    })});
  subtract(phases[2].second, phases[1].second);
  Features feats;
  phases.push_back({"network forward", time_it(reps, [&] {
                      torch::NoGradGuard ng;
                      feats = pipe.features(maps);
                    })});
  phases.push_back({"network backward (input grad)", time_it(reps, [&] {
                      auto m = maps.clone().set_requires_grad(true);
                      auto f = pipe.features(m);
                      torch::Tensor sum;
                      for (auto& x : f) sum = sum.defined() ? sum + x.sum() : x.sum();
                      sum.backward();
                    })});
  subtract(phases[4].second, phases[3].second);
  for (auto& term : pipe.composite().terms()) {
    phases.push_back({"loss " + term.type + " (forward + backward)", time_it(reps, [&] {
                        Features f;
                        for (auto& x : feats) f.push_back(x.detach().clone().set_requires_grad(true));
                        term.loss->forward(f).backward();
                      })});
  }
  {  // the maps' backward's last step both ways (models/per_point_sum.hpp): a deterministic CUDA run gathers
    const auto idx = (b.device.is_cpu() ? grid_knn(pts, grid, b.s.k) : grid_knn_tensor_ops(pts, grid, b.s.k)).reshape({-1});
    const auto values = torch::rand({idx.size(0), 2}, pts.options());
    for (const auto& [name, method] : {std::pair{"maps backward's per-point sum, index_add", PointSumMethod::scatter},
                                       std::pair{"maps backward's per-point sum, gather", PointSumMethod::gather}})
      phases.push_back({name, time_it(reps, [&, method = method] { sum_per_point(values, idx, pts.size(0), method); })});
  }
  t.full = time_it(reps, [&] {
    if (b.moving.grad().defined()) b.moving.grad().zero_();
    auto m = pipe.output_maps(wrap_unit(b.moving), b.out_w, b.sigma, pipe.draw_jitter(rng));
    pipe.loss(pipe.features(m)).backward();
  });
  t.map_channels = static_cast<int>(maps.size(1));
  return t;
}

// Whole iterations as a run takes them, through the run library's synthesize(): the first
// stage (with one sigma, the finest: a multi-class exemplar's first class, a rectangle's first
// window), a checkpoint written after every iteration (the worst case). The run is stopped
// once that stage ends: later stages would time the same thing again (and their clocks start
// anew, so differences across a stage boundary mean nothing).
struct RunIterationTimes {
  Timing iteration;  // the first (warm-up) left out
  Timing checkpoint_write;
  size_t checkpoint_bytes = 0;
};

RunIterationTimes time_run_iterations(const Subject& b, int reps) {
  struct FirstStageClock : SynthesisObserver {
    std::vector<double> at;  // seconds since the stage began, at the end of each of its iterations
    std::atomic<bool> stop{false};
    void on_iteration(const ProgressEvent& e) override {
      if (e.stage_index == 0) at.push_back(e.seconds);
    }
    void on_stage_end(const ProgressEvent&, const PointSet&) override { stop = true; }
  } clock;
  json spec = b.r;
  spec["method"]["num_sigmas"] = 1;
  spec["method"]["max_iterations"] = reps + 2;
  spec["checkpoint_seconds"] = 1e-9;  // a checkpoint after every iteration
  spec["evaluate"] = false;
  CheckpointStore checkpoints(
      (std::filesystem::temp_directory_path() / ("ppsynth-bench-" + std::to_string(::getpid()) + ".bin")).string());
  RunIterationTimes t;
  SynthesisOptions options;
  options.observers = {&clock};
  options.stop = &clock.stop;
  options.save_checkpoint = [&](const std::string& bytes) {
    const auto a = Clock::now();
    checkpoints.save(bytes);
    t.checkpoint_write.s.push_back(std::chrono::duration<double>(Clock::now() - a).count());
    t.checkpoint_bytes = std::max(t.checkpoint_bytes, bytes.size());
  };
  try {
    synthesize(b.ex, spec, options);
  } catch (const SynthesisInterrupted&) {
    // stopped after the first stage, as asked
  }
  checkpoints.remove();
  for (size_t i = 2; i < clock.at.size(); ++i) t.iteration.s.push_back(clock.at[i] - clock.at[i - 1]);
  if (t.iteration.s.empty() && !clock.at.empty()) t.iteration.s.push_back(clock.at.back());
  return t;
}

// The convolution floor: the network's FLOPs over this binary's own convolution throughput,
// in float32 and in bfloat16 (the path the config runs decides which is its floor).
struct Floor {
  std::vector<ConvThroughput> paths;  // float32, bfloat16
  int bf16_res = 0;                   // where bf16's throughput was measured
  double flops = 0;                   // the network's, forward + input gradient
  bool bf16 = false;                  // the config's network runs bf16
  double gflops() const { return paths[bf16 ? 1 : 0].gflops; }
  double seconds() const { return flops / (gflops() * 1e9); }
};

Floor convolution_floor(const Subject& b, int map_channels, int reps) {
  // The network as its registry resolves it (its declared defaults under the config's).
  const nlohmann::json net = FeatureNetRegistry::instance().resolve(b.s.feature_net, "method.feature_net");
  const bool random_net = net["type"] == "random";
  Floor f;
  // Emulated bf16 runs at about 1/100 of float32 (minutes per convolution at R = 256): its
  // throughput is taken once on a 64 x 64 map, where it is the same per FLOP.
  const bool bf16_units = !b.device.is_cpu() || cpu_isa().native_bf16;
  f.bf16_res = bf16_units ? b.R : std::min(b.R, 64);
  f.paths = {conv_throughput_float32(b.R, reps, b.device)};
  // Where no bf16 convolution can run (an AVX-512 CPU with oneDNN capped below AVX512_CORE,
  // core/processor.hpp) there is no bf16 floor: float32's alone.
  if (!b.device.is_cpu() || !cpu_isa().bf16_unavailable)
    f.paths.push_back(conv_throughput_bfloat16(f.bf16_res, bf16_units ? reps : 1, b.device));
  if (random_net) {
    f.flops = net_flops(map_channels, net["channels"].get<int>(), net["kernel_size"].get<int>(), net["depth"].get<int>(), b.R);
    f.bf16 = resolve_network_precision(net["precision"].get<std::string>(), "method.feature_net.precision").dtype == torch::kBFloat16;
  }
  return f;
}

// Prints the figures and returns them as the --json document.
json report(const Subject& b, const SetupTimes& setup, const PhaseTimes& it, const RunIterationTimes& run, const Floor& floor) {
  json out = {{"exemplar", b.run.options.exemplar}, {"device", b.device.str()}, {"points", b.ex.size()}, {"output_points", b.start.size()},
              {"grid", b.s.sigma_res[b.bench_sigma]}, {"output_grid", b.R}, {"k", b.s.k}, {"threads", at::get_num_threads()}};
  const MachineReport machine = machine_report(0, 0);  // the floors are this config's, below
  std::printf("%s\n", machine.text().c_str());
  out["machine"] = machine.to_json();
  std::printf("ppsynth bench: %s  (%zu -> %zu points, grid %d -> %d, k %d, %d threads, %s)\n",
              b.run.options.exemplar.c_str(), b.ex.size(), b.start.size(), b.s.sigma_res[b.bench_sigma], b.R, b.s.k,
              at::get_num_threads(), b.device.str().c_str());
  std::printf("%-42s %10s %10s\n", "phase", "min [s]", "median [s]");
  json jp = json::array();
  for (auto& [name, t] : it.phases) {
    std::printf("%-42s %10.4f %10.4f\n", name.c_str(), t.min(), t.median());
    jp.push_back({{"phase", name}, {"min_s", t.min()}, {"median_s", t.median()}});
  }
  const Timing& full = it.full;
  const Timing& engine = run.iteration;
  std::printf("%-42s %10.4f %10.4f\n", "ONE FULL ITERATION (forward + backward)", full.min(), full.median());
  std::printf("%-42s %10.4f %10.4f\n", "ONE RUN ITERATION (+ step + checkpoint)", engine.min(), engine.median());
  std::printf("  checkpoint: %.1f KiB, written in %.2f ms (median of %zu)\n", run.checkpoint_bytes / 1024.0,
              1e3 * run.checkpoint_write.median(), run.checkpoint_write.s.size());
  std::printf("\nconvolution 120->120 7x7 at %dx%d, network %.1f GFLOP per iteration (fwd + input grad); this config runs "
              "the %s path:\n",
              b.R, b.R, floor.flops / 1e9, floor.paths[floor.bf16 ? 1 : 0].path.c_str());
  std::printf("  %-24s %10s %10s %14s %18s\n", "path", "GFLOP/s", "floor [s]", "iter / floor", "run iter / floor");
  json jfloors = json::array();
  for (const auto& p : floor.paths) {
    const double f = floor.flops / (p.gflops * 1e9);
    std::printf("  %-24s %10.1f %10.3f %14.2f %18.2f\n", p.path.c_str(), p.gflops, f, floor.flops > 0 ? full.median() / f : 0.0,
                floor.flops > 0 ? engine.median() / f : 0.0);
    jfloors.push_back({{"path", p.path}, {"conv_gflops", p.gflops}, {"floor_s", f},
                       {"measured_at_grid", &p == &floor.paths.front() ? b.R : floor.bf16_res},
                       {"iteration_over_floor", floor.flops > 0 ? full.median() / f : 0}});
  }
  if (floor.paths.size() > 1) {
    std::printf("  bfloat16 / float32 throughput: %.3gx", floor.paths[1].gflops / floor.paths[0].gflops);
    if (floor.bf16_res != b.R) std::printf(" (bf16 emulated here: its throughput measured once at %dx%d)", floor.bf16_res, floor.bf16_res);
  } else {
    std::printf("  bfloat16: no bf16 convolution runs on this CPU as capped (%s)", cpu_isa().kind().c_str());
  }
  std::printf("\n");
  out["floors"] = jfloors;
  std::printf("set-up before the first iteration: %.2f s", setup.first);
  if (setup.each.empty()) {
    std::printf(" (per-sigma set-up not timed: --skip-setup)\n");
  } else {
    double setup_total = 0;
    std::printf("; per sigma:");
    for (double x : setup.each) std::printf(" %.2f", x), setup_total += x;
    std::printf(" s (all %zu sigmas %.2f s)\n", setup.each.size(), setup_total);
  }
  std::printf("peak resident memory: %.0f MiB\n", peak_resident_mib());
  const double floor_s = floor.seconds();
  out["phases"] = jp;
  out["iteration_min_s"] = full.min();
  out["iteration_median_s"] = full.median();
  out["conv_gflops"] = floor.gflops();
  out["net_gflop_per_iteration"] = floor.flops / 1e9;
  out["floor_s"] = floor_s;
  out["iteration_over_floor"] = floor_s > 0 ? full.median() / floor_s : 0;
  out["run_iteration_min_s"] = engine.min();
  out["run_iteration_median_s"] = engine.median();
  out["run_iteration_over_floor"] = floor_s > 0 ? engine.median() / floor_s : 0;
  out["checkpoint_bytes"] = run.checkpoint_bytes;
  out["checkpoint_write_median_s"] = run.checkpoint_write.median();
  out["setup_first_s"] = setup.first;
  out["setup_per_sigma_s"] = setup.each;
  out["peak_rss_mib"] = peak_resident_mib();
  return out;
}

app::RunFn setup(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  app.add_option("config", o->config, "experiment config (JSON)");
  app.add_option("--exemplar,-e", o->exemplar, "exemplar point file");
  app.add_option("--set", o->sets, "override a config key: key.path=value");
  app.add_option("--device", o->device, "where it runs: cpu, cuda, cuda:N or auto (runtime.device)");
  app.add_option("--reps", o->reps, "repetitions per phase")->check(ppsynth::app::whole_number(1, 1000000));
  app.add_option("--json", o->json_out, "also write the figures as JSON");
  app.add_flag("--skip-setup", o->skip_setup, "do not time the set-up of every sigma");
  return [o]() {
    configure_runtime();  // threads, allocator, the Gabor maps' path, as a synthesis has them
    Subject b = make_subject(*o);
    std::mt19937_64 rng(b.run.seed);
    const SetupTimes setup = time_setup(b, o->skip_setup);
    const PhaseTimes iteration = time_phases(b, o->reps, rng);
    const RunIterationTimes run = time_run_iterations(b, o->reps);
    const Floor floor = convolution_floor(b, iteration.map_channels, o->reps);
    const json out = report(b, setup, iteration, run, floor);
    if (!o->json_out.empty()) write_text_atomic(o->json_out, out.dump(2) + "\n");
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("bench", "time one synthesis iteration by phase against the convolution floor", setup)
