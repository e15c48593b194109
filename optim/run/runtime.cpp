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

nlohmann::json runtime_defaults() { return {{"device", "cpu"}, {"tf32", false}, {"deterministic", true}}; }

void check_runtime(const nlohmann::json& runtime) { parse_device(runtime.at("device")); }

DeviceSettings apply_device_settings(const nlohmann::json& runtime) {
  const DeviceRequest request = parse_device(runtime.at("device"));
  DeviceSettings s;
  const bool cuda = torch::cuda::is_available();
  if (request.kind == DeviceRequest::Kind::cpu || (request.kind == DeviceRequest::Kind::automatic && !cuda)) return s;
  const std::string asked = "\"" + runtime["device"].get<std::string>() + "\"";
  if (!cuda)
    throw config_error("runtime.device", asked + " asks for a CUDA device, and this process sees none (a LibTorch built "
                                         "without CUDA, as Debian's, or no GPU or driver); use \"cpu\" or \"auto\"");
  const int64_t count = static_cast<int64_t>(torch::cuda::device_count());
  if (request.index >= count)
    throw config_error("runtime.device", asked + ": this process sees " + std::to_string(count) + " CUDA device" +
                                             (count == 1 ? " (cuda:0)" : "s (cuda:0 to cuda:" + std::to_string(count - 1) + ")"));
  s.device = "cuda:" + std::to_string(request.index);
  s.tf32 = runtime.at("tf32").get<bool>();
  s.deterministic = runtime.at("deterministic").get<bool>();
  auto& context = at::globalContext();
  // The legacy switches exist in every LibTorch from 1.13 on (2.9 and later print a notice
  // that finer ones exist); one family only, as mixing them is refused.
  context.setAllowTF32CuBLAS(s.tf32);
  context.setAllowTF32CuDNN(s.tf32);  // LibTorch's default is on: IEEE float32 unless asked
  context.setBenchmarkCuDNN(!s.deterministic);
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
