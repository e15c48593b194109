#include "core/process_cpu.hpp"

#include <sys/resource.h>

namespace ppsynth {

double process_cpu_seconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(ru.ru_utime) + seconds(ru.ru_stime);
}

}  // namespace ppsynth
