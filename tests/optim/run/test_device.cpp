// runtime.device (optim/run/runtime.hpp): its values and the errors naming the key, what a
// process without CUDA does with each, what the method records (run.json's method_stats),
// and, where this process sees a CUDA device, a synthesis there: the same bits twice, and one
// evaluation (loss and gradient) equal to the CPU's within float32 rounding. Tagged [device]:
// scripts/gpu_check.sh runs these on the GPU machine.
#include <catch2/catch.hpp>

#include <torch/cuda.h>

#include <iostream>

#include "core/processor.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/point_tensor.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/runtime.hpp"
#include "optim/run/synthesize.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;
using Catch::Contains;

namespace {

json runtime(const json& device) {
  json r = runtime_defaults();
  r["device"] = device;
  return r;
}

// The same as a synthesis reads it (RunSpec::options.runtime).
RuntimeOptions runtime_options(const json& device) {
  RuntimeOptions r;
  r.device = device;
  return r;
}

bool cuda_here() {
  if (torch::cuda::is_available()) return true;
  WARN("skipped: this process sees no CUDA device (torch::cuda::is_available() is false)");
  std::cout << "skipped (no CUDA device): " << Catch::getResultCapture().getCurrentTestName() << "\n";
  return false;
}

// A --quick synthesis of `ex` (the small one-class exemplar by default) through the run
// library, on `device`.
SynthesisResult quick_run(const std::string& device, const std::vector<std::string>& sets = {},
                          const PointSet& ex = test::small_exemplar(1, false)) {
  auto sets_all = sets;
  sets_all.push_back("runtime.device=" + device);
  sets_all.push_back("evaluate=false");
  const json spec = resolve_run_config(json::object(), sets_all);
  SynthesisOptions o;
  o.quick = true;
  return synthesize(ex, spec, o);
}

}  // namespace

TEST_CASE("runtime.device takes cpu, cuda, cuda:N and auto; any other value is an error naming the key", "[optim][device]") {
  for (const char* v : {"cpu", "cuda", "cuda:0", "cuda:12", "auto"}) CHECK_NOTHROW(check_runtime(runtime(v)));
  for (const json& v : {json("gpu"), json("cuda:"), json("cuda:x"), json("CUDA"), json(0), json("cuda:123456"), json("cpu:0")}) {
    INFO(v.dump());
    CHECK_THROWS_WITH(check_runtime(runtime(v)), Contains("runtime.device") && Contains("expected \"cpu\", \"cuda\""));
  }
  // A run config: the defaults, --set reaching the key, and the same refusal at resolution.
  CHECK(resolve_run_config(json::object(), {})["runtime"] == runtime_defaults());
  CHECK(resolve_run_config(json::object(), {"runtime.device=auto"})["runtime"]["device"] == "auto");
  CHECK_THROWS_WITH(resolve_run_config(json::object(), {"runtime.device=gpu"}), Contains("runtime.device"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"runtime", {{"devices", "cpu"}}}}, {}), Contains("runtime.devices"));
  CHECK_THROWS_WITH(resolve_run_config(json{{"runtime", {{"tf32", "yes"}}}}, {}), Contains("runtime.tf32"));
}

TEST_CASE("Without CUDA, cpu and auto run on the CPU and cuda is refused naming the key", "[optim][device]") {
  if (torch::cuda::is_available()) {
    WARN("skipped: this process sees a CUDA device, so cuda is not refused");
    return;
  }
  CHECK(apply_device_settings(runtime_options("cpu")).device == "cpu");
  CHECK(apply_device_settings(runtime_options("auto")).device == "cpu");
  for (const char* v : {"cuda", "cuda:1"})
    CHECK_THROWS_AS(apply_device_settings(runtime_options(v)), InputError);
  CHECK_THROWS_WITH(apply_device_settings(runtime_options("cuda")), Contains("runtime.device") && Contains("\"cuda\" asks for a CUDA device"));
  // synthesize() applies it before the method starts.
  CHECK_THROWS_WITH(quick_run("cuda"), Contains("runtime.device"));
}

TEST_CASE("The method's stats (run.json) record the device, the network's precision and the maps' path", "[optim][device]") {
  const auto r = quick_run("cpu");
  const json& rt = r.stats.at("runtime");
  CHECK(rt.at("device") == "cpu");
  CHECK(rt.at("precision") == "float32");
  CHECK(rt.at("deterministic") == true);
  CHECK(rt.at("gabor_maps") == gabor_maps_path_name(gabor_maps_path(GaborMapsPath::automatic, torch::kCPU)));
  // TF32 is a CUDA mode: on the CPU the float32 network stays float32.
  CHECK(quick_run("cpu", {"runtime.tf32=true"}).stats.at("runtime").at("precision") == "float32");
  if (!cpu_isa().bf16_unavailable)  // else refused: tests/models/test_feature_nets.cpp
    CHECK(quick_run("auto", {"method.feature_net.precision=bfloat16"}).stats.at("runtime").at("precision") == "bfloat16");
  // No Gabor maps, no path to record.
  CHECK_FALSE(quick_run("cpu", {"method.rasterizer.type=pixel_splat"}).stats.at("runtime").contains("gabor_maps"));
}

