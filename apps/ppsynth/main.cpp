// `ppsynth`: the command-line front of the framework. Subcommands register themselves
// (apps/ppsynth/analysis/*.cpp, apps/ppsynth/synthesis/*.cpp); this file only parses the
// global flags, dispatches, and turns errors into messages and exit codes -- one code per
// class, as kExitStatus says (`ppsynth --help` prints it):
//   0 done; 2 a usage error (the parser's, an unknown command or option, a value out of
//   range) or an input error (InputError: a file, key or line named; a path; memory);
//   130 / 143 stopped by SIGINT / SIGTERM; 3 an internal error (a bug); 1 `sweep run`: some
//   of its runs failed (their logs say why).
// Messages are one line: never a C++ backtrace or an exception's internal name.
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "apps/ppsynth/command.hpp"
#include "core/error.hpp"
#include "core/plain_message.hpp"
#include "core/log.hpp"
#include "core/revision.hpp"
#ifdef PPSYNTH_WITH_TORCH
#include <c10/util/Exception.h>
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

namespace {

const char* kExitStatus =
    "Exit status: 0 done; 2 a usage or input error (the message names the option, file, key or line; "
    "nothing is half-written); 130 / 143 stopped by SIGINT / SIGTERM (a command that checkpoints says where "
    "its checkpoint is); 3 an internal error (a bug of ppsynth: please report it); 1 `sweep run`: some of its "
    "runs failed (each run's log says why).";

// The command named on the line (the first word that is not a global flag), or "".
std::string named_command(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return "";
}

// A command made of subcommands (`sweep plan|run|status|task`) and the word after it that is
// not a flag, when that word names none of them: CLI11 would say "A subcommand is required".
// Returns the message, or "" when the line is fine (or asks for --help).
std::string unknown_subcommand(int argc, char** argv, const std::string& command, CLI::App& sub) {
  const std::vector<CLI::App*> subs = sub.get_subcommands([](CLI::App*) { return true; });
  if (subs.empty()) return "";
  std::string names;
  for (const CLI::App* s : subs) names += (names.empty() ? "" : ", ") + s->get_name();
  int i = 1;
  while (i < argc && argv[i] != command) ++i;
  for (++i; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "-h" || word == "--help") return "";
    if (word.empty() || word[0] != '-') {
      for (const CLI::App* s : subs)
        if (s->get_name() == word) return "";
      return "'" + word + "' is not a " + command + " subcommand; they are " + names;
    }
  }
  return "name a subcommand: " + names;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ppsynth;
  CLI::App cli{"ppsynth: by-example point-pattern synthesis and analysis (revision " +
               std::string(revision()) + ")"};
  cli.require_subcommand(1);
  cli.footer(kExitStatus);
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
  // An unknown command: CLI11 would say that a subcommand is required.
  if (const std::string named = named_command(argc, argv); !named.empty() && !app::commands().count(named)) {
    std::string known;
    for (const auto& [name, entry] : app::commands()) known += (known.empty() ? "" : ", ") + name;
    std::cerr << "ppsynth: unknown command '" << named << "'; the commands are " << known << " (ppsynth --help)\n";
    return 2;
  }
  if (const std::string named = named_command(argc, argv); !named.empty()) {
    if (const std::string why = unknown_subcommand(argc, argv, named, *subs[named]); !why.empty()) {
      std::cerr << "ppsynth " << named << ": " << why << " (ppsynth " << named << " --help)\n";
      return 2;
    }
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {  // a usage error: exit 2 like every other refused input
    const std::string named = named_command(argc, argv);
    std::cerr << "ppsynth" << (named.empty() ? "" : " " + named) << ": " << plain_message(e.what()) << " (ppsynth "
              << (named.empty() ? "" : named + " ") << "--help)\n";
    return 2;
  }
  configure_logging(verbose - quiet);
  for (auto& [name, sub] : subs) {
    if (!sub->parsed()) continue;
    try {
      // A command that synthesizes configures LibTorch itself (optim/run/runtime.hpp), so that
      // a variable only a synthesis reads (PPSYNTH_THREADS, PPSYNTH_GABOR_MAPS) stops no other.
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
#ifdef PPSYNTH_WITH_TORCH
    } catch (const c10::Error& e) {  // LibTorch's: its message without the C++ backtrace
      std::cerr << "ppsynth " << name << ": internal error (a bug of ppsynth; please report it): "
                << plain_message(e.what_without_backtrace()) << "\n";
      return 3;
#endif
    } catch (const std::exception& e) {
      std::cerr << "ppsynth " << name << ": internal error (a bug of ppsynth; please report it): " << plain_message(e.what())
                << "\n";
      return 3;
    }
  }
  return 1;
}
