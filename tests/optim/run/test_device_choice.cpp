// The device decides: "auto" precision, TF32, cuDNN autotuning and the fast preset's
// variant are pure functions of a DeviceCapabilities value (models/device_capabilities.hpp),
// so a fake CUDA card checks them on a machine without one. The CPU's choices are unchanged.
#include <catch2/catch.hpp>

#include <torch/cuda.h>

#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "models/network_precision.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/runtime.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

namespace {

DeviceCapabilities card(int major, int minor, const std::string& name) {
  DeviceCapabilities c;
  c.cuda = true;
  c.name = name;
  c.major = major;
  c.minor = minor;
  c.memory_bytes = 80.0 * (1 << 30);
  return c;
}

const std::string key = "method.feature_net.precision";

}  // namespace

TEST_CASE("auto precision on a CUDA card: bfloat16 from compute capability 8.0, float32 below or unknown", "[device_choice]") {
  const NetworkPrecision h200 = resolve_network_precision("auto", key, card(9, 0, "NVIDIA H200"));
  CHECK(h200.name == "bfloat16");
  CHECK(h200.dtype == torch::kBFloat16);
  CHECK_THAT(h200.reason, Contains("auto: bfloat16") && Contains("NVIDIA H200, compute capability 9.0"));
  CHECK(resolve_network_precision("auto", key, card(8, 0, "NVIDIA A100")).name == "bfloat16");
  const NetworkPrecision v100 = resolve_network_precision("auto", key, card(7, 0, "Tesla V100"));
  CHECK(v100.name == "float32");
  CHECK_THAT(v100.reason, Contains("no bf16 tensor cores") && Contains("7.0"));
  const NetworkPrecision unknown = resolve_network_precision("auto", key, card(0, 0, "cuda:0"));
  CHECK(unknown.name == "float32");
  CHECK_THAT(unknown.reason, Contains("unknown"));
  // As configured, whatever the host CPU's bf16 units or caps (they do not run it).
  CHECK(resolve_network_precision("bfloat16", key, card(9, 0, "x")).name == "bfloat16");
  CHECK(resolve_network_precision("float32", key, card(9, 0, "x")).name == "float32");
  CHECK_THROWS_WITH(resolve_network_precision("half", key, card(9, 0, "x")), Contains(key));
}

TEST_CASE("On the CPU, auto precision is the CPU's choice as before", "[device_choice]") {
  const NetworkPrecision p = resolve_network_precision("auto", key, cpu_capabilities());
  CHECK(p.name == (cpu_isa().native_bf16 ? "bfloat16" : "float32"));
  CHECK(p.reason.rfind("auto: ", 0) == 0);
  CHECK(resolve_network_precision("auto", key).name == p.name);  // no CUDA synthesis in this process: the CPU
}

TEST_CASE("TF32 follows the card unless configured; cuDNN autotunes exactly when runtime.deterministic is false", "[device_choice]") {
  const DeviceCapabilities h200 = card(9, 0, "NVIDIA H200"), v100 = card(7, 0, "Tesla V100");
  for (const nlohmann::json& automatic : {nlohmann::json(nullptr), nlohmann::json("auto")}) {
    const DeviceDecision d = decide_device_settings(h200, automatic, true);
    CHECK(d.tf32);
    CHECK_FALSE(d.autotune);  // deterministic: the same bits on every run
    CHECK_THAT(d.tf32_reason, Contains("TF32 tensor cores of NVIDIA H200"));
    CHECK_THAT(d.autotune_reason, Contains("deterministic"));
    CHECK(decide_device_settings(h200, automatic, false).autotune);
    CHECK_FALSE(decide_device_settings(v100, automatic, true).tf32);
  }
  CHECK_FALSE(decide_device_settings(h200, false, false).tf32);
  CHECK(decide_device_settings(v100, true, true).tf32);  // as configured
  // The CPU: neither, whatever is asked.
  const DeviceDecision cpu = decide_device_settings(cpu_capabilities(), true, false);
  CHECK_FALSE(cpu.tf32);
  CHECK_FALSE(cpu.autotune);
  const nlohmann::json record = decide_device_settings(h200, nullptr, true).record(h200);
  CHECK(record["tf32"] == true);
  CHECK(record["cudnn_autotune"] == false);
  CHECK(record["memory_mib"] == 80 * 1024);
  CHECK(record.contains("tf32_reason"));
  CHECK(record.contains("cudnn_autotune_reason"));
}

TEST_CASE("runtime.tf32 takes true, false, null or auto (null by default); anything else names the key", "[device_choice]") {
  CHECK(runtime_defaults()["tf32"].is_null());
  for (const char* v : {"runtime.tf32=true", "runtime.tf32=false", "runtime.tf32=auto"})
    CHECK_NOTHROW(resolve_run_config(nlohmann::json::object(), {v}));
  CHECK_THROWS_WITH(resolve_run_config(nlohmann::json{{"runtime", {{"tf32", "yes"}}}}, {}), Contains("runtime.tf32"));
  CHECK_THROWS_WITH(resolve_run_config(nlohmann::json{{"runtime", {{"deterministic", "yes"}}}}, {}), Contains("runtime.deterministic"));
}

TEST_CASE("The fast preset's variant follows the run's device, not the host CPU, when the device is CUDA", "[device_choice]") {
  if (torch::cuda::is_available()) {
    WARN("skipped: this process sees a CUDA device (the check below needs one it cannot see)");
    return;
  }
  // A CUDA device this process cannot see: its capability is unknown, so the float32 variant
  // (whatever the host CPU's bf16 units), and the record says why.
  const nlohmann::json r = resolve_run_config(nlohmann::json{{"preset", "fast"}}, {"runtime.device=cuda"});
  CHECK(r["method"]["feature_net"]["channels"] == 64);  // the float32 variant's
  const nlohmann::json record = preset_record(r["preset"], r["runtime"]["device"]);
  CHECK(record["variant"] == "without bf16 units");
  CHECK_THAT(record["reason"].get<std::string>(), Contains("CUDA device"));
  // On the CPU, as before: the CPU's units decide.
  const nlohmann::json on_cpu = resolve_run_config(nlohmann::json{{"preset", "fast"}}, {});
  const nlohmann::json cpu = preset_record(on_cpu["preset"], on_cpu["runtime"]["device"]);
  CHECK(cpu["variant"] == (cpu_isa().native_bf16 ? "every processor" : "without bf16 units"));
  CHECK(capabilities_of_device("cpu").bf16() == cpu_isa().native_bf16);
  CHECK_FALSE(capabilities_of_device("auto").cuda);
  CHECK(capabilities_of_device("cuda:1").cuda);
}
