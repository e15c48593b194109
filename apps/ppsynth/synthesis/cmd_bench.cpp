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
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "optim/run/checkpoint_store.hpp"
#include "optim/run/run_config.hpp"
#include "core/memory_budget.hpp"
#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/network_precision.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/gabor_pipeline.hpp"
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
    json c = o->config.empty() ? json::object() : load_config(o->config);
    if (!o->exemplar.empty()) c["exemplar"] = o->exemplar;
    if (!o->device.empty()) c["runtime"]["device"] = o->device;
    auto r = resolve_run_config(c, o->sets);
    if (r["method"]["type"] != "gabor") throw InputError("bench: only the gabor method is benchmarked");
    const torch::Device device(apply_device_settings(r["runtime"]).device);
    const json& p = r["method"];
    PointSet ex = load_exemplar(r);
    const int u = r["upscale"];
    const uint64_t seed = r["seed"];
    const auto settings_t0 = Clock::now();
    OutputShape shape;  // the paper's u x u output: the bench times its iteration
    shape.upscale = u;
    GaborSettings s = resolve_gabor_settings(p, ex, shape, false);
    GaborPipeline pipe(p, s, seed, device);
    auto init = InitializerRegistry::instance().create(p["init"], "method.init");
    PointSet start = init->initialize(ex.size() * u * u, 0, seed, Domain{});
    auto ex_pts = positions_tensor(ex).to(device);
    auto moving = positions_tensor(start).to(device).set_requires_grad(true);
    // Map weights (disks, multi-attribute scenes): the output carries the exemplar's values u^2 times.
    const auto ex_w = s.attr_cols.empty() ? torch::Tensor() : normalized_attributes(ex, s.attr_cols).to(device);
    const auto out_w = ex_w.defined() ? ex_w.repeat({u * u, 1}) : torch::Tensor();
    // The finest sigma: every config's most expensive stage, on the grid every config shares
    // at its end (per-sigma grids make the coarser ones cheaper), and the stage the one-stage
    // run below executes.
    const int bench_sigma = static_cast<int>(s.sigmas.size()) - 1;
    const double sigma = s.sigmas.back();
    const int R = s.sigma_out_res[bench_sigma];
    pipe.set_grid(bench_sigma);
    std::mt19937_64 rng(seed);
    json out = {{"exemplar", r["exemplar"]}, {"device", device.str()}, {"points", ex.size()}, {"output_points", start.size()},
                {"grid", s.sigma_res[bench_sigma]}, {"output_grid", R}, {"k", s.k}, {"threads", at::get_num_threads()}};

    // --- set-up: exemplar maps -> features -> targets, per sigma ----------------------
    double setup_first = 0;
    std::vector<double> setup_each;
    {
      auto a = Clock::now();
      pipe.set_targets(ex_pts, ex_w, sigma);
      setup_first = std::chrono::duration<double>(Clock::now() - a).count() +
                    std::chrono::duration<double>(a - settings_t0).count();
      if (!o->skip_setup)
        for (size_t i = 0; i < s.sigmas.size(); ++i) {
          pipe.set_grid(static_cast<int>(i));
          auto b = Clock::now();
          pipe.set_targets(ex_pts, ex_w, s.sigmas[i]);
          setup_each.push_back(std::chrono::duration<double>(Clock::now() - b).count());
        }
      pipe.set_grid(bench_sigma);
      pipe.set_targets(ex_pts, ex_w, sigma);
    }

    // --- phases of one iteration -----------------------------------------------------
    GaborMapsOptions mo;
    mo.res = R;  // the finest sigma's grid (the pipeline's, set above)
    mo.upscale = u;
    mo.k = s.k;
    GaborFeatureMaps maps_mod(mo);
    maps_mod->to(device);
    auto pts = wrap_unit(moving.detach());
    auto jit = pipe.draw_jitter(rng);
    auto grid = jit.defined() ? maps_mod->grid() + jit : maps_mod->grid();
    std::vector<std::pair<std::string, Timing>> phases;
    phases.push_back({"neighbor search (k-NN)", time_it(o->reps, [&] {
                        device.is_cpu() ? grid_knn(pts, grid, s.k) : grid_knn_tensor_ops(pts, grid, s.k);
                      })});
    torch::Tensor maps;
    phases.push_back({"Gabor maps forward", time_it(o->reps, [&] {
                        torch::NoGradGuard ng;
                        maps = pipe.output_maps(pts, out_w, sigma, jit);
                      })});
    phases.push_back({"Gabor maps backward", time_it(o->reps, [&] {
                        auto p2 = pts.clone().set_requires_grad(true);
                        auto m = pipe.output_maps(p2, out_w, sigma, jit);
                        auto probe = torch::ones_like(m);
                        // forward is inside: subtract it afterwards
                        m.backward(probe);
                      })});
    phases.back().second.s = [&] {
      auto v = phases.back().second.s;
      const double fwd = phases[1].second.median();
      for (auto& x : v) x = std::max(0.0, x - fwd);
      return v;
    }();
    Features feats;
    phases.push_back({"network forward", time_it(o->reps, [&] {
                        torch::NoGradGuard ng;
                        feats = pipe.features(maps);
                      })});
    phases.push_back({"network backward (input grad)", time_it(o->reps, [&] {
                        auto m = maps.clone().set_requires_grad(true);
                        auto f = pipe.features(m);
                        torch::Tensor sum;
                        for (auto& t : f) sum = sum.defined() ? sum + t.sum() : t.sum();
                        sum.backward();
                      })});
    phases.back().second.s = [&] {
      auto v = phases.back().second.s;
      const double fwd = phases[3].second.median();
      for (auto& x : v) x = std::max(0.0, x - fwd);
      return v;
    }();
    for (auto& term : pipe.composite().terms()) {
      phases.push_back({"loss " + term.type + " (forward + backward)", time_it(o->reps, [&] {
                          Features f;
                          for (auto& t : feats) f.push_back(t.detach().clone().set_requires_grad(true));
                          term.loss->forward(f).backward();
                        })});
    }
    auto optimizer_spec = p["optimizer"];
    Timing full = time_it(o->reps, [&] {
      if (moving.grad().defined()) moving.grad().zero_();
      auto m = pipe.output_maps(wrap_unit(moving), out_w, sigma, pipe.draw_jitter(rng));
      pipe.loss(pipe.features(m)).backward();
    });

    // --- whole iterations through the run library, checkpointing after each -----------------
    struct IterationClock : SynthesisObserver {
      std::vector<double> at;  // seconds since the stage began, at the end of each iteration
      void on_iteration(const ProgressEvent& e) override { at.push_back(e.seconds); }
    } iteration_clock;
    json engine_spec = r;
    // One stage: with one sigma, the run's only sigma is the finest (its grid, too).
    engine_spec["method"]["num_sigmas"] = 1;
    engine_spec["method"]["max_iterations"] = o->reps + 2;
    engine_spec["checkpoint_seconds"] = 1e-9;  // a checkpoint after every iteration
    engine_spec["evaluate"] = false;
    CheckpointStore checkpoints(
        (std::filesystem::temp_directory_path() / ("ppsynth-bench-" + std::to_string(::getpid()) + ".bin")).string());
    Timing checkpoint_write;
    size_t checkpoint_bytes = 0;
    SynthesisOptions engine_options;
    engine_options.observers = {&iteration_clock};
    engine_options.save_checkpoint = [&](const std::string& bytes) {
      const auto a = Clock::now();
      checkpoints.save(bytes);
      checkpoint_write.s.push_back(std::chrono::duration<double>(Clock::now() - a).count());
      checkpoint_bytes = std::max(checkpoint_bytes, bytes.size());
    };
    synthesize(ex, engine_spec, engine_options);
    checkpoints.remove();
    Timing engine;  // the first iteration (warm-up) is left out
    for (size_t i = 2; i < iteration_clock.at.size(); ++i) engine.s.push_back(iteration_clock.at[i] - iteration_clock.at[i - 1]);
    if (engine.s.empty()) engine.s.push_back(iteration_clock.at.back());

    // --- the convolution floor ---------------------------------------------------------
    // The network as its registry resolves it (its declared defaults under the config's).
    const nlohmann::json net = FeatureNetRegistry::instance().resolve(s.feature_net, "method.feature_net");
    const bool random_net = net["type"] == "random";
    const int C = random_net ? net["channels"].get<int>() : 0, ks = random_net ? net["kernel_size"].get<int>() : 0,
              depth = random_net ? net["depth"].get<int>() : 0;
    // Emulated bf16 runs at about 1/100 of float32 (minutes per convolution at R = 256): its
    // throughput is taken once on a 64 x 64 map, where it is the same per FLOP.
    const bool bf16_units = !device.is_cpu() || cpu_isa().native_bf16;
    const int bf16_res = bf16_units ? R : std::min(R, 64);
    const std::vector<ConvThroughput> paths = {conv_throughput_float32(R, o->reps, device),
                                               conv_throughput_bfloat16(bf16_res, bf16_units ? o->reps : 1, device)};
    const double flops = random_net ? net_flops(static_cast<int>(maps.size(1)), C, ks, depth, R) : 0;
    const bool bf16 = random_net &&
                      resolve_network_precision(net["precision"].get<std::string>(), "method.feature_net.precision").dtype ==
                          torch::kBFloat16;
    const double conv_gflops = paths[bf16 ? 1 : 0].gflops;  // the floor of the path this config runs
    const double floor_s = flops / (conv_gflops * 1e9);

    // --- print ---------------------------------------------------------------------------
    const MachineReport machine = machine_report(0, 0);  // the floors are this config's, below
    std::printf("%s\n", machine.text().c_str());
    out["machine"] = machine.to_json();
    std::printf("ppsynth bench: %s  (%zu -> %zu points, grid %d -> %d, k %d, %d threads, %s)\n",
                r["exemplar"].get<std::string>().c_str(), ex.size(), start.size(), s.sigma_res[bench_sigma], R, s.k, at::get_num_threads(),
                device.str().c_str());
    std::printf("%-42s %10s %10s\n", "phase", "min [s]", "median [s]");
    json jp = json::array();
    for (auto& [name, t] : phases) {
      std::printf("%-42s %10.4f %10.4f\n", name.c_str(), t.min(), t.median());
      jp.push_back({{"phase", name}, {"min_s", t.min()}, {"median_s", t.median()}});
    }
    std::printf("%-42s %10.4f %10.4f\n", "ONE FULL ITERATION (forward + backward)", full.min(), full.median());
    std::printf("%-42s %10.4f %10.4f\n", "ONE RUN ITERATION (+ step + checkpoint)", engine.min(), engine.median());
    std::printf("  checkpoint: %.1f KiB, written in %.2f ms (median of %zu)\n", checkpoint_bytes / 1024.0,
                1e3 * checkpoint_write.median(), checkpoint_write.s.size());
    std::printf("\nconvolution 120->120 7x7 at %dx%d, network %.1f GFLOP per iteration (fwd + input grad); this config runs "
                "the %s path:\n",
                R, R, flops / 1e9, paths[bf16 ? 1 : 0].path.c_str());
    std::printf("  %-24s %10s %10s %14s %18s\n", "path", "GFLOP/s", "floor [s]", "iter / floor", "run iter / floor");
    json jfloors = json::array();
    for (const auto& p : paths) {
      const double f = flops / (p.gflops * 1e9);
      std::printf("  %-24s %10.1f %10.3f %14.2f %18.2f\n", p.path.c_str(), p.gflops, f, flops > 0 ? full.median() / f : 0.0,
                  flops > 0 ? engine.median() / f : 0.0);
      jfloors.push_back({{"path", p.path}, {"conv_gflops", p.gflops}, {"floor_s", f},
                         {"measured_at_grid", &p == &paths[1] ? bf16_res : R},
                         {"iteration_over_floor", flops > 0 ? full.median() / f : 0}});
    }
    std::printf("  bfloat16 / float32 throughput: %.3gx", paths[1].gflops / paths[0].gflops);
    if (bf16_res != R) std::printf(" (bf16 emulated here: its throughput measured once at %dx%d)", bf16_res, bf16_res);
    std::printf("\n");
    out["floors"] = jfloors;
    std::printf("set-up before the first iteration: %.2f s", setup_first);
    if (setup_each.empty()) {
      std::printf(" (per-sigma set-up not timed: --skip-setup)\n");
    } else {
      double setup_total = 0;
      std::printf("; per sigma:");
      for (double x : setup_each) std::printf(" %.2f", x), setup_total += x;
      std::printf(" s (all %zu sigmas %.2f s)\n", setup_each.size(), setup_total);
    }
    std::printf("peak resident memory: %.0f MiB\n", peak_resident_mib());
    out["phases"] = jp;
    out["iteration_min_s"] = full.min();
    out["iteration_median_s"] = full.median();
    out["conv_gflops"] = conv_gflops;
    out["net_gflop_per_iteration"] = flops / 1e9;
    out["floor_s"] = floor_s;
    out["iteration_over_floor"] = floor_s > 0 ? full.median() / floor_s : 0;
    out["run_iteration_min_s"] = engine.min();
    out["run_iteration_median_s"] = engine.median();
    out["run_iteration_over_floor"] = floor_s > 0 ? engine.median() / floor_s : 0;
    out["checkpoint_bytes"] = checkpoint_bytes;
    out["checkpoint_write_median_s"] = checkpoint_write.median();
    out["setup_first_s"] = setup_first;
    out["setup_per_sigma_s"] = setup_each;
    out["peak_rss_mib"] = peak_resident_mib();
    if (!o->json_out.empty()) write_text_atomic(o->json_out, out.dump(2) + "\n");
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("bench", "time one synthesis iteration by phase against the convolution floor", setup)
