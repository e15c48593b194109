#pragma once
// Shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp, built with -DPPSYNTH_FUZZ=ON; see
// scripts/fuzz.sh). The contract every target checks: for any input a reader or the config
// loader either returns or throws ppsynth::InputError (a correct rejection). Any other
// exception escapes LLVMFuzzerTestOneInput and libFuzzer reports it (deadly signal), as it
// does a crash, a leak or undefined behavior (ASan + UBSan, UB is fatal).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/point_set.hpp"

namespace ppsynth::fuzz {

// Readers log warnings (coincident points, ...): silence them, they are not findings.
inline void quiet_logging() { spdlog::set_level(spdlog::level::off); }

// Runs f(); an InputError is the documented way to refuse input. Returns false then.
template <class F>
bool accepts(F&& f) {
  try {
    f();
    return true;
  } catch (const ppsynth::InputError&) {
    return false;
  }
}

// A property that must hold (not an input error): report and abort so libFuzzer keeps
// the input as a crash.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "ppsynth fuzz property violated: %s\n", what.c_str());
  std::abort();
}

// What a reader's result must survive: validation may refuse it (InputError); a valid set
// written by ppsynth in `format` must read back in that format with as many points.
inline void check_parsed(const PointSet& ps, Format format, const std::string& source) {
  if (!accepts([&] { validate(ps, source); })) return;
  const std::string text = format_points(ps, format);
  ReadOptions opts;
  opts.format = format;
  opts.attribute_names = ps.attribute_names();
  if (format == Format::Plain || format == Format::Json) opts.attribute_names.clear();
  PointSet back;
  if (!accepts([&] { back = parse_points(text, source, opts); }))
    fail("a valid point set written as " + format_name(format) + " does not read back:\n" + text);
  if (back.size() != ps.size()) fail("round trip through " + format_name(format) + " changed the point count");
}

}  // namespace ppsynth::fuzz

// libFuzzer's two entry points for a target that reads its input as text and needs no set-up
// but quiet logging. Write `PPSYNTH_FUZZ_TEXT_TARGET { ... }`: the body sees `text` and
// returns 0.
#define PPSYNTH_FUZZ_TEXT_TARGET                                                 \
  static int fuzz_text(const std::string& text);                                 \
  extern "C" int LLVMFuzzerInitialize(int*, char***) {                           \
    ppsynth::fuzz::quiet_logging();                                              \
    return 0;                                                                    \
  }                                                                              \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {      \
    return fuzz_text(std::string(reinterpret_cast<const char*>(data), size));    \
  }                                                                              \
  static int fuzz_text(const std::string& text)
