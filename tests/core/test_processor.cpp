// The processor a run records (core/processor.hpp): its model, the widest instruction set
// that decides LibTorch's kernels, read from /proc/cpuinfo, and the caps that lower it.
#include <catch2/catch.hpp>

#include <map>

#include "core/processor.hpp"

using namespace ppsynth;

namespace {
auto env(std::map<std::string, std::string> vars) {
  return [vars](const char* name) {
    auto it = vars.find(name);
    return it == vars.end() ? std::string() : it->second;
  };
}
const std::string amd = "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC\n"
                        "flags\t\t: fpu sse avx avx2 avx512f avx512_bf16 avx512bw\n\nprocessor\t: 1\nmodel name\t: other\n";
const std::string intel = "model name\t: Intel(R) Xeon(R) Platinum 8488C\nflags\t\t: avx2 avx512f avx512_bf16 amx_bf16 amx_tile\n";
const std::string avx2 = "model name\t: AMD EPYC 7R13\nflags\t\t: fpu sse avx avx2 fma\n";
std::string kind(const std::string& cpuinfo, std::map<std::string, std::string> vars = {}) {
  return cpu_isa_from(cpuinfo, env(vars)).kind();
}
}  // namespace

TEST_CASE("the processor kind: the model and the widest instruction set of the kernels", "[core][processor]") {
  CHECK(kind(amd) == "AMD EPYC (avx512_bf16)");
  CHECK(kind(intel) == "Intel(R) Xeon(R) Platinum 8488C (amx_bf16)");
  // a flag that only begins like one of the sets is not it
  CHECK(kind("model name : old\nflags : sse2 avx avx2x\n") == "old (baseline)");
  CHECK(kind("flags : avx2\n") == "unknown model (avx2)");
  CHECK(kind("") == "unknown");
  CHECK(kind("no colon here\n") == "unknown");
  CHECK(kind("processor : 0\nFeatures : fp asimd bf16\n") == "unknown model (baseline)");  // arm64
  CHECK_FALSE(processor_kind().empty());
}

TEST_CASE("bf16 unavailable: an AVX-512 CPU with oneDNN capped below AVX512_CORE, and only there", "[core][processor]") {
  // LibTorch 1.13 sends bf16 convolutions to oneDNN by the CPU's flags; oneDNN under the cap
  // has no bf16 kernel for them (measured on a Xeon with AMX: "could not create a primitive
  // descriptor iterator" under ONEDNN_MAX_CPU_ISA=AVX2; under AVX512_CORE they ran).
  const auto avx2_cap = env({{"ONEDNN_MAX_CPU_ISA", "AVX2"}});
  CHECK(cpu_isa_from(amd, avx2_cap).bf16_unavailable);
  CHECK(cpu_isa_from(intel, avx2_cap).bf16_unavailable);
  CHECK(cpu_isa_from("model name : x\nflags : avx2 avx512f avx512bw\n", avx2_cap).bf16_unavailable);
  CHECK_FALSE(cpu_isa_from(intel, env({{"ONEDNN_MAX_CPU_ISA", "AVX512_CORE"}})).bf16_unavailable);  // emulated there
  CHECK_FALSE(cpu_isa_from(intel, env({})).bf16_unavailable);
  CHECK_FALSE(cpu_isa_from(avx2, env({})).bf16_unavailable);  // an AVX2 CPU emulates bf16: slow, but it runs
  CHECK_FALSE(cpu_isa_from(avx2, avx2_cap).bf16_unavailable);
  CHECK_FALSE(cpu_isa_from("", avx2_cap).bf16_unavailable);
}

TEST_CASE("native bf16: the CPU's bf16 units, unless oneDNN is capped below them", "[core][processor]") {
  CHECK(cpu_isa_from(amd, env({})).native_bf16);
  CHECK(cpu_isa_from(intel, env({})).native_bf16);
  CHECK_FALSE(cpu_isa_from(avx2, env({})).native_bf16);
  CHECK_FALSE(cpu_isa_from("model name : x\nflags : avx2 avx512f avx512bw\n", env({})).native_bf16);  // AVX-512 without bf16
  CHECK_FALSE(cpu_isa_from("", env({})).native_bf16);

  // The AVX2 class on an AVX512_BF16 machine: the caps the test suite and bench use.
  const CpuIsa capped = cpu_isa_from(amd, env({{"ONEDNN_MAX_CPU_ISA", "AVX2"}, {"ATEN_CPU_CAPABILITY", "avx2"}}));
  CHECK(capped.effective == "avx2");
  CHECK_FALSE(capped.native_bf16);
  CHECK(capped.kind() == "AMD EPYC (avx512_bf16, capped: oneDNN to avx2 by ONEDNN_MAX_CPU_ISA=AVX2; ATen to avx2 by ATEN_CPU_CAPABILITY)");
  // the older name, lower case as oneDNN accepts it
  CHECK(cpu_isa_from(intel, env({{"DNNL_MAX_CPU_ISA", "avx512_core"}})).effective == "avx512f");
  CHECK(cpu_isa_from(intel, env({{"ONEDNN_MAX_CPU_ISA", "AVX512_CORE_BF16"}})).native_bf16);
  // a cap at or above what the CPU has changes nothing: the same kind, the same trajectories
  CHECK(kind(avx2, {{"ONEDNN_MAX_CPU_ISA", "AVX2"}, {"ATEN_CPU_CAPABILITY", "avx2"}}) == "AMD EPYC 7R13 (avx2)");
  CHECK(kind(avx2, {{"ONEDNN_MAX_CPU_ISA", "ALL"}}) == "AMD EPYC 7R13 (avx2)");
  // a name oneDNN does not know is ignored by it, and so here
  CHECK(kind(amd, {{"ONEDNN_MAX_CPU_ISA", "AVX3000"}}) == "AMD EPYC (avx512_bf16)");
  CHECK(kind(avx2, {{"ATEN_CPU_CAPABILITY", "default"}}) == "AMD EPYC 7R13 (avx2, capped: ATen to default by ATEN_CPU_CAPABILITY)");
}
