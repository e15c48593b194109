// A preset run is reused as the same request whichever processor class made it
// (presets.hpp's as_every_processor_variant, run_store's find_matching_run): a sweep kept in
// git across machines with and without bf16 units (docs/lab/reproduce_runs) is gathered on
// either kind. Machine-independent: the other kind's run is forged from this machine's.
#include <catch2/catch.hpp>

#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/formats/text_table.hpp"
#include "core/run_json.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_store.hpp"
#include "optim/run/run_synthesis.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kLines = "shared:data/exemplars/gabor-paper/lines.txt";

// The fast preset's keys for machines without bf16 units, over a config resolved for machines
// with them: what the other kind of machine resolves.
json as_without_bf16_units(const json& every) { return merge(every, presets()["fast"]["without_bf16_units"]); }

}  // namespace

TEST_CASE("a config resolved without bf16 units, as the preset's every-processor variant", "[optim][config][preset][reuse]") {
  REQUIRE(presets()["fast"].contains("without_bf16_units"));  // the case this handles
  const json every = {{"preset", "fast"},
                      {"seed", 3},
                      {"method", {{"type", "gabor"}, {"feature_net", {{"type", "random"}, {"precision", "auto"}}}, {"grid", {{"per_sigma", true}}}}}};
  const json without = as_without_bf16_units(every);
  REQUIRE(without != every);
  CHECK(as_every_processor_variant(without, kPresetWithoutBf16Units) == every);
  // Under the every-processor variant, or without a preset, nothing is taken out.
  CHECK(as_every_processor_variant(without, kPresetEveryProcessor) == without);
  CHECK(as_every_processor_variant(without, "") == without);
  json no_preset = without;
  no_preset["preset"] = nullptr;
  CHECK(as_every_processor_variant(no_preset, kPresetWithoutBf16Units) == no_preset);
  // A value the config set itself, other than the variant's, stays: it is another request.
  json own = without;
  own["method"]["feature_net"]["channels"] = 24;
  CHECK(as_every_processor_variant(own, kPresetWithoutBf16Units)["method"]["feature_net"]["channels"] == 24);
}

TEST_CASE("reuse takes a run of the same preset request made on the other processor class", "[optim][run][preset][reuse]") {
  const fs::path d = test::scratch_dir("reuse_across_variants");
  const json resolved = resolve_run_config({{"preset", "fast"}, {"exemplar", kLines}, {"seed", 5}}, {});
  const std::string here = preset_record(resolved["preset"], resolved["runtime"]["device"])["variant"];
  const std::string other = here == kPresetEveryProcessor ? kPresetWithoutBf16Units : kPresetEveryProcessor;
  RunRequest req;
  req.quick = true;
  req.dir = (d / "made_here").string();
  run_synthesis(resolved, req);
  REQUIRE(find_matching_run(resolved, true, {req.dir}) == req.dir);

  // The same run as the other kind of machine records it: its config holds the other
  // variant's values, and run.json names that variant and another processor.
  const json config_there = here == kPresetEveryProcessor ? as_without_bf16_units(resolved)
                                                          : as_every_processor_variant(resolved, kPresetWithoutBf16Units);
  REQUIRE_FALSE(same_synthesis(config_there, resolved));
  auto forge = [&](const std::string& name, const json& config, const json& variant) {
    const fs::path run = d / "pool" / name;
    fs::create_directories(run.parent_path());
    fs::copy(req.dir, run, fs::copy_options::recursive);
    write_text_atomic((run / "config.json").string(), config.dump(2) + "\n");
    json record = json::parse(read_file_text(run / "run.json"));
    record["processor"] = "another processor";
    if (variant.is_null()) record.erase("preset");
    else record["preset"]["variant"] = variant;
    write_text_atomic((run / "run.json").string(), record.dump(2) + "\n");
    return run.string();
  };
  const std::string there = forge("there", config_there, other);
  CHECK(read_run_record(there + "/run.json").preset_variant == other);
  CHECK(find_matching_run(resolved, true, {there}) == there);
  CHECK(find_matching_run(resolved, false, {there}).empty());  // a quick run never stands in for a full one

  // Not taken: the other config under this machine's own variant (it is another request),
  // a run that did not record its variant, and another request under the other variant.
  CHECK(find_matching_run(resolved, true, {forge("same_variant", config_there, here)}).empty());
  CHECK(find_matching_run(resolved, true, {forge("unrecorded", config_there, nullptr)}).empty());
  json another = config_there;
  another["method"]["c1"] = 0.123;
  CHECK(find_matching_run(resolved, true, {forge("another_request", another, other)}).empty());

  // Where both exist, this machine's own variant wins, even when the other variant's run comes
  // first by name or by root: an item's arms compare like for like.
  const std::string other_first = forge("a_other_variant", config_there, other);
  const std::string own_later = forge("z_own_variant", resolved, here);
  CHECK(find_matching_run(resolved, true, {(d / "pool").string()}) == own_later);
  CHECK(find_matching_run(resolved, true, {other_first, own_later}) == own_later);

  // reproduce --reuse-own-variant: the other variant's run is never taken, so it runs again here.
  ReuseRule own_only;
  own_only.other_variant = false;
  CHECK(find_matching_run(resolved, true, {there}, own_only).empty());
  CHECK(find_matching_run(resolved, true, {other_first, own_later}, own_only) == own_later);
}
