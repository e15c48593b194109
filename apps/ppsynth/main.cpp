// `ppsynth`: the command-line front of the framework. Subcommands register themselves
// (apps/ppsynth/analysis/*.cpp, apps/ppsynth/synthesis/*.cpp); this file only parses the
// global flags, dispatches, and turns errors into messages and exit codes.
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include "apps/ppsynth/command.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/revision.hpp"
#ifdef PPSYNTH_WITH_TORCH
#include "optim/run/runtime.hpp"
#endif

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

int main(int argc, char** argv) {
  using namespace ppsynth;
  CLI::App cli{"ppsynth: by-example point-pattern synthesis and analysis (revision " +
               std::string(revision()) + ")"};
  cli.require_subcommand(1);
  int verbose = 0, quiet = 0;
  cli.add_flag("-v,--verbose", verbose, "more log output (repeat for trace)");
  cli.add_flag("-q,--quiet", quiet, "less log output (repeat for errors only)");
  cli.set_version_flag("--version", std::string(revision()));

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
  for (auto& [name, sub] : subs) {
    if (!sub->parsed()) continue;
    try {
#ifdef PPSYNTH_WITH_TORCH
      configure_runtime();  // threads (PPSYNTH_THREADS) and allocator: optim/run/runtime.hpp
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
