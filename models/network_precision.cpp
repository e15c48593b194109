#include "models/network_precision.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/error.hpp"
#include "core/processor.hpp"

namespace ppsynth {

namespace {

// The network's dominant operation at a small size: a 64 -> 64 7x7 convolution, channels-last,
// on a 24 x 24 map (0.23 GFLOP): small enough to time at start-up even where bf16 is emulated.
double conv_seconds(torch::Dtype dtype) {
  torch::NoGradGuard ng;
  const auto cl = at::MemoryFormat::ChannelsLast;
  auto w = torch::randn({64, 64, 7, 7}).to(dtype).contiguous(cl);
  auto x = torch::randn({1, 64, 24, 24}).to(dtype).contiguous(cl);
  torch::conv2d(x, w, {}, 1, 3);  // warm-up: oneDNN builds its kernel on the first call
  double best = 1e30;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    torch::conv2d(x, w, {}, 1, 3);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

std::string times(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, x >= 10 ? "%.0f" : "%.2g", x);
  return buf;
}

}  // namespace

double measured_bf16_slowdown() {
  static const double ratio = conv_seconds(torch::kBFloat16) / conv_seconds(torch::kFloat32);
  return ratio;
}

namespace {

// On a CUDA device: bf16 where its tensor cores run it (compute capability 8.0 and later).
NetworkPrecision cuda_precision(const std::string& requested, const std::string& key_path, const DeviceCapabilities& device) {
  NetworkPrecision p;
  if (requested == "float32") {
    p.reason = "float32 as configured";
  } else if (requested == "bfloat16") {
    p.dtype = torch::kBFloat16;
    p.name = "bfloat16";
    p.reason = "bfloat16 as configured";
    if (device.known() && !device.bf16())
      p.reason += "; " + device.describe() + " has no bf16 tensor cores (they start at compute capability 8.0)";
  } else if (requested == "auto") {
    if (device.bf16()) {
      p.dtype = torch::kBFloat16;
      p.name = "bfloat16";
      p.reason = "auto: bfloat16, the CUDA device's bf16 tensor cores (" + device.describe() + ")";
    } else {
      p.reason = "auto: float32, no bf16 tensor cores known on " + device.describe() +
                 " (they start at compute capability 8.0)";
    }
  } else {
    throw config_error(key_path, "expected \"float32\", \"bfloat16\" or \"auto\", got \"" + requested + "\"");
  }
  return p;
}

}  // namespace

NetworkPrecision resolve_network_precision(const std::string& requested, const std::string& key_path) {
  return resolve_network_precision(requested, key_path, synthesis_device().capabilities);
}

NetworkPrecision resolve_network_precision(const std::string& requested, const std::string& key_path,
                                           const DeviceCapabilities& device) {
  if (device.cuda) {
    NetworkPrecision p = cuda_precision(requested, key_path, device);
    static bool logged = false;  // once per process: a run draws a network per class
    if (requested == "auto" && !logged) spdlog::info("{}: {}", key_path, p.reason);
    logged = logged || requested == "auto";
    return p;
  }
  const CpuIsa& cpu = cpu_isa();
  NetworkPrecision p;
  if (requested == "float32") {
    p.reason = "float32 as configured";
  } else if (requested == "bfloat16") {
    if (cpu.bf16_unavailable)
      throw config_error(key_path, "\"bfloat16\" cannot run on this CPU as capped (" + cpu.kind() +
                                       "): LibTorch sends its bf16 convolutions to oneDNN, which has none below "
                                       "AVX512_CORE; lift ONEDNN_MAX_CPU_ISA to AVX512_CORE or above, or use \"float32\" or \"auto\"");
    p.dtype = torch::kBFloat16;
    p.name = "bfloat16";
    p.reason = "bfloat16 as configured";
    if (!cpu.native_bf16) {
      const double slow = measured_bf16_slowdown();
      p.reason += "; this CPU has no bf16 units in use (" + cpu.kind() + "), oneDNN emulates bf16: " + times(slow) +
                  " x float32's time here";
      static bool warned = false;  // once per process: a run draws a network per class
      if (!warned)
        spdlog::warn("{} \"bfloat16\": this CPU has no bf16 units in use ({}), so oneDNN emulates bf16; a convolution "
                     "took {} x its float32 time here. \"auto\" picks the faster precision per processor.",
                     key_path, cpu.kind(), times(slow));
      warned = true;
    }
  } else if (requested == "auto") {
    if (cpu.native_bf16) {
      p.dtype = torch::kBFloat16;
      p.name = "bfloat16";
      p.reason = "auto: bfloat16, the CPU's bf16 units (" + cpu.kind() + ")";
    } else {
      p.reason = "auto: float32, no bf16 units in use on this CPU (" + cpu.kind() + "): oneDNN would emulate bf16";
    }
    static bool logged = false;  // once per process: a run draws a network per class
    if (!logged) spdlog::info("{}: {}", key_path, p.reason);
    logged = true;
  } else {
    throw config_error(key_path, "expected \"float32\", \"bfloat16\" or \"auto\", got \"" + requested + "\"");
  }
  return p;
}

}  // namespace ppsynth
