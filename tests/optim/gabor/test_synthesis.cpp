// End-to-end synthesis at --quick settings: sizes, classes, attributes, frozen classes,
// determinism, and a loss defined here (registered by one line) driving a synthesis step.
#include <catch2/catch.hpp>

#include "core/generators/lattices.hpp"
#include "losses/loss.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;

namespace {

PointSet two_class_exemplar() {
  PointSet ps;
  ps.add_attribute("radius");
  auto a = jittered_grid_points(16, 11), b = jittered_grid_points(9, 12);
  for (size_t i = 0; i < a.size(); ++i) ps.add(a[i], 0, {0.02});
  for (size_t i = 0; i < b.size(); ++i) ps.add(b[i], 1, {0.03});
  ps.set_class_labels({1000, 2000});
  return ps;
}

struct Recorder : SynthesisObserver {
  std::vector<PointSet> after_stage;
  void on_stage_end(const ProgressEvent&, const PointSet& p) override { after_stage.push_back(p); }
};

std::unique_ptr<SynthesisMethod> gabor(json extra = json::object()) {
  json spec = {{"type", "gabor"}};
  spec.update(extra);
  return MethodRegistry::instance().create(spec, "method");
}

}  // namespace

TEST_CASE("Quick 2-class synthesis keeps classes and attributes and freezes earlier classes", "[optim][synthesis]") {
  auto ex = two_class_exemplar();
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 3;
  Recorder rec;
  ctx.observers = {&rec};
  // The paper's plan: the border relax and the revisit after every class move class 0 again
  // (tests/optim/gabor/test_border_relax.cpp, test_revisit_stage.cpp).
  auto out = gabor({{"border_relax", {{"iterations", 0}}}, {"revisit", {{"iterations", 0}}}})->synthesize(ex, ctx);
  REQUIRE(out.size() == 4 * ex.size());
  auto counts = out.class_counts();
  CHECK(counts[0] == 64);
  CHECK(counts[1] == 36);
  CHECK(out.class_label(1) == 2000);
  for (size_t i = 0; i < out.size(); ++i) {
    CHECK(out.attr(i, 0) == Approx(out.cls(i) == 0 ? 0.01 : 0.015));  // radius / u
    CHECK(out.domain().contains(out[i]));
  }
  // 2 classes x 2 quick sigmas = 4 stages; class 0 fixed once its stages are done.
  REQUIRE(rec.after_stage.size() == 4);
  auto class0_done = rec.after_stage[1].subset_class(0);
  auto class0_end = out.subset_class(0);
  for (size_t i = 0; i < class0_end.size(); ++i) {
    CHECK(class0_end[i].x == class0_done[i].x);
    CHECK(class0_end[i].y == class0_done[i].y);
  }
  // Class 1 did move during its stages.
  auto c1_before = rec.after_stage[1].subset_class(1), c1_after = out.subset_class(1);
  double moved = 0;
  for (size_t i = 0; i < c1_after.size(); ++i) moved += std::abs(c1_after[i].x - c1_before[i].x);
  CHECK(moved > 0);
}

TEST_CASE("The per-class map term (map_terms.class_own) acts on the later classes only", "[optim][synthesis]") {
  auto ex = two_class_exemplar();
  struct FirstLossPerStage : SynthesisObserver {
    std::vector<double> first;
    void on_iteration(const ProgressEvent& e) override {
      if (e.iteration == 0) first.push_back(e.loss);
    }
  };
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 3;
  FirstLossPerStage paper_seen, own_seen;
  ctx.observers = {&paper_seen};
  // In the sequential pass (no revisit: there class 0 moves again, with the term).
  const json sequential = {{"revisit", {{"iterations", 0}}}};
  json paper_spec = sequential;
  paper_spec["map_terms"] = {{"class_own", {{"weight", 0.0}}}};
  auto paper = gabor(paper_spec)->synthesize(ex, ctx);
  ctx.observers = {&own_seen};
  auto with_own = gabor(sequential)->synthesize(ex, ctx);  // on by default
  REQUIRE(paper.size() == with_own.size());
  // Class 0 (the first stage, where joint = own) is untouched; class 1 moves differently.
  double class1_diff = 0;
  for (size_t i = 0; i < paper.size(); ++i) {
    if (paper.cls(i) == 0) {
      CHECK(paper[i].x == with_own[i].x);
      CHECK(paper[i].y == with_own[i].y);
    } else {
      class1_diff += std::abs(paper[i].x - with_own[i].x) + std::abs(paper[i].y - with_own[i].y);
    }
  }
  CHECK(class1_diff > 0);
  // 2 classes x 2 quick sigmas: the first loss of each class-1 stage carries the added term.
  REQUIRE(paper_seen.first.size() == 4);
  REQUIRE(own_seen.first.size() == 4);
  CHECK(own_seen.first[0] == paper_seen.first[0]);
  CHECK(own_seen.first[2] > paper_seen.first[2]);
  CHECK_THROWS_WITH(gabor(json{{"map_terms", {{"class_own", {{"weight", -1.0}}}}}})->synthesize(ex, ctx),
                    Catch::Contains("method.map_terms.class_own.weight"));
  CHECK_THROWS_WITH(gabor(json{{"map_terms", {{"no_such_term", {{"weight", 1.0}}}}}})->synthesize(ex, ctx),
                    Catch::Contains("no_such_term"));
}

