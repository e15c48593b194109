#pragma once
// What the device of a synthesis offers, as the settings chosen for it read it: the network's
// precision ("auto", models/network_precision.hpp), TF32 and cuDNN's autotuning
// (optim/run/runtime.hpp), a preset's variant (optim/run/presets.hpp) and how many runs share
// a card (experiments/execute/sweep_executors.hpp). Those choices are pure functions of this
// value, so a test can hand them a CUDA device the machine does not have.
#include <cstdint>
#include <string>

namespace ppsynth {

struct DeviceCapabilities {
  bool cuda = false;            // a CUDA device; else the CPU
  std::string name;             // "NVIDIA H200", or the CPU's kind (core/processor.hpp)
  int major = 0, minor = 0;     // CUDA compute capability; 0.0 where it could not be read
  double memory_bytes = 0;      // CUDA: the card's memory; 0 where unknown (and on the CPU)
  bool cpu_bf16_units = false;  // CPU: oneDNN runs bf16 on bf16 units (AVX512_BF16, AMX), not emulated

  bool known() const { return !cuda || major > 0; }
  // bf16 and TF32 tensor cores arrived with compute capability 8.0 (Ampere); below it cuDNN
  // emulates bf16 or refuses it, and TF32 does not exist.
  bool bf16() const { return cuda ? major >= 8 : cpu_bf16_units; }
  bool tf32() const { return cuda && major >= 8; }
  // "NVIDIA H200, compute capability 9.0" / the CPU's kind; what the reasons in run.json name.
  std::string describe() const;
};

// This process's CPU (core/processor.hpp's reading of it).
DeviceCapabilities cpu_capabilities();
// CUDA device `index` as this process numbers them (CUDA_VISIBLE_DEVICES applies), read from
// the driver (libcuda.so.1, loaded at run time, so a build without CUDA has the same code).
// Where the driver cannot be read: cuda = true with the capability unknown (0.0), so that a
// choice that needs it takes the conservative branch and says why.
DeviceCapabilities cuda_capabilities(int index);

// The device the synthesis of this process runs on, with the choices made for it (a JSON
// text: run.json's runtime.choices): set by apply_device_settings (optim/run/runtime.hpp) before
// the method builds anything; the CPU until then. "auto" precision reads it.
struct SynthesisDevice {
  DeviceCapabilities capabilities;
  std::string choices = "{}";  // a JSON object; {} on the CPU
};
void set_synthesis_device(const SynthesisDevice& device);
SynthesisDevice synthesis_device();

}  // namespace ppsynth
