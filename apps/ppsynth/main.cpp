// `ppsynth`: the command-line front of the framework. Subcommands register themselves
// (apps/ppsynth/analysis/*.cpp, apps/ppsynth/synthesis/*.cpp); this file only parses the
// global flags, dispatches, and turns errors into messages and exit codes.
#include <filesystem>
#include <iostream>
#include <new>
#include <thread>
#include <limits>
#include <string>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#ifdef PPSYNTH_WITH_TORCH
#include <torch/torch.h>
#endif

#include "apps/ppsynth/command.hpp"
#include "core/error.hpp"
#include "core/log.hpp"

namespace ppsynth::app {

std::map<std::string, CommandEntry>& commands() {
  static std::map<std::string, CommandEntry> c;
  return c;
}

bool register_command(const std::string& name, const std::string& description, SetupFn setup) {
  commands().emplace(name, CommandEntry{description, std::move(setup)});
  return true;
}

}  // namespace ppsynth::app

// glibc hands freed blocks above its trim threshold back to the kernel and serves blocks
// above its mmap threshold (at most 32 MiB) from fresh mappings, so every synthesis
// iteration page-faults its activation buffers in again. Measured with `ppsynth bench` on
// lines, idle machine: 256 x 256 output grid, one iteration 1.71 s -> 1.20 s (network
// backward 0.76 -> 0.45 s); 512 x 512, 5.8 s -> 3.7 s. So everything comes from the heap
// and freed memory stays there for reuse (peak resident memory at 512 x 512: 1655 -> 2085
// MiB; it is returned when the process ends). PPSYNTH_MALLOC=system keeps glibc's defaults.
void keep_freed_memory() {
#ifdef __GLIBC__
  const char* env = std::getenv("PPSYNTH_MALLOC");
  if (env && std::string(env) == "system") return;
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
  mallopt(M_TOP_PAD, 64 << 20);
#endif
}

int main(int argc, char** argv) {
  using namespace ppsynth;
  CLI::App cli{"ppsynth: by-example point-pattern synthesis and analysis (revision " +
               std::string(app::revision()) + ")"};
  cli.require_subcommand(1);
  int verbose = 0, quiet = 0;
  cli.add_flag("-v,--verbose", verbose, "more log output (repeat for trace)");
  cli.add_flag("-q,--quiet", quiet, "less log output (repeat for errors only)");
  cli.set_version_flag("--version", std::string(app::revision()));

  std::map<std::string, app::RunFn> runs;
  std::map<std::string, CLI::App*> subs;
  for (auto& [name, entry] : app::commands()) {
    CLI::App* sub = cli.add_subcommand(name, entry.description);
    // Global flags are accepted after the subcommand too ("ppsynth eval ... -v").
    sub->add_flag("-v,--verbose", verbose, "more log output");
    sub->add_flag("-q,--quiet", quiet, "less log output");
    runs[name] = entry.setup(*sub);
    subs[name] = sub;
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  configure_logging(verbose - quiet);
  keep_freed_memory();
  for (auto& [name, sub] : subs) {
    if (!sub->parsed()) continue;
    try {
#ifdef PPSYNTH_WITH_TORCH
      // Debian's LibTorch starts with one intra-op thread: use every core (PPSYNTH_THREADS
      // overrides; run.json records the count, since results depend on it in the last bits).
      int threads = static_cast<int>(std::thread::hardware_concurrency());
      if (const char* env = std::getenv("PPSYNTH_THREADS")) {
        char* end = nullptr;
        const long v = std::strtol(env, &end, 10);
        if (end == env || *end != '\0' || v < 1 || v > 1024)
          throw InputError(std::string("PPSYNTH_THREADS='") + env + "': expected a whole number from 1 to 1024");
        threads = static_cast<int>(v);
      }
      if (threads > 0) torch::set_num_threads(threads);
#endif
      return runs[name]();
    } catch (const InputError& e) {
      std::cerr << "ppsynth " << name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::filesystem::filesystem_error& e) {  // a path the user gave: its message names it
      std::cerr << "ppsynth " << name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::bad_alloc&) {  // sizes are checked up front (core/memory_budget.hpp); this is what slips through
      std::cerr << "ppsynth " << name << ": ran out of memory; reduce the point count, grid resolution or upscaling\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "ppsynth " << name << ": internal error: " << e.what() << "\n";
      return 3;
    }
  }
  return 1;
}
