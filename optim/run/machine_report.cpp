#include "optim/run/machine_report.hpp"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "models/network_precision.hpp"
#include "models/feature_net.hpp"
#include "optim/run/presets.hpp"

namespace ppsynth {

namespace {

ConvThroughput conv_throughput(const std::string& path, torch::Dtype dtype, bool channels_last, int R, int reps,
                               const c10::Device& device) {
  torch::NoGradGuard ng;
  auto wait = [&] {
    if (device.is_cuda()) torch::cuda::synchronize(device.index() < 0 ? -1 : device.index());
  };
  const auto layout = channels_last ? at::MemoryFormat::ChannelsLast : at::MemoryFormat::Contiguous;
  auto w = torch::randn({120, 120, 7, 7}).to(device, dtype).contiguous(layout);
  auto x = torch::randn({1, 120, R, R}).to(device, dtype).contiguous(layout);
  torch::conv2d(x, w, {}, 1, 3);  // warm-up: oneDNN builds its kernel on the first call
  wait();
  double best = 1e30;
  for (int r = 0; r < std::max(1, reps); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    torch::conv2d(x, w, {}, 1, 3);
    wait();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return {path, 2.0 * 120 * 120 * 49 * double(R) * R / best / 1e9, best};
}

}  // namespace

ConvThroughput conv_throughput_float32(int res, int reps, const c10::Device& device) {
  return conv_throughput("float32", torch::kFloat32, false, res, reps, device);
}
ConvThroughput conv_throughput_bfloat16(int res, int reps, const c10::Device& device) {
  return conv_throughput("bfloat16 channels-last", torch::kBFloat16, true, res, reps, device);
}

std::string loaded_blas() {
  std::ifstream maps("/proc/self/maps");
  std::vector<std::string> found;
  for (std::string line; std::getline(maps, line);) {
    const auto slash = line.find('/');
    if (slash == std::string::npos) continue;
    const std::string path = line.substr(slash);
    const std::string file = path.substr(path.find_last_of('/') + 1);
    const bool blas = file.find("blas") != std::string::npos || file.find("libmkl") != std::string::npos ||
                      file.find("libblis") != std::string::npos;
    if (blas && std::find(found.begin(), found.end(), path) == found.end()) found.push_back(path);
  }
  if (found.empty()) return "none loaded";
  std::string out, seen;
  for (const auto& path : found) {
    std::string what = "BLAS";
    if (path.find("openblas-pthread") != std::string::npos) what = "OpenBLAS (pthread)";
    else if (path.find("openblas-openmp") != std::string::npos) what = "OpenBLAS (OpenMP)";
    else if (path.find("openblas") != std::string::npos) what = "OpenBLAS";
    else if (path.find("mkl") != std::string::npos) what = "MKL";
    else if (path.find("blis") != std::string::npos) what = "BLIS";
    else if (path.find("/blas/") != std::string::npos) what = "reference BLAS (slow: install libopenblas0-pthread)";
    if (seen.find("|" + what + "|") != std::string::npos) continue;  // Debian's libblas.so.3 alternative beside the library it points to
    seen += "|" + what + "|";
    out += (out.empty() ? "" : "; ") + what + ": " + path;
  }
  return out;
}

MachineReport machine_report(int floor_res, int reps) {
  MachineReport m;
  const CpuIsa& cpu = cpu_isa();
  m.processor = cpu.kind();
  m.effective_isa = cpu.effective.empty() ? "unknown" : cpu.effective;
  m.native_bf16 = cpu.native_bf16;
  m.threads = at::get_num_threads();
  m.interop_threads = at::get_num_interop_threads();
  m.blas = loaded_blas();
  if (floor_res > 0) {
    m.floor_res = floor_res;
    m.floors = {conv_throughput_float32(floor_res, reps)};
    if (!cpu.bf16_unavailable) m.floors.push_back(conv_throughput_bfloat16(floor_res, reps));  // else none runs (core/processor.hpp)
  }
  // The network a run takes here (the default's, then each preset's): the preset's fragment
  // over the "random" network's registered defaults, so no default is restated here.
  auto network_of = [](const nlohmann::json& fragment) {
    nlohmann::json net = FeatureNetRegistry::instance().entry("random").defaults;
    if (fragment.contains("method") && fragment["method"].contains("feature_net")) net = merge(net, fragment["method"]["feature_net"]);
    return net;
  };
  auto filters_of = [](const nlohmann::json& net, int classes) {
    return with_channels_for_classes(net, classes, "method.feature_net")["channels"].get<int>();
  };
  auto add = [&](const std::string& name, const nlohmann::json& fragment) {
    const nlohmann::json net = network_of(fragment);
    const NetworkPrecision p = resolve_network_precision(net["precision"].get<std::string>(), "method.feature_net.precision");
    m.presets.push_back({name, p.name, p.reason, filters_of(net, 1), filters_of(net, 2)});
  };
  add("default", nlohmann::json::object());
  const nlohmann::json all = presets();
  for (auto it = all.begin(); it != all.end(); ++it) add(it.key(), preset_fragment(it.key()));
  return m;
}

nlohmann::json MachineReport::to_json() const {
  nlohmann::json j = {{"processor", processor}, {"effective_isa", effective_isa}, {"native_bf16", native_bf16},
                      {"threads", threads}, {"interop_threads", interop_threads}, {"blas", blas}};
  if (!floors.empty()) {
    j["floor_grid"] = floor_res;
    for (const auto& f : floors) j["conv_gflops"][f.path] = f.gflops;
    if (floors.size() > 1) j["bf16_over_float32"] = floors[1].gflops / floors[0].gflops;  // one floor where no bf16 runs
  }
  for (const auto& p : presets)
    j["presets"][p.preset] = {{"precision", p.precision}, {"reason", p.reason},
                              {"filters", {{"one_class", p.filters_one_class}, {"several_classes", p.filters_several_classes}}}};
  return j;
}

std::string MachineReport::text() const {
  std::string t;
  char buf[512];
  t += "processor:  " + processor + "\n";
  t += "bf16:       " + std::string(native_bf16 ? "native (oneDNN on the CPU's bf16 units)"
                                    : cpu_isa().bf16_unavailable ? "unavailable (oneDNN capped below AVX512_CORE on an AVX-512 CPU)"
                                                                 : "emulated by oneDNN (no bf16 units in use)") + "\n";
  std::snprintf(buf, sizeof buf, "threads:    %d intra-op, %d inter-op (PPSYNTH_THREADS sets the first)\n", threads, interop_threads);
  t += buf;
  t += "BLAS:       " + blas + "\n";
  if (!floors.empty()) {
    std::snprintf(buf, sizeof buf, "convolution 120 -> 120 7x7 at %d x %d:", floor_res, floor_res);
    t += buf;
    for (const auto& f : floors) {
      std::snprintf(buf, sizeof buf, " %s %.1f GFLOP/s;", f.path.c_str(), f.gflops);
      t += buf;
    }
    if (floors.size() > 1) {
      std::snprintf(buf, sizeof buf, " bf16 / float32 %.3g x", floors[1].gflops / floors[0].gflops);
      t += buf;
    }
    t += "\n";
  }
  t += "network per preset here (precision, filters for one class / several):\n";
  for (const auto& p : presets) {
    std::snprintf(buf, sizeof buf, "  %-10s %-9s %3d / %-3d %s\n", p.preset.c_str(), p.precision.c_str(), p.filters_one_class,
                  p.filters_several_classes, p.reason.c_str());
    t += buf;
  }
  return t;
}

}  // namespace ppsynth
