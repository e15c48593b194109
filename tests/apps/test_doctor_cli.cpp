// `ppsynth doctor` and what a run records of its processor: the ISA class and its caps, native
// or emulated bf16, the BLAS, both floors, the precision each preset takes here; and run.json
// names the preset variant and the network precision chosen, with the reason.
// No assertion on time: only that the figures exist and agree with the library's view.
#include <catch2/catch.hpp>

#include <fstream>

#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using ppsynth::json;

namespace {
json read_json(const std::filesystem::path& f) {
  std::ifstream in(f);
  return json::parse(in);
}
}  // namespace

TEST_CASE("doctor says what the machine is: ISA, bf16, threads, BLAS, floors, each preset's precision", "[apps][doctor]") {
  const auto d = ppsynth::test::scratch_dir("cli_doctor");
  const auto r = ppsynth::test::run_ppsynth("-q doctor --grid 16 --reps 1 --json " + (d / "m.json").string());
  REQUIRE(r.status == 0);
  CHECK(r.output.find("processor:") != std::string::npos);
  const json m = read_json(d / "m.json");
  CHECK(m["processor"] == ppsynth::processor_kind());
  CHECK(m["native_bf16"] == ppsynth::cpu_isa().native_bf16);
  CHECK(m["threads"].get<int>() >= 1);
  CHECK_FALSE(m["blas"].get<std::string>().empty());
  CHECK(m["conv_gflops"]["float32"].get<double>() > 0);
  if (ppsynth::cpu_isa().bf16_unavailable)  // an AVX-512 CPU under the AVX2 cap: no bf16 convolution runs
  {
    CHECK_FALSE(m["conv_gflops"].contains("bfloat16 channels-last"));
    CHECK(r.output.find("bf16 / float32") == std::string::npos);
  }
  else
    CHECK(m["conv_gflops"]["bfloat16 channels-last"].get<double>() > 0);
  CHECK(m["presets"]["default"]["precision"] == "float32");
  CHECK(m["presets"]["fast"]["precision"] == (ppsynth::cpu_isa().native_bf16 ? "bfloat16" : "float32"));
  // The filters too: fewer where bf16 is emulated, for one class and for several.
  CHECK(m["presets"]["default"]["filters"] == ppsynth::json{{"one_class", 120}, {"several_classes", 120}});
  CHECK(m["presets"]["fast"]["filters"]["one_class"] == (ppsynth::cpu_isa().native_bf16 ? 120 : 64));
  CHECK(m["presets"]["fast"]["filters"]["several_classes"] == (ppsynth::cpu_isa().native_bf16 ? 120 : 64));

  // The caps of another class are read and named (core/processor.hpp); SSE4.1 is below every
  // x86-64 processor this runs on, so the kind always changes.
  const auto capped = ppsynth::test::run_ppsynth("-q doctor --grid 0", "ONEDNN_MAX_CPU_ISA=SSE41");
  REQUIRE(capped.status == 0);
  CHECK(capped.output.find("capped: oneDNN to baseline by ONEDNN_MAX_CPU_ISA=SSE41") != std::string::npos);
  CHECK(capped.output.find("fast       float32") != std::string::npos);  // no bf16 units in use below them
  CHECK(ppsynth::test::run_ppsynth("-q doctor --grid -1").status != 0);
}

TEST_CASE("run.json records the preset's variant and the network precision chosen, with the reason", "[apps][doctor][preset]") {
  const auto d = ppsynth::test::scratch_dir("cli_doctor_run");
  const std::string lines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
  const auto r = ppsynth::test::run_ppsynth("-q synthesize " + lines + " --quick --preset fast -o " + (d / "fast").string());
  REQUIRE(r.status == 0);
  const json run = read_json(d / "fast" / "run.json");
  CHECK(run["preset"]["name"] == "fast");
  CHECK(run["preset"]["variant"] == (ppsynth::cpu_isa().native_bf16 ? "every processor" : "without bf16 units"));
  const json net = run["method_stats"]["resolved"]["feature_net"];
  CHECK(net["precision"] == (ppsynth::cpu_isa().native_bf16 ? "bfloat16" : "float32"));
  CHECK(net["precision_reason"].get<std::string>().rfind("auto: ", 0) == 0);
  // the config keeps what was asked: "auto" resolves per processor class
  CHECK(read_json(d / "fast" / "config.json")["method"]["feature_net"]["precision"] == "auto");
}
