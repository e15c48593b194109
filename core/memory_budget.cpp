#include "core/memory_budget.hpp"

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace ppsynth {

namespace {

std::string gib(double bytes) {
  char buf[64];
  std::snprintf(buf, sizeof buf, bytes < 1024.0 * 1024 * 1024 ? "%.0f MiB" : "%.1f GiB",
                bytes < 1024.0 * 1024 * 1024 ? bytes / (1024.0 * 1024) : bytes / (1024.0 * 1024 * 1024));
  return buf;
}

}  // namespace

double available_memory_bytes() {
  double bytes = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream is(line.substr(13));
    double kib = 0;
    if (is >> kib && kib > 0) bytes = kib * 1024.0;
    break;
  }
  if (const char* limit = std::getenv("PPSYNTH_MEMORY_LIMIT_MB")) {
    char* end = nullptr;
    const double mb = std::strtod(limit, &end);
    if (end == limit || *end != '\0' || !(mb > 0))
      throw InputError(std::string("PPSYNTH_MEMORY_LIMIT_MB='") + limit + "': expected a positive number of MiB");
    bytes = std::min(bytes, mb * 1024.0 * 1024.0);
  }
  return bytes;
}

void check_memory(double bytes, const std::string& what) {
  const double available = available_memory_bytes();
  if (!(bytes <= available))
    throw InputError(what + " needs about " + gib(bytes) + " of memory; " + gib(available) + " are available");
}

double peak_resident_mib() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0;  // KiB on Linux
}

void release_freed_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

}  // namespace ppsynth
