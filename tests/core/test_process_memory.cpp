// The process's memory as core/memory_budget.hpp reports and releases it.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "core/memory_budget.hpp"
#include "tests/support/sanitizers.hpp"

using namespace ppsynth;

namespace {

// AddressSanitizer replaces malloc and free: its allocator keeps freed blocks in quarantine, so
// glibc's heap, what release_freed_memory() trims, is not the one the blocks come from.
constexpr bool kGlibcHeap = !test::kAddressSanitizer;

double resident_mib() {  // VmRSS: the current resident set, not the peak
  std::ifstream in("/proc/self/status");
  std::string key;
  double kib = 0;
  while (in >> key) {
    if (key == "VmRSS:") {
      in >> kib;
      break;
    }
    std::getline(in, key);
  }
  return kib / 1024.0;
}

}  // namespace

TEST_CASE("release_freed_memory gives the heap's free pages back; the peak stays the peak", "[core][memory]") {
  if (!kGlibcHeap) {
    release_freed_memory();  // still callable; its effect is glibc's heap, which ASan replaces
    WARN("built with AddressSanitizer: glibc's heap is not in use, the release is not measured");
    return;
  }
#ifdef __GLIBC__
  // What a synthesis sets (optim/run/runtime.cpp): no mmap'd blocks, no trimming on free.
  // Freed blocks then stay resident until release_freed_memory().
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::vector<char*> blocks;
  for (int i = 0; i < 48; ++i) {  // 192 MiB, touched
    blocks.push_back(static_cast<char*>(std::malloc(4 << 20)));
    REQUIRE(blocks.back());
    std::memset(blocks.back(), 1 + i, 4 << 20);
  }
  char* pin = static_cast<char*>(std::malloc(64));  // above them: the heap's top cannot shrink past it
  const double peak_before = peak_resident_mib();
  for (char* b : blocks) std::free(b);
  const double kept = resident_mib();
  release_freed_memory();
  const double released = resident_mib();
  INFO("resident after free: " << kept << " MiB; after release_freed_memory: " << released << " MiB");
  CHECK(kept - released > 150);
  CHECK(peak_resident_mib() >= peak_before);
  std::free(pin);
  mallopt(M_TRIM_THRESHOLD, 128 * 1024);  // glibc's defaults again for the other tests
  mallopt(M_MMAP_MAX, 65536);
#else
  release_freed_memory();  // a no-op elsewhere
  SUCCEED();
#endif
}
