#pragma once
// Test support: whether this build runs under AddressSanitizer (scripts/sanitize.sh), for the
// few tests that measure what ASan changes: glibc's heap (ASan replaces malloc) and a virtual
// memory limit (ASan reserves terabytes of shadow address space at start-up).
namespace ppsynth::test {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

}  // namespace ppsynth::test
