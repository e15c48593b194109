// libFuzzer target: a run directory's marker (.ppsynth-run) as every command reads it
// (core/run_directory.hpp's parse_run_dir_marker), then what `sweep status` and a resume take
// from it: the progress line, the kind, the quick setting, the thread count. Contract:
// fuzz_common.hpp.
#include "core/run_directory.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  nlohmann::json m;
  if (!fuzz::accepts([&] { m = parse_run_dir_marker(text, ".ppsynth-run"); })) return 0;
  try {  // what the readers of an accepted marker take from it, unchecked
    (void)run_progress_text(m, 1700000000);
    (void)m.value("kind", std::string());
    (void)m.value("quick", false);
    (void)m.value("processor", std::string());
    (void)m.value("threads", nlohmann::json()).dump();
  } catch (const nlohmann::json::exception& e) {
    fuzz::fail(std::string("an accepted marker breaks a reader: ") + e.what());
  }
  return 0;
}
