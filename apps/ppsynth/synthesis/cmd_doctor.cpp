// `ppsynth doctor [--grid R] [--reps N] [--json FILE]`: what this machine gives a synthesis:
// processor class and ISA caps, native or emulated bf16, threads, the BLAS loaded, both
// convolution floors and the network precision each preset takes here
// (optim/run/machine_report.hpp). A few seconds on a CPU without bf16 units (its bf16 floor is
// emulated); no test asserts on the figures.
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "core/atomic_file.hpp"
#include "optim/run/machine_report.hpp"
#include "optim/run/runtime.hpp"

namespace {

using namespace ppsynth;

struct Opts {
  int grid = 128, reps = 3;
  std::string json_out;
};

app::RunFn setup(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  app.add_option("--grid", o->grid, "grid of the floors' convolution (0: leave the floors out)")->check(CLI::Range(0, 1024));
  app.add_option("--reps", o->reps, "repetitions per floor (the fastest is kept)")->check(CLI::Range(1, 100));
  app.add_option("--json", o->json_out, "also write the report as JSON");
  return [o]() {
    configure_runtime();  // the threads it reports are a synthesis's: optim/run/runtime.hpp
    if (!o->json_out.empty()) check_writable(o->json_out);  // before the floors are measured, not after
    const MachineReport m = machine_report(o->grid, o->reps);
    std::cout << m.text();
    if (!o->json_out.empty()) write_text_atomic(o->json_out, m.to_json().dump(2) + "\n");
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("doctor", "what this machine gives a synthesis: ISA, bf16, threads, BLAS, floors, each preset's precision", setup)
