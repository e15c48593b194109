#include "optim/run/runtime.hpp"

#include <cstdlib>
#include <limits>
#include <string>
#include <thread>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#ifdef __linux__
#include <sched.h>
#endif

#include <ATen/Context.h>
#include <torch/cuda.h>
#include <torch/torch.h>

#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "models/gabor_feature_maps.hpp"

namespace ppsynth {

namespace {

// Keeping freed memory on the heap spares every iteration the page faults of its large
// activation buffers, at the price of resident memory held until the process ends (how much
// of each: docs/lab/performance/README.md, "Per phase", step 3, and "512 x 512 output grid").
bool keep_freed_memory() {
#ifdef __GLIBC__
  static const bool applied = [] {
    const char* env = std::getenv("PPSYNTH_MALLOC");
    if (env && std::string(env) == "system") return false;
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
    mallopt(M_TOP_PAD, 64 << 20);
    return true;
  }();
  return applied;
#else
  return false;
#endif
}

}  // namespace

int threads_from_environment() {
  const char* env = std::getenv("PPSYNTH_THREADS");
  if (!env) return 0;
  char* end = nullptr;
  const long v = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || v < 1 || v > 1024)
    throw InputError(std::string("PPSYNTH_THREADS='") + env + "': expected a whole number from 1 to 1024");
  return static_cast<int>(v);
}

namespace {

const char* kDeviceChoices = "expected \"cpu\", \"cuda\", \"cuda:N\" or \"auto\"";

// runtime.device parsed: the CPU, a CUDA device (index), or the first CUDA device if any.
struct DeviceRequest {
  enum class Kind { cpu, cuda, automatic } kind = Kind::cpu;
  int index = 0;
};

DeviceRequest parse_device(const nlohmann::json& v) {
  if (!v.is_string()) throw config_error("runtime.device", std::string(kDeviceChoices) + ", got " + v.dump());
  const std::string s = v.get<std::string>();
  if (s == "cpu") return {DeviceRequest::Kind::cpu, 0};
  if (s == "auto") return {DeviceRequest::Kind::automatic, 0};
  if (s == "cuda") return {DeviceRequest::Kind::cuda, 0};
  const std::string digits = s.rfind("cuda:", 0) == 0 ? s.substr(5) : "";
  if (!digits.empty() && digits.size() <= 4 && digits.find_first_not_of("0123456789") == std::string::npos)
    return {DeviceRequest::Kind::cuda, std::stoi(digits)};
  throw config_error("runtime.device", std::string(kDeviceChoices) + ", got \"" + s + "\"");
}

}  // namespace

const ParamTable<RuntimeOptions>& RuntimeOptions::params() {
  using O = RuntimeOptions;
  static const ParamTable<O> t("runtime", {
      param("device", &O::device, "", "cpu, cuda, cuda:N, or auto (the first CUDA device this process sees, else the CPU)"),
      param("tf32", &O::tf32, "", "CUDA only: TF32 tensor cores for float32 (null or \"auto\": the device decides)"),
      param("deterministic", &O::deterministic, "", "CUDA only: deterministic algorithms, no autotuning (the same bits every run)"),
  });
  return t;
}

nlohmann::json runtime_defaults() { return RuntimeOptions::params().defaults(); }

void check_runtime(const nlohmann::json& runtime) {
  parse_device(runtime.at("device"));
  const auto& tf32 = runtime.at("tf32");
  if (!tf32.is_boolean() && !tf32.is_null() && tf32 != "auto")
    throw config_error("runtime.tf32", "expected true, false, or null or \"auto\" (the device decides), got " + tf32.dump());
  if (!runtime.at("deterministic").is_boolean())
    throw config_error("runtime.deterministic", "expected true or false, got " + runtime["deterministic"].dump());
}

DeviceCapabilities capabilities_of_device(const nlohmann::json& device) {
  const DeviceRequest request = parse_device(device);
  if (request.kind == DeviceRequest::Kind::cpu) return cpu_capabilities();
  if (!torch::cuda::is_available()) {
    if (request.kind == DeviceRequest::Kind::automatic) return cpu_capabilities();
    DeviceCapabilities unseen;
    unseen.cuda = true;
    unseen.name = device.get<std::string>() + " (not visible to this process)";
    return unseen;
  }
  return cuda_capabilities(request.index);
}

