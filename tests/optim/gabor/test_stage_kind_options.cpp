// A stage kind that owns options and a record, added by this one file: its block
// (method.test_trail) is declared once, in its table, where it registers (its defaults,
// ranges, doc lines and typed read come from it), the settings carry the block without knowing it, and its record holds a string that the
// checkpoint stores and gives back without reading it. Each trail stage appends its word to
// the trail of the stage before it, so a resumed run that lost the record would write another
// trail. The run is interrupted after a checkpoint and resumed: the same points and records.
#include <catch2/catch.hpp>

#include <atomic>
#include <string>
#include <vector>

#include "core/checkpoint_file.hpp"
#include "core/config/config.hpp"
#include "core/config/param_docs.hpp"
#include "core/error.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/gabor/stages/stage_plan.hpp"
#include "optim/gabor/stages/synthesis_state.hpp"
#include "optim/method/method.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;

namespace {

class TrailStage : public StageKind {
 public:
  TrailStage(int iterations, std::string word) : iterations_(iterations), word_(std::move(word)) {}
  std::string label() const override { return "trail"; }
  int iteration_cap(const GaborSettings&) const override { return iterations_; }
  bool judged() const override { return false; }
  bool rolls_grid() const override { return false; }
  StageStart start(const StageStartView& v) const override {
    std::string trail;
    for (const StageRecord& r : v.finished_stages)
      if (r.details.contains("trail")) trail = r.details["trail"].get<std::string>();
    StageStart st;
    st.record = {{"trail", trail + word_ + std::to_string(v.stage.own_class)}};
    st.note = "trail " + st.record["trail"].get<std::string>();
    return st;
  }
  std::string record_problem(const nlohmann::json& details) const override {
    return details.contains("trail") && !details["trail"].is_string() ? "'trail' is not a string" : "";
  }

 private:
  int iterations_;
  std::string word_;
};

struct TrailOptions {
  int iterations = 0;  // off by default: the kind is registered for the whole test binary
  std::string word = "w";
  static const ParamTable<TrailOptions>& params() {
    static const ParamTable<TrailOptions> t("method.test_trail", {
        param("iterations", &TrailOptions::iterations, "int [0, 100]", "trail iterations per class (0: off)"),
        param("word", &TrailOptions::word, "", "appended to the trail at each trail stage"),
    });
    return t;
  }
};

PPSYNTH_REGISTER_STAGE_KIND("test_trail", TrailOptions::params(), "a test's stage kind with options and a string in its record",
                            [](const TrailOptions& o, const std::string&, const GaborSettings&) -> std::unique_ptr<StageKind> {
                              if (o.iterations == 0) return nullptr;
                              return std::make_unique<TrailStage>(o.iterations, o.word);
                            })

json trail_method(const json& trail) {
  return {{"type", "gabor"},
          {"border_relax", {{"iterations", 0}}},  // the built-in class-end kinds off: the paper's plan
          {"revisit", {{"iterations", 0}}},
          {"test_trail", trail},
          {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 3}, {"num_sigmas", 2}}}};
}

// Everything of the records but their wall time.
json records_without_time(const StagesReport& report) {
  json all = to_json(report.stages);
  for (auto& r : all) r.erase("seconds");
  return all;
}

}  // namespace

TEST_CASE("a stage kind with options runs its block and records a string", "[optim][stage_kinds][stage_kind_options]") {
  const PointSet ex = test::small_exemplar(2, false);
  const auto run = test::checkpointed_run(trail_method({{"iterations", 2}, {"word", "ab"}}), ex, 7);
  // Per class: 2 sigma stages, then its trail (after its own class).
  REQUIRE(run.report.stages.size() == 6);
  CHECK(run.report.stages[2].stage == "class 1/2 (id 0), trail");
  CHECK(run.report.stages[2].iterations == 2);
  CHECK(run.report.stages[2].details["trail"] == "ab0");
  CHECK(run.report.stages[5].details["trail"] == "ab0ab1");
  // Off (its default): the paper's plan.
  CHECK(test::checkpointed_run(trail_method(json::object()), ex, 7).report.stages.size() == 4);
}

TEST_CASE("a stage kind's table gives the method its block's defaults, ranges and doc lines", "[optim][stage_kinds][stage_kind_options][params]") {
  const auto& gabor = MethodRegistry::instance().entry("gabor");
  CHECK(gabor.defaults["test_trail"] == TrailOptions::params().defaults());
  CHECK(gabor.bounds["test_trail"] == TrailOptions::params().bounds());
  CHECK(param_docs("method", "gabor")["test_trail"] == TrailOptions::params().docs());
}

TEST_CASE("a stage kind's options are checked where it declares them, naming the key", "[optim][stage_kinds][stage_kind_options]") {
  const PointSet ex = test::small_exemplar(1, false);
  OutputShape square;
  square.upscale = 2;
  CHECK_THROWS_WITH(test::method_params(trail_method({{"iterations", 1000}})), Catch::Contains("method.test_trail.iterations"));
  CHECK_THROWS_WITH(test::method_params(trail_method({{"colour", 1}})), Catch::Contains("method.test_trail.colour"));
  CHECK_THROWS_WITH(resolve_gabor_settings(test::method_params(trail_method({{"word", 3}})), ex, square, false),
                    Catch::Contains("method.test_trail.word"));
}

TEST_CASE("a stage kind with options, interrupted after a checkpoint, resumes bit for bit with its records",
          "[optim][stage_kinds][stage_kind_options][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, false);
  const json method = trail_method({{"iterations", 2}, {"word", "ab"}});
  const auto whole = test::checkpointed_run(method, ex, 7);

  // Stopped in the second class's trail stage, after the first class's trail was recorded.
  auto m = MethodRegistry::instance().create(method, "method");
  std::string last;
  std::atomic<bool> stop{false};
  int saved = 0;
  StagesReport first_report;
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 7;
  ctx.stages = &first_report;
  ctx.checkpoint_seconds = 0;
  ctx.stop = &stop;
  const int stop_at = static_cast<int>(whole.checkpoints.size()) - 2;
  ctx.save_checkpoint = [&](const std::string& bytes) {
    last = bytes;
    if (++saved == stop_at) stop = true;
  };
  CHECK_THROWS_AS(m->synthesize(ex, ctx), SynthesisInterrupted);
  const SynthesisState at_stop = deserialize_state(last, "the checkpoint");
  REQUIRE(at_stop.stages.size() >= 3);
  CHECK(at_stop.stages[2].details["trail"] == "ab0");

  const auto resumed = test::checkpointed_run(method, ex, 7, &last);
  CHECK(test::same_bits(resumed.output, whole.output));
  CHECK(records_without_time(resumed.report) == records_without_time(whole.report));
  CHECK(resumed.report.stages[5].details["trail"] == "ab0ab1");
}

TEST_CASE("a checkpoint whose record the kind cannot read is refused, saying which field", "[optim][stage_kinds][stage_kind_options][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, false);
  const json method = trail_method({{"iterations", 2}, {"word", "ab"}});
  const auto whole = test::checkpointed_run(method, ex, 7);
  SynthesisState s = deserialize_state(whole.checkpoints[whole.checkpoints.size() - 2], "the checkpoint");
  REQUIRE(s.stages.size() >= 3);
  s.stages[2].details["trail"] = 5;
  const std::string damaged = serialize_state(s);
  CHECK_THROWS_AS(test::checkpointed_run(method, ex, 7, &damaged), CheckpointError);
  CHECK_THROWS_WITH(test::checkpointed_run(method, ex, 7, &damaged), Catch::Contains("'trail' is not a string"));
}
