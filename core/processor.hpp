#pragma once
// The kind of processor a run computes on. LibTorch's oneDNN and OpenBLAS choose their kernels
// by the CPU's instruction set (AMX, AVX-512, AVX2) and each kernel sums in its own order, so
// the same config, seed and thread count give the same bits on one kind of processor and
// another trajectory on another. run.json records the kind, and a resume or a SLURM requeue
// on another kind says so.
//
// Two environment variables cap the instruction set LibTorch uses below what the CPU has, so
// that one machine can run as another class would (the test suite runs its ISA-sensitive
// cases both ways, scripts/test.sh):
//   ONEDNN_MAX_CPU_ISA (or DNNL_MAX_CPU_ISA)  oneDNN's convolutions: AVX2, AVX512_CORE, ...
//   ATEN_CPU_CAPABILITY                       ATen's vectorized kernels: default, avx2, avx512
// Both are read by the libraries once, at their first use; the kind below includes them.
#include <functional>
#include <string>

namespace ppsynth {

struct CpuIsa {
  std::string model;        // /proc/cpuinfo's first "model name"; "" if none
  std::string widest;       // the widest of amx_bf16, avx512_bf16, avx512f, avx2 the CPU lists; "baseline"; "" if unreadable
  std::string onednn_cap;   // ONEDNN_MAX_CPU_ISA (or DNNL_MAX_CPU_ISA) as set, upper case; "" if unset
  std::string aten_cap;     // ATEN_CPU_CAPABILITY as set, lower case; "" if unset
  std::string effective;    // what oneDNN may use: `widest` lowered to the cap (avx2 under ONEDNN_MAX_CPU_ISA=AVX2)
  bool native_bf16 = false; // oneDNN runs bf16 convolutions on bf16 units (AVX512_BF16 or AMX), not emulated
  // No bf16 convolution can run: LibTorch sends them to oneDNN on any CPU with AVX-512 (its own
  // check reads the CPU, not the cap), and oneDNN capped below AVX512_CORE has no bf16 kernel,
  // so each throws "could not create a primitive descriptor iterator". An AVX2 CPU runs them
  // (LibTorch's emulation, far slower); an AVX-512 CPU under ONEDNN_MAX_CPU_ISA=AVX2 cannot.
  bool bf16_unavailable = false;

  // "MODEL (ISA)", with the caps where they lower it: "MODEL (avx512_bf16 capped to avx2 by
  // ONEDNN_MAX_CPU_ISA=AVX2)"; "unknown" where /proc/cpuinfo cannot be read.
  std::string kind() const;
};

// This process's CPU, read once.
const CpuIsa& cpu_isa();
// The same from the text of a /proc/cpuinfo and an environment lookup (tests).
CpuIsa cpu_isa_from(const std::string& cpuinfo, const std::function<std::string(const char*)>& getenv);

// cpu_isa().kind(): what run.json records.
std::string processor_kind();

}  // namespace ppsynth
