// One synthesis resolves its exemplar, output shape, options and method once
// (optim/run/run_spec.hpp): the run layer, the checkpoint key and the log read the one RunSpec
// instead of each reading the file, resolving the shape, reading the JSON or building the
// method again. Counted with the reader's and
// the resolver's process-wide counters and a method whose factory counts its creations.
#include <catch2/catch.hpp>

#include <atomic>

#include "core/formats/point_io.hpp"
#include "core/output_shape.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_spec.hpp"
#include "optim/run/run_synthesis.hpp"
#include "optim/run/synthesize.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;

namespace {

const char* kLines = "shared:data/exemplars/gabor-paper/lines.txt";

std::atomic<int> g_creations{0};

// The Gabor method, counted each time the registry builds it.
class CountedGabor : public SynthesisMethod {
 public:
  CountedGabor() : inner_(MethodRegistry::instance().create(json{{"type", "gabor"}}, "method")) { ++g_creations; }
  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override { return inner_->synthesize(exemplar, ctx); }
  bool can_resume() const override { return inner_->can_resume(); }
  int version() const override { return inner_->version(); }

 private:
  std::unique_ptr<SynthesisMethod> inner_;
};

// Stops the run at the end of its first stage (the method checkpoints there, then stops).
struct StopAfterFirstStage : SynthesisObserver {
  std::atomic<bool> stop{false};
  void on_stage_end(const ProgressEvent&, const PointSet&) override { stop = true; }
};

struct Counts {
  size_t reads = point_file_reads(), shapes = output_shape_resolutions();
  int creations = g_creations.load();
  size_t reads_since() const { return point_file_reads() - reads; }
  size_t shapes_since() const { return output_shape_resolutions() - shapes; }
  int creations_since() const { return g_creations.load() - creations; }
};

}  // namespace

PPSYNTH_REGISTER(ppsynth::MethodRegistry, "test_counted_gabor", nlohmann::json::object(), nlohmann::json::object(),
                 "the gabor method at its defaults, its creations counted (tests/optim/run/test_run_spec.cpp)",
                 [](const nlohmann::json&, const std::string&) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<CountedGabor>();
                 })

TEST_CASE("one run reads its exemplar once, resolves its output shape once and builds its method once", "[run][run_spec]") {
  const auto d = test::scratch_dir("run_spec_once");
  const json spec = resolve_run_config({{"exemplar", kLines}, {"seed", 5}, {"method", {{"type", "test_counted_gabor"}}}}, {});
  RunRequest req;
  req.dir = (d / "run").string();
  req.quick = true;
  const Counts before;
  const RunOutcome run = run_synthesis(spec, req);
  CHECK(run.output.size() == 80);
  CHECK(before.reads_since() == 1);
  CHECK(before.shapes_since() == 1);
  CHECK(before.creations_since() == 1);
}

TEST_CASE("a resumed run reads its exemplar copy once, resolves its output shape once and builds its method once", "[run][run_spec]") {
  const auto d = test::scratch_dir("run_spec_resume");
  const json spec = resolve_run_config({{"exemplar", kLines}, {"seed", 5}, {"method", {{"type", "test_counted_gabor"}}}}, {});
  StopAfterFirstStage stopper;
  RunRequest req;
  req.dir = (d / "run").string();
  req.quick = true;
  req.stop = &stopper.stop;
  req.observers = {&stopper};
  REQUIRE_THROWS_AS(run_synthesis(spec, req), RunInterrupted);

  RunRequest again;
  const Counts before;
  const RunOutcome run = resume_synthesis(req.dir, again);
  CHECK(run.output.size() == 80);
  CHECK(before.reads_since() == 1);  // the run directory's exemplar.txt
  CHECK(before.shapes_since() == 1);
  // One to check the directory's config.json as resolve_run_config has it, one for the run.
  CHECK(before.creations_since() == 2);
}

TEST_CASE("make_run_spec reads the config's options through their table, and the run layer follows them", "[run][run_spec]") {
  const json resolved = resolve_run_config({{"exemplar", kLines}, {"method", {{"type", "tiled_copy"}}}},
                                           {"seed=12", "checkpoint_seconds=7", "snapshots=false", "runtime.device=auto",
                                            "runtime.tf32=false", "runtime.deterministic=false"});
  const PointSet ex = load_exemplar(resolved);
  const RunSpec spec = make_run_spec(resolved, ex);
  CHECK(spec.seed == 12);
  CHECK(spec.options.checkpoint_seconds == 7);
  CHECK(spec.options.evaluate);
  CHECK_FALSE(spec.options.snapshots);
  CHECK(spec.options.runtime.device == "auto");
  CHECK(spec.options.runtime.tf32 == false);
  CHECK_FALSE(spec.options.runtime.deterministic);
  CHECK(spec.options.method == resolved["method"]);
  CHECK(spec.config == resolved);  // what config.json and the checkpoint key are written from
  const json key = checkpoint_key(spec, true);
  CHECK(key["config"] == resolved);
  CHECK(key["seed"].dump() == resolved["seed"].dump());  // the typed seed writes as the config's
  CHECK(key["method"] == "tiled_copy");

  // What the synthesis does is what the options say, whatever the JSON beside them holds.
  RunSpec typed = spec;
  typed.options.evaluate = false;
  CHECK(synthesize(spec).metrics.is_object());
  CHECK(synthesize(typed).metrics.is_null());
  typed.options.runtime.device = "tpu";
  CHECK_THROWS_WITH(synthesize(typed), Catch::Contains("runtime.device") && Catch::Contains("tpu"));
}