TEST_CASE("Same config and seed give the same output", "[optim][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 9;
  auto a = gabor()->synthesize(ex, ctx), b = gabor()->synthesize(ex, ctx);
  ctx.seed = 10;
  auto c = gabor()->synthesize(ex, ctx);
  REQUIRE(a.size() == b.size());
  bool same = true, differs = false;
  for (size_t i = 0; i < a.size(); ++i) {
    same = same && a[i].x == b[i].x && a[i].y == b[i].y;
    differs = differs || a[i].x != c[i].x;
  }
  CHECK(same);
  CHECK(differs);
}

TEST_CASE("Bad method parameters are errors naming the key", "[optim][synthesis]") {
  CHECK_THROWS_WITH(gabor(json{{"c1", "big"}}), Catch::Contains("c1"));
  // The British spelling of `optimizer` is an unknown key, not an alias (written in two pieces so
  // that a spelling pass leaves it as it is).
  CHECK_THROWS_WITH(gabor(json{{"optim" "iser", json{{"type", "adam"}}}}), Catch::Contains("optim" "iser"));
  auto ex = jittered_grid_points(16, 5);
  SynthesisContext ctx;
  ctx.quick = true;
  CHECK_THROWS_WITH(gabor(json{{"class_order", {3}}})->synthesize(ex, ctx), Catch::Contains("class_order"));
  CHECK_THROWS_WITH(gabor(json{{"optimizer", json{{"type", "rmsprop"}}}})->synthesize(ex, ctx), Catch::Contains("optimizer.type"));
}

// --- a loss defined and registered right here: one class, one registration line ---------
namespace {
class MeanActivationLoss : public FeatureLoss {
 public:
  void set_target(const Features& ex, const LossContext&) override { target_ = ex.back().mean().detach(); }
  torch::Tensor forward(const Features& out) override { return (out.back().mean() - target_).pow(2) + 1e-3; }

 private:
  torch::Tensor target_;
};
}  // namespace
PPSYNTH_REGISTER(ppsynth::LossRegistry, "test_mean_activation", (ppsynth::json{{"layers", {2}}, {"weight", 1.0}}),
                 (ppsynth::json{{"layers", "int [0, 15]"}, {"weight", "[0, inf)"}}),
                 "test-only loss", [](const ppsynth::json&, const std::string&) -> std::unique_ptr<ppsynth::FeatureLoss> {
                   return std::make_unique<MeanActivationLoss>();
                 })

TEST_CASE("A loss registered in a test file drives a synthesis", "[optim][synthesis][registry]") {
  struct LossSeen : SynthesisObserver {
    std::vector<double> losses;
    void on_iteration(const ProgressEvent& e) override { losses.push_back(e.loss); }
  } seen;
  auto ex = jittered_grid_points(16, 5);
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.observers = {&seen};
  auto m = gabor(json{{"losses", json::array({json{{"type", "test_mean_activation"}}})}});
  auto out = m->synthesize(ex, ctx);
  CHECK(out.size() == 64);
  REQUIRE_FALSE(seen.losses.empty());
  CHECK(seen.losses.front() >= 1e-3);
}
