// libFuzzer target: a sweep's manifest.json as the executors read it (core/sweep_manifest.hpp,
// after the file's JSON parse). What it accepts must write back to a manifest that reads back
// the same, with names and row ids that are plain and directories under runs/. Contract:
// fuzz_common.hpp.
#include "core/config/json_text.hpp"
#include "core/run_directory.hpp"
#include "core/sweep_manifest.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  SweepManifest m;
  if (!fuzz::accepts([&] { m = parse_sweep_manifest(parse_json_text(text, "manifest.json", false), "manifest.json"); })) return 0;
  if (!is_safe_name(m.name)) fuzz::fail("an accepted sweep name that is not a plain name");
  for (const auto& r : m.rows)
    if (!is_safe_name(r.id) || r.dir != "runs/" + r.id) fuzz::fail("an accepted row outside runs/: " + r.dir);
  SweepManifest back;
  if (!fuzz::accepts([&] { back = parse_sweep_manifest(sweep_manifest_json(m), "manifest.json"); }))
    fuzz::fail("an accepted manifest does not read back once written");
  if (sweep_manifest_hash(back) != sweep_manifest_hash(m)) fuzz::fail("an accepted manifest reads back otherwise");
  return 0;
}
