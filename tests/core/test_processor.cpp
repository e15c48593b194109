// The processor a run records (core/processor.hpp): its model and the widest instruction set
// that decides LibTorch's kernels, read from /proc/cpuinfo.
#include <catch2/catch.hpp>

#include "core/processor.hpp"

using namespace ppsynth;

TEST_CASE("the processor kind: the model and the widest instruction set of the kernels", "[core][processor]") {
  const std::string amd = "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC\n"
                          "flags\t\t: fpu sse avx avx2 avx512f avx512_bf16 avx512bw\n\nprocessor\t: 1\nmodel name\t: other\n";
  CHECK(processor_kind_from_cpuinfo(amd) == "AMD EPYC (avx512_bf16)");
  const std::string intel = "model name\t: Intel(R) Xeon(R) Platinum 8488C\nflags\t\t: avx2 avx512f avx512_bf16 amx_bf16 amx_tile\n";
  CHECK(processor_kind_from_cpuinfo(intel) == "Intel(R) Xeon(R) Platinum 8488C (amx_bf16)");
  // a flag that only begins like one of the sets is not it
  CHECK(processor_kind_from_cpuinfo("model name : old\nflags : sse2 avx avx2x\n") == "old (baseline)");
  CHECK(processor_kind_from_cpuinfo("flags : avx2\n") == "unknown model (avx2)");
  CHECK(processor_kind_from_cpuinfo("") == "unknown");
  CHECK(processor_kind_from_cpuinfo("no colon here\n") == "unknown");
  CHECK_FALSE(processor_kind().empty());
}
