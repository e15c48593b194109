// Checkpoint and resume of the Gabor engine, in process: a run restored from any of its
// checkpoints (mid-stage or at a stage boundary) ends with the very bits of the run that was
// never stopped; and the comparison is sharp enough to see a wrong generator, wrong moments
// or a one-ulp position change in the restored state.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "core/generators/lattices.hpp"
#include "core/metrics/pcf.hpp"
#include "optim/method.hpp"
#include "optim/synthesis_state.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;
using ppsynth::test::same_bits;

namespace {


using Run = test::CheckpointedRun;

const json kQuickMethod{{"type", "gabor"}, {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 7}, {"num_sigmas", 2}}}};

Run synthesize(const PointSet& ex, const std::string* resume = nullptr, const std::atomic<bool>* stop = nullptr,
               const json& method_spec = kQuickMethod) {
  return test::checkpointed_run(method_spec, ex, 5, resume, stop);
}


}  // namespace

TEST_CASE("a run resumed from any checkpoint ends bit for bit as the uninterrupted one", "[optim][checkpoint]") {
  for (auto [classes, disks] : {std::pair{1, false}, std::pair{2, false}, std::pair{2, true}}) {
    INFO(classes << " classes, disks " << disks);
    const PointSet ex = test::small_exemplar(classes, disks);
    const Run whole = synthesize(ex);
    // checkpoints: every iteration plus every stage boundary
    REQUIRE(whole.checkpoints.size() > 2u * classes * 2);
    const size_t n = whole.checkpoints.size();
    for (size_t i : {size_t{0}, size_t{3}, n / 2, n - 2, n - 1}) {
      const SynthesisState st = deserialize_state(whole.checkpoints[i], "test");
      INFO("checkpoint " << i << ": stage " << st.stage << ", iteration " << st.iteration);
      const Run resumed = synthesize(ex, &whole.checkpoints[i]);
      CHECK(same_bits(resumed.output, whole.output));
      REQUIRE(resumed.stats["stages"].size() == whole.stats["stages"].size());
      // per-stage iterations and final losses are the same too (seconds aside)
      for (size_t s = 0; s < whole.stats["stages"].size(); ++s) {
        CHECK(resumed.stats["stages"][s]["iterations"] == whole.stats["stages"][s]["iterations"]);
        CHECK(resumed.stats["stages"][s]["final_loss"] == whole.stats["stages"][s]["final_loss"]);
      }
    }
  }
}

TEST_CASE("a stage stopped by the pattern rule resumes to the same stopping iteration", "[optim][checkpoint]") {
  // The rule's record of the stage (its PCF checks) is in the checkpoint: resumed mid-stage,
  // the stage stops where the uninterrupted one did, before its cap. Per-sigma grids: the
  // grid changes between the stages and is rebuilt the same on resuming.
  json spec = kQuickMethod;
  spec["quick"]["max_iterations"] = 80;
  spec["grid"] = {{"per_sigma", true}};
  spec["convergence"] = {{"type", "pattern"}, {"window", 10}, {"check_every", 5}, {"threshold", 0.5}, {"min_iterations", 0}};
  spec["border_relax"] = {{"iterations", 0}};  // the sigma stages only
  const PointSet ex = test::small_exemplar(1, false);
  const Run whole = synthesize(ex, nullptr, nullptr, spec);
  REQUIRE(whole.stats["stages"].size() == 2);
  const int first_stage = whole.stats["stages"][0]["iterations"];
  CHECK(whole.stats["output_grid_res_per_sigma"][0] < whole.stats["output_grid_res_per_sigma"][1]);
  CHECK(first_stage < 80);  // stopped by the rule, not the cap
  for (size_t i : {size_t{7}, size_t{12}, whole.checkpoints.size() / 2}) {
    INFO("checkpoint " << i);
    const Run resumed = synthesize(ex, &whole.checkpoints[i], nullptr, spec);
    CHECK(same_bits(resumed.output, whole.output));
    CHECK(resumed.stats["stages"][0]["iterations"] == first_stage);
    CHECK(resumed.stats["stages"][1]["iterations"] == whole.stats["stages"][1]["iterations"]);
  }
}

