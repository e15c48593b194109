#pragma once
// What this machine gives a synthesis, in one place: the processor class and the ISA caps in
// effect, whether bf16 is native or emulated, threads, the BLAS library this process loaded,
// the network's convolution floor in float32 and in bf16, and the precision each preset takes
// here. `ppsynth doctor` prints it; `ppsynth bench` heads its figures with it.
#include <string>
#include <vector>

#include <c10/core/Device.h>
#include <nlohmann/json.hpp>

namespace ppsynth {

// The throughput of the network's dominant operation, a 120 -> 120 7x7 convolution on an
// R x R map: float32 as the default network lays it out, bfloat16 channels-last as the bf16
// network's fast path. On a CUDA device the time runs to the end of the queued work.
struct ConvThroughput {
  std::string path;  // "float32" | "bfloat16 channels-last"
  double gflops = 0, min_s = 0;
};
ConvThroughput conv_throughput_float32(int res, int reps, const c10::Device& device = c10::Device(c10::kCPU));
ConvThroughput conv_throughput_bfloat16(int res, int reps, const c10::Device& device = c10::Device(c10::kCPU));

struct PresetPrecision {
  std::string preset, precision, reason;
  int filters_one_class = 120, filters_several_classes = 120;  // the random network's, here
};

struct MachineReport {
  std::string processor;  // core/processor.hpp's kind, caps included
  std::string effective_isa;
  bool native_bf16 = false;
  int threads = 0, interop_threads = 0;
  std::string blas;  // the BLAS library mapped into this process, and what it is
  std::vector<ConvThroughput> floors;  // float32, then bfloat16 (empty: not measured)
  int floor_res = 0;
  std::vector<PresetPrecision> presets;  // "default" and every named preset

  nlohmann::json to_json() const;
  std::string text() const;  // lines for a terminal
};

// `floor_res` > 0 measures both floors at that grid (`reps` repetitions, the minimum kept);
// 0 leaves them out.
MachineReport machine_report(int floor_res, int reps);

// The BLAS library among the shared objects of this process (/proc/self/maps), named:
// "OpenBLAS (pthread): PATH", "reference BLAS (slow): PATH", ...; "none loaded" if none.
std::string loaded_blas();

}  // namespace ppsynth