TEST_CASE("On CUDA, the same config and seed give the same output, twice", "[optim][device][cuda]") {
  if (!cuda_here()) return;
  const auto a = quick_run("cuda"), b = quick_run("cuda");
  CHECK(a.stats.at("runtime").at("device") == "cuda:0");
  CHECK(a.stats.at("runtime").at("gabor_maps") == "tensor_ops");
  CHECK(test::same_bits(a.output, b.output));
}

TEST_CASE("On CUDA, one evaluation's loss and gradient equal the CPU's within float32 rounding", "[optim][device][cuda]") {
  if (!cuda_here()) return;
  RuntimeOptions ieee = runtime_options("cuda");
  ieee.tf32 = false;  // IEEE float32: on a card with TF32 the device would take it
  apply_device_settings(ieee);  // deterministic
  const PointSet ex = test::small_exemplar(1, false);
  json p = test::method_params(json{{"type", "gabor"}, {"jitter", false}});
  p["grid"]["res"] = 32;
  p["feature_net"]["channels"] = 16;
  OutputShape shape;
  shape.upscale = 2;
  const GaborSettings s = resolve_gabor_settings(p, ex, shape, false);
  auto start = positions_tensor(test::small_exemplar(1, false, 64));
  std::vector<double> loss;
  std::vector<torch::Tensor> grad;
  for (const torch::Device device : {torch::Device(torch::kCPU), torch::Device("cuda:0")}) {
    GaborPipeline pipe(s, 9, device);
    pipe.set_targets(positions_tensor(ex), {}, s.sigmas.back());
    auto x = start.detach().to(device).requires_grad_(true);  // a leaf of its own on each device
    auto l = pipe.loss(pipe.features(pipe.output_maps(wrap_unit(x), {}, s.sigmas.back(), {})));
    l.backward();
    loss.push_back(l.item<double>());
    grad.push_back(x.grad().cpu());
  }
  CHECK(loss[1] == Approx(loss[0]).epsilon(1e-4));
  CHECK((grad[1] - grad[0]).abs().max().item<double>() < 1e-3 * grad[0].abs().max().item<double>());
}

// The terms beside the paper's that work window by window (tests/optim/gabor/test_windows.cpp
// checks what they do) build tensors of their own: thresholds, plane distances, a class's
// frozen context points. Each must live on the run's device, in the network's precision.
TEST_CASE("A two-class rectangle output with separation and class_own runs on each device and precision, the same bits twice",
          "[optim][device][cuda]") {
  const PointSet ex = test::small_exemplar(2, false, 25);
  std::vector<std::string> devices = {"cpu"};
  if (torch::cuda::is_available()) devices.push_back("cuda");
  for (const std::string& device : devices) {
    for (const std::string precision : {"float32", "bfloat16"}) {
      // On a CPU without bf16 units bf16 is emulated (about 100 x float32's time) or refused
      // (capped): the point here is the device, so the CPU half takes bf16 only where native.
      if (device == "cpu" && precision == "bfloat16" && !cpu_isa().native_bf16) continue;
      INFO(device << ", " << precision);
      // A window budget below the canvas's grid positions: several windows (one grid would hold it).
      const std::vector<std::string> sets = {"output.size=[3,1]", "method.window.pixels=40", "method.window.margin=0.3", "method.terms.separation.weight=1",
                                             "method.map_terms.class_own.weight=1", "method.feature_net.precision=" + precision,
                                             "runtime.tf32=false"};  // float32 as named, not TF32 where the card has it
      const auto a = quick_run(device, sets, ex), b = quick_run(device, sets, ex);
      CHECK(a.stats.at("runtime").at("device") == (device == "cuda" ? "cuda:0" : "cpu"));
      CHECK(a.stats.at("runtime").at("precision") == precision);
      INFO(a.stats.at("windows").dump());
      CHECK(a.stats.at("windows").at("nx").get<int>() * a.stats.at("windows").at("ny").get<int>() >= 2);
      CHECK(a.stats.at("terms").at("separation").get<double>() == 1.0);
      CHECK(a.stats.at("map_terms").at("class_own").get<double>() == 1.0);
      CHECK(a.output.size() > ex.size());
      CHECK(test::same_bits(a.output, b.output));
    }
  }
  if (devices.size() == 1) cuda_here();  // says the CUDA half was skipped
}
