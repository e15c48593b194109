// Checkpoint and resume of the Gabor engine, in process: a run restored from any of its
// checkpoints (mid-stage or at a stage boundary) ends with the very bits of the run that was
// never stopped; and the comparison is sharp enough to see a wrong generator, wrong moments
// or a one-ulp position change in the restored state.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <sstream>

#include "core/checkpoint_file.hpp"
#include "core/content_hash.hpp"
#include "core/generators/lattices.hpp"
#include "core/metrics/pcf.hpp"
#include "optim/method/method.hpp"
#include "optim/gabor/stages/synthesis_state.hpp"
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

// Sets the stop flag at the first iteration it is told of: the run stops at that iteration's
// end (a flag set before the start stops it before any work, with nothing to save).
struct StopAtFirstIteration : SynthesisObserver {
  std::atomic<bool> stop{false};
  void on_iteration(const ProgressEvent&) override { stop = true; }
};

// A run (resumed from `resume` when given) stopped at the end of its first iteration: it
// throws SynthesisInterrupted, its checkpoint in `saved`.
void stop_after_one_iteration(const PointSet& ex, const std::string* resume, std::vector<std::string>& saved) {
  StopAtFirstIteration first;
  auto method = MethodRegistry::instance().create(kQuickMethod, "method");
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 5;
  ctx.checkpoint_seconds = 1e9;
  ctx.save_checkpoint = [&](const std::string& bytes) { saved.push_back(bytes); };
  ctx.resume_state = resume;
  ctx.stop = &first.stop;
  ctx.observers = {&first};
  method->synthesize(ex, ctx);
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
      REQUIRE(resumed.report.stages.size() == whole.report.stages.size());
      // per-stage iterations and final losses are the same too (seconds aside)
      for (size_t s = 0; s < whole.report.stages.size(); ++s) {
        CHECK(resumed.report.stages[s].iterations == whole.report.stages[s].iterations);
        CHECK(resumed.report.stages[s].final_loss == whole.report.stages[s].final_loss);
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
  REQUIRE(whole.report.stages.size() == 2);
  const int first_stage = whole.report.stages[0].iterations;
  CHECK(whole.stats["output_grid_res_per_sigma"][0] < whole.stats["output_grid_res_per_sigma"][1]);
  CHECK(first_stage < 80);  // stopped by the rule, not the cap
  for (size_t i : {size_t{7}, size_t{12}, whole.checkpoints.size() / 2}) {
    INFO("checkpoint " << i);
    const Run resumed = synthesize(ex, &whole.checkpoints[i], nullptr, spec);
    CHECK(same_bits(resumed.output, whole.output));
    CHECK(resumed.report.stages[0].iterations == first_stage);
    CHECK(resumed.report.stages[1].iterations == whole.report.stages[1].iterations);
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
  REQUIRE(best.report.stages[0].iterations == 60);  // both ran to the cap: same trajectory
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

TEST_CASE("a judged stage's record says what the pattern rule saw and the iterate it ended on, resumed or not",
          "[optim][checkpoint]") {
  json spec = kQuickMethod;
  spec["quick"]["max_iterations"] = 60;
  spec["quick"]["num_sigmas"] = 1;
  spec["convergence"] = {{"type", "pattern"}, {"window", 1000}, {"check_every", 5}, {"min_iterations", 0}};
  spec["border_relax"] = {{"iterations", 0}};
  const PointSet ex = test::small_exemplar(1, false);
  const Run last = synthesize(ex, nullptr, nullptr, spec);
  const json& on_last = last.report.stages[0].details.at("stopping_rule");
  CHECK(on_last.at("check_every") == 5);
  CHECK(on_last.at("pcf_mse").size() == 12);  // iterations 4, 9, ..., 59: the start is no candidate
  CHECK_FALSE(on_last.contains("ended_on_iteration"));

  spec["convergence"]["end_on"] = "best";
  const Run best = synthesize(ex, nullptr, nullptr, spec);
  const json& on_best = best.report.stages[0].details.at("stopping_rule");
  const auto measures = on_best.at("pcf_mse").get<std::vector<double>>();
  REQUIRE(measures.size() == 13);  // the start, then every 5th iteration
  CHECK(measures[1] == on_last.at("pcf_mse")[0].get<double>());  // the same trajectory, the same checks
  // The torus is chosen on the plane rectangle (a second list); the stage ended on its minimum.
  const auto chosen = on_best.at("pcf_mse_chosen_by").get<std::vector<double>>();
  REQUIRE(chosen.size() == measures.size());
  const int first_min = static_cast<int>(std::min_element(chosen.begin(), chosen.end()) - chosen.begin());
  CHECK(on_best.at("ended_on_iteration") == first_min * 5 - 1);
  CHECK(on_best.at("ended_on_iteration").get<int>() < 59);  // the test above: this trajectory's best is not its last
  // A stage resumed midway reads the same from the checkpointed record.
  const Run resumed = synthesize(ex, &best.checkpoints[20], nullptr, spec);
  CHECK(resumed.report.stages[0].details.at("stopping_rule") == on_best);
}

TEST_CASE("the stop flag saves a checkpoint and throws; resuming from it finishes the run", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, false);
  const Run whole = synthesize(ex);
  Run stopped;
  CHECK_THROWS_AS(stop_after_one_iteration(ex, nullptr, stopped.checkpoints), SynthesisInterrupted);
  REQUIRE(stopped.checkpoints.size() == 1);
  CHECK(deserialize_state(stopped.checkpoints[0], "t").iteration == 1);
  CHECK(same_bits(synthesize(ex, &stopped.checkpoints[0]).output, whole.output));
}

TEST_CASE("the resume comparison sees a perturbed generator, optimizer or position", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(1, false);
  const Run whole = synthesize(ex);
  // a checkpoint in the middle of the first stage: the optimizer has moments, the generator has drawn
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

namespace {

// The checkpoint `bytes` with its state changed by `edit`, written back whole (checksum and all):
// what a crafted file holds, to reach the checks behind the checksum.
std::string edited(const std::string& bytes, const std::function<void(SynthesisState&)>& edit) {
  SynthesisState s = deserialize_state(bytes, "test");
  edit(s);
  return serialize_state(s);
}

}  // namespace

TEST_CASE("a restored state is checked against the plan: indices, counts, flags, finite values", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, true);
  const Run whole = synthesize(ex);
  const std::string& mid = whole.checkpoints[2];  // inside the first stage: moving points, optimizer moments
  {
    const SynthesisState st = deserialize_state(mid, "test");
    REQUIRE(st.moving.defined());
    REQUIRE_FALSE(st.optimizer.empty());
    REQUIRE(st.iteration > 0);
  }
  struct Case {
    const char* what;
    std::function<void(SynthesisState&)> edit;
  };
  const std::vector<Case> cases = {
      // The defect: an index out of range made map_weights read past the output (SIGSEGV).
      {"point index", [](SynthesisState& s) { s.group_moving[0] = 1000000; }},
      {"point index", [](SynthesisState& s) { s.group_frozen.push_back(-3); }},
      {"twice", [](SynthesisState& s) { s.group_moving[1] = s.group_moving[0]; }},
      {"moving positions for", [](SynthesisState& s) { s.group_moving.pop_back(); }},
      {"outside the synthesis domain", [](SynthesisState& s) { s.positions[4].x = 7.5; }},
      {"points; this synthesis has", [](SynthesisState& s) { s.positions.pop_back(); }},
      {"stage", [](SynthesisState& s) { s.stage = 1000; }},
      {"iteration", [](SynthesisState& s) { s.iteration = 100000; }},
      {"losses recorded", [](SynthesisState& s) { s.stage_losses.push_back(1.0); }},
      {"a loss recorded at stage", [](SynthesisState& s) { s.history[0].stage = 999; }},
      {"finished stages", [](SynthesisState& s) { s.stages.push_back(StageRecord{}); }},
      {"not finite", [](SynthesisState& s) { s.moving[0][0] = std::nanf(""); }},
      {"not finite", [](SynthesisState& s) { s.stage_losses[0] = INFINITY; }},
      {"optimizer state 'exp_avg'", [](SynthesisState& s) { s.optimizer["exp_avg"] = torch::zeros({3, 2}); }},
      {"optimizer state 'exp_avg_sq'", [](SynthesisState& s) { s.optimizer["exp_avg_sq"] = -s.optimizer["exp_avg_sq"] - 1; }},
      {"optimizer state 'step'", [](SynthesisState& s) { s.optimizer["step"] = torch::tensor(int64_t{0}); }},
      {"optimizer state 'momentum'", [](SynthesisState& s) { s.optimizer["momentum"] = torch::zeros({1}); }},
      {"best iterate", [](SynthesisState& s) { s.stage_best = torch::zeros({1, 2}); }},
      {"generator", [](SynthesisState& s) { s.rng = "not a generator"; }},
  };
  for (const Case& c : cases) {
    const std::string bytes = edited(mid, c.edit);
    INFO(c.what);
    CHECK_THROWS_AS(synthesize(ex, &bytes), CheckpointError);
    CHECK_THROWS_WITH(synthesize(ex, &bytes), Catch::Contains(c.what));
  }
  // Intact, the round trip resumes to the same bits.
  const std::string same = edited(mid, [](SynthesisState&) {});
  CHECK(same_bits(synthesize(ex, &same).output, whole.output));
}

TEST_CASE("a finished stage's record is checked when a run resumes: the engine's fields, then its kind's", "[optim][checkpoint][border_relax]") {
  const PointSet ex = test::small_exemplar(2, true);
  const Run whole = synthesize(ex);
  // Inside the last stage: every earlier stage's record is in it, the relaxes' among them.
  const std::string& late = whole.checkpoints[whole.checkpoints.size() - 2];
  size_t relax = 0;
  {
    const SynthesisState st = deserialize_state(late, "test");
    while (relax < st.stages.size() && !st.stages[relax].details.contains("relaxed")) ++relax;
    REQUIRE(relax < st.stages.size());
  }
  struct Case {
    const char* what;
    std::function<void(SynthesisState&)> edit;
  };
  const std::vector<Case> cases = {
      {"'k' is not a whole number", [](SynthesisState& s) { s.stages[0].details["k"] = "two"; }},
      {"'sigma' is not a number", [](SynthesisState& s) { s.stages[0].details.erase("sigma"); }},
      {"'relaxed' is not true or false", [&](SynthesisState& s) { s.stages[relax].details["relaxed"] = "yes"; }},
      {"'parked_over_uniform' is not a number", [&](SynthesisState& s) { s.stages[relax].details["parked_over_uniform"] = "x"; }},
  };
  for (const Case& c : cases) {
    const std::string bytes = edited(late, c.edit);
    INFO(c.what);
    CHECK_THROWS_AS(synthesize(ex, &bytes), CheckpointError);
    CHECK_THROWS_WITH(synthesize(ex, &bytes), Catch::Contains(c.what));
  }
}

TEST_CASE("random bytes changed in a checkpoint (checksum mended) never crash a resume", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, true);
  const Run whole = synthesize(ex);
  const std::string& mid = whole.checkpoints[3];
  std::mt19937_64 rng(7);
  int refused = 0, resumed = 0;
  for (int trial = 0; trial < 150; ++trial) {
    std::string bytes = mid;
    const size_t at = 19 + rng() % (bytes.size() - 27);  // past the magic, before the checksum
    bytes[at] = static_cast<char>(bytes[at] ^ (1 + rng() % 255));
    const uint64_t h = fnv1a64(bytes.data(), bytes.size() - 8);
    std::memcpy(&bytes[bytes.size() - 8], &h, 8);
    try {  // each trial restores, runs an iteration at most, and stops
      std::vector<std::string> saved;
      stop_after_one_iteration(ex, &bytes, saved);
      ++resumed;
    } catch (const InputError&) {
      ++refused;
    } catch (const SynthesisInterrupted&) {
      ++resumed;
    }
  }
  INFO(refused << " refused, " << resumed << " resumed");
  CHECK(refused + resumed == 150);
  CHECK(refused > 0);
}

TEST_CASE("a checkpoint carries its synthesis's key; another key is refused, naming what differs", "[optim][checkpoint]") {
  const PointSet ex = test::small_exemplar(1, false);
  auto run_keyed = [&](const json& key, const std::string* resume, std::vector<std::string>* saved) {
    auto method = MethodRegistry::instance().create(kQuickMethod, "method");
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = 5;
    ctx.checkpoint_seconds = 0;
    ctx.checkpoint_key = key;
    ctx.resume_state = resume;
    ctx.resume_source = "run/checkpoint.bin";
    ctx.save_checkpoint = [&](const std::string& b) {
      if (saved) saved->push_back(b);
    };
    return method->synthesize(ex, ctx);
  };
  const json key = {{"method", "gabor"}, {"method_version", 1}, {"seed", 5}, {"quick", true}, {"exemplar", "e"}};
  std::vector<std::string> saved;
  const PointSet out = run_keyed(key, nullptr, &saved);
  REQUIRE(saved.size() > 2);
  CHECK(deserialize_state(saved[1], "t").key == key);
  CHECK(same_bits(run_keyed(key, &saved[1], nullptr), out));
  json other = key;
  other["seed"] = 6;
  CHECK_THROWS_WITH(run_keyed(other, &saved[1], nullptr),
                    Catch::Contains("run/checkpoint.bin") && Catch::Contains("seed 6 (the checkpoint's: 5)"));
}

TEST_CASE("L-BFGS's state resumes bit for bit too", "[optim][checkpoint]") {
  json spec = kQuickMethod;
  spec["optimizer"] = {{"type", "lbfgs"}, {"max_iter", 3}};
  const PointSet ex = test::small_exemplar(1, false);
  const Run whole = synthesize(ex, nullptr, nullptr, spec);
  REQUIRE(whole.checkpoints.size() > 4);
  const SynthesisState st = deserialize_state(whole.checkpoints[2], "test");
  REQUIRE(st.optimizer.count("old_dirs"));
  for (size_t i : {size_t{1}, size_t{2}, whole.checkpoints.size() / 2}) {
    INFO("checkpoint " << i);
    CHECK(same_bits(synthesize(ex, &whole.checkpoints[i], nullptr, spec).output, whole.output));
  }
}

TEST_CASE("a checkpoint keeps the run's CPU time; a resume adds it, or says it is unknown when the checkpoint has none",
          "[optim][checkpoint][cpu_seconds]") {
  const PointSet ex = test::small_exemplar(2, false);
  const Run whole = synthesize(ex);
  CHECK(whole.report.cpu_seconds_before_resume == 0);  // nothing before an uninterrupted run
  const std::string& mid = whole.checkpoints[whole.checkpoints.size() / 2];
  const SynthesisState st = deserialize_state(mid, "test");
  REQUIRE(st.phase_seconds.contains("cpu"));
  const double cpu = st.phase_seconds["cpu"].get<double>();
  CHECK(cpu >= 0);  // a recorded time, not a speed: its size is no test's business
  CHECK(synthesize(ex, &mid).report.cpu_seconds_before_resume == cpu);
  // A checkpoint made before the CPU time was kept (2026-11-30) resumes as before, its CPU time unknown:
  // -1, which the run records as "not recorded" (0), never as a small number that a timing rule would pass.
  SynthesisState old = st;
  old.phase_seconds.erase("cpu");
  const std::string old_bytes = serialize_state(old);
  const Run resumed = synthesize(ex, &old_bytes);
  CHECK(resumed.report.cpu_seconds_before_resume == -1);
  CHECK(same_bits(resumed.output, whole.output));
  for (size_t i = 0; i < resumed.checkpoints.size(); ++i)  // and it stays unknown through later resumes
    CHECK_FALSE(deserialize_state(resumed.checkpoints[i], "test").phase_seconds.contains("cpu"));
}
