// `ppsynth synthesize [CONFIG] [--exemplar FILE] [-o RUN_DIR] [--set key=value ...]`
// `ppsynth synthesize --resume RUN_DIR [--force]`  (--force: afresh from its config.json)
// `--size W H` / `--points N`: an output of that size (exemplar sides) or point count instead of
// the paper's u x u unit square (the config's "output"; core/output_shape.hpp).
// Runs one synthesis (default method: the paper's, with the published settings) and writes a
// run directory (see run_synthesis.hpp). SIGINT and SIGTERM stop it at the end of the current
// iteration with a checkpoint; the command prints how to resume and exits 130 / 143 (a second
// signal ends it at once).
#include <csignal>
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "apps/ppsynth/stop_signals.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_spec.hpp"
#include "optim/run/run_synthesis.hpp"
#include "optim/run/runtime.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/shell_quote.hpp"

namespace {

struct Opts {
  std::string config, exemplar, out, method, init, format, resume, preset, device, seed;
  std::vector<std::string> sets;
  std::vector<double> size;
  long long points = -1;
  bool quick = false, force = false;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  app.add_option("config", o->config, "experiment config (JSON); optional with --exemplar")->check(ppsynth::app::path_text());
  app.add_option("--exemplar,-e", o->exemplar, "exemplar point file (overrides the config's)")
      ->check(ppsynth::app::path_text());
  app.add_option("--format", o->format, "exemplar format: auto | gabor | point-synthesis | plain | json");
  app.add_option("-o,--out", o->out, "run directory (default runs/<name>); must be new or empty")
      ->check(ppsynth::app::path_text());
  app.add_flag("--force", o->force, "replace the run directory if it holds a run of ppsynth (with --resume: start that run afresh from its config.json)");
  app.add_option("--resume", o->resume, "continue the unfinished run in this directory from its last checkpoint")
      ->check(ppsynth::app::path_text());
  app.add_option("--method,-m", o->method, "synthesis method (gabor, roveri2015, pcf2017, ...)");
  app.add_option("--set", o->sets, "override a config key: key.path=value (repeatable)");
  app.add_option("--seed", o->seed, "random seed, a whole number from 0 to 2^63 - 1")->check(ppsynth::app::seed_number());
  app.add_option("--preset", o->preset, "a named preset under the config's own keys: fast (`ppsynth config --kind preset`)");
  app.add_option("--init", o->init, "explicit initialization point file")->check(ppsynth::app::path_text());
  app.add_option("--device", o->device, "where the synthesis runs: cpu (default), cuda, cuda:N or auto (runtime.device)");
  app.add_flag("--quick", o->quick, "tiny grid and few iterations (smoke test)");
  auto* size = app.add_option("--size", o->size, "output rectangle W H in exemplar sides: W exemplar widths by H exemplar heights (clean borders)")
                   ->expected(2)
                   ->check(ppsynth::app::positive_number());
  app.add_option("--points", o->points, "output of about N points (a square at the exemplar's density)")
      ->check(ppsynth::app::whole_number(1, 1000000000000ull))
      ->excludes(size);
  return [o]() -> int {
    using namespace ppsynth;
    RunRequest req;
    req.dir = o->out;
    req.quick = o->quick;
    req.force = o->force;
    req.stop = ppsynth::app::stop_flag();
    configure_runtime();  // threads, allocator, the Gabor maps' path: optim/run/runtime.hpp
    try {
      if (!o->resume.empty()) {
        if (!o->config.empty() || !o->exemplar.empty() || !o->out.empty() || !o->sets.empty() || !o->seed.empty() ||
            !o->method.empty() || !o->init.empty() || !o->format.empty() || o->quick || !o->size.empty() || o->points >= 0 ||
            !o->preset.empty() || !o->device.empty())
          throw InputError("--resume takes the run directory alone (and --force to start it afresh): its config, seed and "
                           "settings are the run's own");
        ppsynth::app::install_stop_handlers();
        std::cout << resume_synthesis(o->resume, req).dir << "\n";
        return 0;
      }
      json c = o->config.empty() ? json::object() : load_config(o->config);
      // Each flag sets a config key; a --set of the same key would silently win over it.
      std::vector<std::pair<std::string, std::string>> flags;
      auto flag = [&](const std::string& given, const std::string& name, const std::string& key, json value) {
        if (given.empty()) return;
        flags.emplace_back(name + " " + given, key);
        set_at_key_path(c, key, std::move(value));
      };
      flag(o->exemplar, "--exemplar", "exemplar", o->exemplar);
      flag(o->format, "--format", "format", o->format);
      if (!o->method.empty()) {  // the whole method object: the config's method parameters are for its own type
        flags.emplace_back("--method " + o->method, "method.type");
        c["method"] = json{{"type", o->method}};
      }
      if (!o->seed.empty()) flag(o->seed, "--seed", "seed", std::stoull(o->seed));  // digits below 2^63 (seed_number)
      flag(o->init, "--init", "init_file", o->init);
      if (!o->size.empty()) flag(json(o->size).dump(), "--size", "output.size", o->size);
      if (o->points >= 0) flag(std::to_string(o->points), "--points", "output.points", o->points);
      flag(o->preset, "--preset", "preset", o->preset);
      flag(o->device, "--device", "runtime.device", o->device);
      ppsynth::app::refuse_set_conflicts(o->sets, flags);
      auto resolved = resolve_run_config(c, o->sets);
      // --force empties the run directory: an input inside it would be lost with it.
      if (o->force) {
        const json& exemplar = resolved["exemplar"];
        ppsynth::app::check_inputs_outside({"-o", o->out}, {{"config", o->config},
                                                            {"exemplar", exemplar.is_string() ? exemplar.get<std::string>() : ""},
                                                            {"--init", o->init}});
      }
      // The exemplar read and the shape, seed and method resolved once, for every step of the run.
      const RunSpec spec = load_run_spec(resolved);
      if (spec.method->can_resume()) ppsynth::app::install_stop_handlers();  // others stop at once, as without handlers
      std::cout << run_synthesis(spec, req).dir << "\n";
      return 0;
    } catch (const RunInterrupted& e) {
      if (e.dir.empty())
        std::cerr << "ppsynth synthesize: stopped by " << ppsynth::app::stop_signal_name()
                  << " before the first checkpoint; nothing was kept\n";
      else
        std::cerr << "ppsynth synthesize: stopped by " << ppsynth::app::stop_signal_name() << "; the checkpoint is in " << e.dir
                  << ". Continue with:\n  ppsynth synthesize --resume " << ppsynth::shell_quoted(e.dir) << "\n";
      return ppsynth::app::exit_code_for_stop();
    }
  };
}

}  // namespace

PPSYNTH_COMMAND("synthesize", "synthesize a larger pattern from an exemplar (writes a run directory)", setup)
