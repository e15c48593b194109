// `ppsynth synthesize [CONFIG] [--exemplar FILE] [-o RUN_DIR] [--set key=value ...]`
// Runs one synthesis (default method: the paper's, with the published settings) and writes a
// run directory (see run_synthesis.hpp).
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/synthesis/run_config.hpp"
#include "apps/ppsynth/synthesis/run_synthesis.hpp"
#include "core/config/config.hpp"

namespace {

struct Opts {
  std::string config, exemplar, out, method, init, format;
  std::vector<std::string> sets;
  long long seed = -1;
  bool quick = false;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  app.add_option("config", o->config, "experiment config (JSON); optional with --exemplar");
  app.add_option("--exemplar,-e", o->exemplar, "exemplar point file (overrides the config's)");
  app.add_option("--format", o->format, "exemplar format: auto | gabor | point-synthesis | plain | json");
  app.add_option("-o,--out", o->out, "run directory (default runs/<name>)");
  app.add_option("--method,-m", o->method, "synthesis method (gabor, roveri2015, pcf2017, ...)");
  app.add_option("--set", o->sets, "override a config key: key.path=value (repeatable)");
  app.add_option("--seed", o->seed, "random seed");
  app.add_option("--init", o->init, "explicit initialisation point file");
  app.add_flag("--quick", o->quick, "tiny grid and few iterations (smoke test)");
  return [o]() {
    using namespace ppsynth;
    json c = o->config.empty() ? json::object() : load_config(o->config);
    if (!o->exemplar.empty()) c["exemplar"] = o->exemplar;
    if (!o->format.empty()) c["format"] = o->format;
    if (!o->method.empty()) c["method"] = json{{"type", o->method}};
    if (o->seed >= 0) c["seed"] = o->seed;
    if (!o->init.empty()) c["init_file"] = o->init;
    auto resolved = app::resolve_run_config(c, o->sets);
    auto outcome = app::run_synthesis(resolved, o->out, o->quick);
    std::cout << outcome.dir << "\n";
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("synthesize", "synthesise a larger pattern from an exemplar (writes a run directory)", setup)
