#pragma once
// The arithmetic of the random-filter network (method.feature_net.precision), chosen for the
// processor at hand:
//   "float32"   the paper's; every processor.
//   "bfloat16"  oneDNN's bf16 convolutions: several times float32's rate on a CPU with bf16
//               units (AVX512_BF16, AMX), but emulated elsewhere, where it is far slower
//               (docs/lab/performance/README.md, "Per machine class"). It runs as asked,
//               with a warning that gives the slowdown measured on this processor; refused
//               where no bf16 convolution can run (an AVX-512 CPU with oneDNN capped below
//               AVX512_CORE: CpuIsa::bf16_unavailable).
//   "auto"      bfloat16 where the device runs it natively, float32 elsewhere: on the CPU,
//               where it has bf16 units that oneDNN may use (core/processor.hpp: the ISA caps
//               count); on a CUDA device, from compute capability 8.0 (bf16 tensor cores).
//               The same config and seed then give one output per processor class; the run
//               records the choice and its reason.
// On a CUDA device "bfloat16" runs as asked: the CPU's units and caps do not concern it.
// The maps, losses and positions stay float32/float64 either way.
#include <torch/torch.h>

#include <string>

#include "models/device_capabilities.hpp"

namespace ppsynth {

struct NetworkPrecision {
  torch::Dtype dtype = torch::kFloat32;
  std::string name = "float32";  // "float32" | "bfloat16": what runs
  std::string reason;            // why, in a sentence (run.json, the log)
};

// `requested` as written in the config, for `device`; errors name `key_path`. A pure function
// of its arguments on a CUDA device (a test hands it one the machine does not have).
NetworkPrecision resolve_network_precision(const std::string& requested, const std::string& key_path,
                                           const DeviceCapabilities& device);
// The same for the synthesis device of this process (synthesis_device(): the CPU unless a
// CUDA synthesis set it).
NetworkPrecision resolve_network_precision(const std::string& requested, const std::string& key_path);

// Seconds of a bf16 channels-last convolution over the same in float32 on this processor,
// measured once per process (well under a second): what the warning and `ppsynth doctor` report.
double measured_bf16_slowdown();

}  // namespace ppsynth
