#include "models/device_capabilities.hpp"

#include <dlfcn.h>

#include <mutex>

#include "core/processor.hpp"

namespace ppsynth {

std::string DeviceCapabilities::describe() const {
  if (!cuda) return name;
  const std::string who = name.empty() ? "a CUDA device" : name;
  return major > 0 ? who + ", compute capability " + std::to_string(major) + "." + std::to_string(minor)
                   : who + ", compute capability unknown (libcuda.so.1 could not be read)";
}

DeviceCapabilities cpu_capabilities() {
  DeviceCapabilities c;
  c.name = cpu_isa().kind();
  c.cpu_bf16_units = cpu_isa().native_bf16;
  return c;
}

namespace {

// The driver API's few entry points, by their stable C ABI (cuda.h): CUresult is an int (0:
// success), CUdevice an int, and the attribute numbers are fixed.
using CuInit = int (*)(unsigned);
using CuDeviceGet = int (*)(int*, int);
using CuDeviceGetAttribute = int (*)(int*, int, int);
using CuDeviceGetName = int (*)(char*, int, int);
using CuDeviceTotalMem = int (*)(size_t*, int);
constexpr int kComputeCapabilityMajor = 75;  // CU_DEVICE_ATTRIBUTE_COMPUTE_CAPABILITY_MAJOR
constexpr int kComputeCapabilityMinor = 76;  // CU_DEVICE_ATTRIBUTE_COMPUTE_CAPABILITY_MINOR

}  // namespace

DeviceCapabilities cuda_capabilities(int index) {
  DeviceCapabilities c;
  c.cuda = true;
  c.name = "cuda:" + std::to_string(index);
  void* lib = dlopen("libcuda.so.1", RTLD_LAZY | RTLD_LOCAL);  // kept open: LibTorch holds it too
  if (!lib) return c;
  const auto init = reinterpret_cast<CuInit>(dlsym(lib, "cuInit"));
  const auto get = reinterpret_cast<CuDeviceGet>(dlsym(lib, "cuDeviceGet"));
  const auto attribute = reinterpret_cast<CuDeviceGetAttribute>(dlsym(lib, "cuDeviceGetAttribute"));
  const auto get_name = reinterpret_cast<CuDeviceGetName>(dlsym(lib, "cuDeviceGetName"));
  const auto total = reinterpret_cast<CuDeviceTotalMem>(dlsym(lib, "cuDeviceTotalMem_v2"));
  int dev = 0;
  if (!init || !get || !attribute || init(0) != 0 || get(&dev, index) != 0) return c;
  int major = 0, minor = 0;
  if (attribute(&major, kComputeCapabilityMajor, dev) == 0 && attribute(&minor, kComputeCapabilityMinor, dev) == 0) {
    c.major = major;
    c.minor = minor;
  }
  char buf[256] = {};
  if (get_name && get_name(buf, static_cast<int>(sizeof buf) - 1, dev) == 0 && buf[0]) c.name = buf;
  size_t bytes = 0;
  if (total && total(&bytes, dev) == 0) c.memory_bytes = static_cast<double>(bytes);
  return c;
}

namespace {
std::mutex device_mutex;
SynthesisDevice& current() {
  static SynthesisDevice d{cpu_capabilities(), "{}"};
  return d;
}
}  // namespace

void set_synthesis_device(const SynthesisDevice& device) {
  std::lock_guard<std::mutex> lock(device_mutex);
  current() = device;
}

SynthesisDevice synthesis_device() {
  std::lock_guard<std::mutex> lock(device_mutex);
  return current();
}

}  // namespace ppsynth
