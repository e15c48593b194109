#pragma once
// The kind of processor a run computes on. LibTorch's oneDNN and OpenBLAS choose their kernels
// by the CPU's instruction set (AMX, AVX-512, AVX2) and each kernel sums in its own order, so
// the same config, seed and thread count give the same bits on one kind of processor and
// another trajectory on another (`lines`, default settings, seed 95: quadrant PCF MSE 0.0097
// on an Intel CPU with AMX, 0.041 on an AMD EPYC with AVX-512; README, "Runs that survive").
// run.json records it, and a resume or a SLURM requeue on another kind says so.
#include <string>

namespace ppsynth {

// "MODEL (ISA)": /proc/cpuinfo's first "model name", and the widest of the instruction sets
// that decide LibTorch's CPU kernels it lists (amx_bf16, avx512_bf16, avx512f, avx2; else
// "baseline"); "unknown" where /proc/cpuinfo cannot be read.
std::string processor_kind();

// The same from the text of a /proc/cpuinfo (tests).
std::string processor_kind_from_cpuinfo(const std::string& cpuinfo);

}  // namespace ppsynth
