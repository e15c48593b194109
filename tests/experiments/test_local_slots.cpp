// Several runs on one card: how many sweep tasks the local executor starts at once
// and which card each sees (plan_local_slots, a pure function of the machine and the rows).
#include <catch2/catch.hpp>

#include "experiments/execute/sweep_executors.hpp"

using namespace ppsynth;
using Catch::Matchers::Contains;

namespace {
constexpr double GiB = 1024.0 * 1024 * 1024;
}

TEST_CASE("CPU rows run one at a time unless -j says more, the cores split between them", "[executor]") {
  LocalExecution how;
  LocalMachine m;
  m.cores = 8;
  m.card_memory_bytes = {141 * GiB};  // a card, but the rows stay on the CPU
  LocalWork w;
  w.rows = 5;
  w.run_memory_bytes = 4 * GiB;
  LocalSlots s = plan_local_slots(how, m, w);
  CHECK(s.jobs == 1);
  CHECK(s.threads == 8);
  CHECK(s.runs_per_device == 0);
  CHECK(s.card_of_slot == std::vector<int>{-1});
  how.jobs = 3;
  s = plan_local_slots(how, m, w);
  CHECK(s.jobs == 3);
  CHECK(s.threads == 2);
  m.env_threads = 1;  // the user's PPSYNTH_THREADS wins over the split
  CHECK(plan_local_slots(how, m, w).threads == 1);
}

TEST_CASE("CUDA rows share one card: as many as its memory holds, at most its share of the cores, at most the rows", "[executor]") {
  LocalExecution how;
  LocalMachine m;
  m.cores = 16;
  m.card_memory_bytes = {141 * GiB};
  LocalWork w;
  w.on_cuda = true;
  w.rows = 5;
  w.run_memory_bytes = 4 * GiB;
  LocalSlots s = plan_local_slots(how, m, w);
  CHECK(s.runs_per_device == 16);  // 31 fit in 90 % of the card; 16 cores
  CHECK(s.jobs == 5);              // five rows
  CHECK(s.threads == 3);
  CHECK(s.card_of_slot == std::vector<int>(5, -1));  // one card: nothing to pick
  CHECK_THAT(s.reason, Contains("16 per card") && Contains("5 at once on 1 card"));
  w.rows = 100;
  w.run_memory_bytes = 40 * GiB;  // 3 fit
  s = plan_local_slots(how, m, w);
  CHECK(s.runs_per_device == 3);
  CHECK(s.jobs == 3);
  w.run_memory_bytes = 400 * GiB;  // not even one: one at a time
  CHECK(plan_local_slots(how, m, w).jobs == 1);
  how.runs_per_device = 2;  // as asked
  CHECK(plan_local_slots(how, m, w).jobs == 2);
  m.card_memory_bytes = {0};  // memory unknown
  how.runs_per_device = 0;
  CHECK(plan_local_slots(how, m, w).runs_per_device == 1);
}

TEST_CASE("With several cards each task is given one, in turn, unless a row names its card", "[executor]") {
  LocalExecution how;
  how.runs_per_device = 2;
  LocalMachine m;
  m.cores = 16;
  m.card_memory_bytes = {80 * GiB, 80 * GiB};
  LocalWork w;
  w.on_cuda = true;
  w.rows = 10;
  w.run_memory_bytes = 4 * GiB;
  LocalSlots s = plan_local_slots(how, m, w);
  CHECK(s.jobs == 4);
  CHECK(s.threads == 4);
  CHECK(s.card_of_slot == std::vector<int>{0, 1, 0, 1});
  w.any_card = false;  // a row says cuda:1: its device number must keep its meaning
  CHECK(plan_local_slots(how, m, w).card_of_slot == std::vector<int>(4, -1));
}