DeviceDecision decide_device_settings(const DeviceCapabilities& device, const nlohmann::json& tf32, bool deterministic) {
  DeviceDecision d;
  if (!device.cuda) {
    d.tf32_reason = "the CPU: no TF32";
    d.autotune_reason = "the CPU: no cuDNN";
    return d;
  }
  if (tf32.is_null() || tf32 == "auto") {
    d.tf32 = device.tf32();
    d.tf32_reason = d.tf32 ? "auto: the TF32 tensor cores of " + device.describe()
                           : "auto: no TF32 tensor cores known on " + device.describe() + " (they start at compute capability 8.0)";
  } else {
    d.tf32 = tf32.get<bool>();
    d.tf32_reason = std::string(d.tf32 ? "on" : "off") + " as configured (runtime.tf32)";
  }
  d.autotune = !deterministic;
  d.autotune_reason = deterministic ? "off: runtime.deterministic asks for the same bits on every run, and autotuning "
                                      "may pick another algorithm each time"
                                    : "on: runtime.deterministic is false, so cuDNN times its algorithms and keeps the fastest";
  return d;
}

nlohmann::json DeviceDecision::record(const DeviceCapabilities& device) const {
  nlohmann::json r = {{"device", device.describe()},
                      {"tf32", tf32},
                      {"tf32_reason", tf32_reason},
                      {"cudnn_autotune", autotune},
                      {"cudnn_autotune_reason", autotune_reason}};
  if (device.memory_bytes > 0) r["memory_mib"] = static_cast<int64_t>(device.memory_bytes / (1 << 20));
  return r;
}

DeviceSettings apply_device_settings(const RuntimeOptions& runtime) {
  const DeviceRequest request = parse_device(runtime.device);
  DeviceSettings s;
  const bool cuda = torch::cuda::is_available();
  if (request.kind == DeviceRequest::Kind::cpu || (request.kind == DeviceRequest::Kind::automatic && !cuda)) {
    set_synthesis_device({cpu_capabilities(), "{}"});
    return s;
  }
  const std::string asked = "\"" + runtime.device.get<std::string>() + "\"";
  if (!cuda)
    throw config_error("runtime.device", asked + " asks for a CUDA device, and this process sees none (a LibTorch built "
                                         "without CUDA, as Debian's, or no GPU or driver); use \"cpu\" or \"auto\"");
  const int64_t count = static_cast<int64_t>(torch::cuda::device_count());
  if (request.index >= count)
    throw config_error("runtime.device", asked + ": this process sees " + std::to_string(count) + " CUDA device" +
                                             (count == 1 ? " (cuda:0)" : "s (cuda:0 to cuda:" + std::to_string(count - 1) + ")"));
  s.device = "cuda:" + std::to_string(request.index);
  check_runtime(RuntimeOptions::params().to_json(runtime));  // tf32's values, as a config's are checked
  s.deterministic = runtime.deterministic;
  const DeviceCapabilities caps = cuda_capabilities(request.index);
  const DeviceDecision decision = decide_device_settings(caps, runtime.tf32, s.deterministic);
  s.tf32 = decision.tf32;
  set_synthesis_device({caps, decision.record(caps).dump()});
  auto& context = at::globalContext();
  // The legacy switches exist in every LibTorch from 1.13 on (2.9 and later print a notice
  // that finer ones exist); one family only, as mixing them is refused.
  context.setAllowTF32CuBLAS(s.tf32);
  context.setAllowTF32CuDNN(s.tf32);  // set either way: LibTorch's default is on
  context.setBenchmarkCuDNN(decision.autotune);
  context.setDeterministicCuDNN(s.deterministic);
  // cuBLAS is deterministic with a fixed workspace, read when its first handle is made; a
  // value the user set stays.
  if (s.deterministic) setenv("CUBLAS_WORKSPACE_CONFIG", ":4096:8", 0);
  // An operation without a deterministic CUDA algorithm warns (naming itself) instead of
  // failing the run.
  context.setDeterministicAlgorithms(s.deterministic, /*warn_only=*/true);
  return s;
}

int usable_cores() {
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
#endif
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void check_runtime_environment() {
  threads_from_environment();
  gabor_maps_tensor_ops_forced();
}

RuntimeSettings configure_runtime() {
  check_runtime_environment();  // every variable checked before any is applied
  RuntimeSettings s;
  const int cores = usable_cores();
  s.threads = threads_from_environment();
  // Warned, not refused: a user may mean to oversubscribe (a SLURM job or container whose
  // affinity mask is narrower than what it may use, a measurement of the effect), and no bound
  // fits every machine; what must not happen is a slowdown nobody is told about.
  if (s.threads > cores)
    spdlog::warn("PPSYNTH_THREADS={} is more than the {} core{} this process may run on: the threads take turns on "
                 "them and a synthesis can run many times slower; set PPSYNTH_THREADS={} or fewer unless you mean to "
                 "oversubscribe",
                 s.threads, cores, cores == 1 ? "" : "s", cores);
  if (s.threads == 0) s.threads = cores;
  torch::set_num_threads(s.threads);
  s.keeps_freed_memory = keep_freed_memory();
  return s;
}

}  // namespace ppsynth
