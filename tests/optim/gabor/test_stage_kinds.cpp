// A stage kind is one file (optim/gabor/stages/stage_kind.hpp): this one, written and registered here
// and nowhere else, enters the plan after each class's sigma stages, moves only the points in
// the left half of the unit square for a fixed count, and records what it did. The engine runs
// it without knowing it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/method/method.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"
#include "tests/support/stage_ends.hpp"

using namespace ppsynth;

namespace {

// Off but in this file's test: the kind is registered for the whole test binary.
bool left_half_enabled = false;

class LeftHalfStage : public StageKind {
 public:
  std::string label() const override { return "left half"; }
  int iteration_cap(const GaborSettings&) const override { return 3; }
  bool judged() const override { return false; }
  bool rolls_grid() const override { return false; }
  StageStart start(const StageStartView& v) const override {
    StageStart st;
    st.moving_mask = torch::zeros({static_cast<int64_t>(v.moving.size()), 1}, torch::kBool);
    auto mask = st.moving_mask.accessor<bool, 2>();
    int64_t left = 0;
    for (size_t i = 0; i < v.moving.size(); ++i)
      if (v.output[v.moving[i]].x < 0.5) mask[static_cast<int64_t>(i)][0] = true, ++left;
    st.note = std::to_string(left) + " points in the left half";
    st.record = {{"left_points", left}};
    return st;
  }
};

// No options: an empty table.
struct LeftHalfOptions {
  static const ParamTable<LeftHalfOptions>& params() {
    static const ParamTable<LeftHalfOptions> t("method.test_left_half", {});
    return t;
  }
};

PPSYNTH_REGISTER_STAGE_KIND("test_left_half", LeftHalfOptions::params(), "a test's stage kind",
                            [](const LeftHalfOptions&, const std::string&, const GaborSettings&) -> std::unique_ptr<StageKind> {
                              if (!left_half_enabled) return nullptr;
                              return std::make_unique<LeftHalfStage>();
                            })

PointSet run(const PointSet& ex, test::StageEnds& ends, StagesReport* stages) {
  const json method = {{"type", "gabor"},
                       {"border_relax", {{"iterations", 0}}},  // the built-in class-end kinds off: the paper's plan
                       {"revisit", {{"iterations", 0}}},
                       {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 5}, {"num_sigmas", 2}}}};
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 11;
  ctx.observers.push_back(&ends);
  ctx.stages = stages;
  return MethodRegistry::instance().create(method, "method")->synthesize(ex, ctx);
}

}  // namespace

TEST_CASE("a stage kind added by one file runs in the plan", "[optim][stage_kinds][synthesis]") {
  const PointSet ex = test::small_exemplar(2, false);
  test::StageEnds paper, with_kind;
  StagesReport stats;
  run(ex, paper, nullptr);
  {
    left_half_enabled = true;
    struct Off {
      ~Off() { left_half_enabled = false; }
    } off;
    run(ex, with_kind, &stats);
  }
  // Per class: sigma 1, sigma 2, then the new kind (after its own class: after_all_classes false).
  REQUIRE(paper.labels.size() == 4);
  REQUIRE(with_kind.labels.size() == 6);
  CHECK(with_kind.labels[2] == "class 1/2 (id 0), left half");
  CHECK(with_kind.labels[5] == "class 2/2 (id 1), left half");
  CHECK(with_kind.notes[2].find("points in the left half") != std::string::npos);
  // The first class's sigma stages are the paper's bit for bit.
  CHECK(test::same_bits(with_kind.points[0], paper.points[0]));
  CHECK(test::same_bits(with_kind.points[1], paper.points[1]));
  // Its class's right-half points and every other class's stay; some left-half ones move.
  for (int c = 0; c < 2; ++c) {
    const PointSet& before = with_kind.points[3 * c + 1];
    const PointSet& after = with_kind.points[3 * c + 2];
    size_t left = 0, moved = 0;
    for (size_t i = 0; i < before.size(); ++i) {
      const bool may_move = before.cls(i) == c && before[i].x < 0.5;
      const bool did = before[i].x != after[i].x || before[i].y != after[i].y;
      left += may_move;
      moved += did;
      if (!may_move) CHECK_FALSE(did);
    }
    INFO("class " << c);
    CHECK(moved > left / 2);
    // Its record: the engine's fields, with the kind's own.
    const StageRecord& record = stats.stages[3 * c + 2];
    CHECK(record.iterations == 3);
    CHECK(record.details["left_points"] == static_cast<int64_t>(left));
  }
}