TEST_CASE("a stage that ends on its best iterate ends there, and resumes to the same bits", "[optim][checkpoint]") {
  // One sigma, so the run's output is that stage's end: with end_on "best" it is the checked
  // iterate nearest the exemplar's PCF, never farther than the last iterate (the same
  // trajectory with end_on "last"); the kept copy is in the checkpoint, so a run resumed
  // after it was taken still ends on it.
  json spec = kQuickMethod;
  spec["quick"]["max_iterations"] = 60;
  spec["quick"]["num_sigmas"] = 1;
  spec["convergence"] = {{"type", "pattern"}, {"window", 1000}, {"check_every", 5}, {"min_iterations", 0}};
  spec["border_relax"] = {{"iterations", 0}};  // no relax after it: the stage's end is the output
  const PointSet ex = test::small_exemplar(1, false);
  const Run last = synthesize(ex, nullptr, nullptr, spec);
  spec["convergence"]["end_on"] = "best";
  const Run best = synthesize(ex, nullptr, nullptr, spec);
  REQUIRE(best.stats["stages"][0]["iterations"] == 60);  // both ran to the cap: same trajectory
  PcfOptions torus;
  torus.periodic = true;
  const Curve target = pcf(ex);
  const double mse_best = curve_mse(pcf(best.output, torus), target), mse_last = curve_mse(pcf(last.output, torus), target);
  INFO("PCF MSE, end on best " << mse_best << ", end on last " << mse_last);
  CHECK(mse_best < mse_last);  // this trajectory's best check is not its last
  for (size_t i : {size_t{2}, size_t{20}, size_t{45}, best.checkpoints.size() - 2}) {
    INFO("checkpoint " << i);
    CHECK(same_bits(synthesize(ex, &best.checkpoints[i], nullptr, spec).output, best.output));
  }
}

TEST_CASE("the stop flag saves a checkpoint and throws; resuming from it finishes the run", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, false);
  const Run whole = synthesize(ex);
  std::atomic<bool> stop{true};  // stop at the end of the first iteration
  Run stopped;
  auto method = MethodRegistry::instance().create(kQuickMethod, "method");
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 5;
  ctx.checkpoint_seconds = 1e9;
  ctx.save_checkpoint = [&](const std::string& bytes) { stopped.checkpoints.push_back(bytes); };
  ctx.stop = &stop;
  CHECK_THROWS_AS(method->synthesize(ex, ctx), SynthesisInterrupted);
  REQUIRE(stopped.checkpoints.size() == 1);
  CHECK(deserialize_state(stopped.checkpoints[0], "t").iteration == 1);
  CHECK(same_bits(synthesize(ex, &stopped.checkpoints[0]).output, whole.output));
}

TEST_CASE("the resume comparison sees a perturbed generator, optimiser or position", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(1, false);
  const Run whole = synthesize(ex);
  // a checkpoint in the middle of the first stage: the optimiser has moments, the generator has drawn
  SynthesisState st = deserialize_state(whole.checkpoints[2], "test");
  REQUIRE(st.iteration > 0);
  REQUIRE_FALSE(st.optimizer.empty());
  const std::string intact = serialize_state(st);
  CHECK(same_bits(synthesize(ex, &intact).output, whole.output));  // the round trip itself changes nothing

  SynthesisState rng = st;  // the generator one draw ahead
  std::mt19937_64 g;
  std::istringstream(rng.rng) >> g;
  g();
  std::ostringstream os;
  os << g;
  rng.rng = os.str();
  const std::string rng_bytes = serialize_state(rng);
  CHECK_FALSE(same_bits(synthesize(ex, &rng_bytes).output, whole.output));

  SynthesisState fresh_optimizer = st;  // Adam's moments lost
  fresh_optimizer.optimizer.clear();
  const std::string opt_bytes = serialize_state(fresh_optimizer);
  CHECK_FALSE(same_bits(synthesize(ex, &opt_bytes).output, whole.output));

  SynthesisState nudged = st;  // one position one ulp off
  nudged.moving = st.moving.clone();
  float* p = nudged.moving.data_ptr<float>();
  p[0] = std::nextafter(p[0], 2.0f);
  const std::string pos_bytes = serialize_state(nudged);
  CHECK_FALSE(same_bits(synthesize(ex, &pos_bytes).output, whole.output));
}

TEST_CASE("a checkpoint of another synthesis is refused", "[optim][checkpoint]") {
  const Run one = synthesize(test::small_exemplar(1, false));
  const PointSet other = test::small_exemplar(2, false);
  CHECK_THROWS_AS(synthesize(other, &one.checkpoints[1]), InputError);
  const std::string garbage = "not a checkpoint";
  CHECK_THROWS_WITH(synthesize(other, &garbage), Catch::Contains("checkpoint"));
}
