// `ppsynth reproduce NAME [--quick] [--out DIR] [--preset fast] [--set key=value ...] [--seeds 95-99 [-j N] [--plan-only]]`
// `ppsynth reproduce --list` | `--check [NAME...]` | `--rules` | `--page DIR`
// Re-runs a published experiment (a figure, table or ablation of Huang et al. 2022) from its
// config in configs/paper/ and writes a self-contained report (reports/NAME/index.html, plus
// CSV/Markdown tables). Schema: experiments/plan/reproduce_config.hpp, docs/howto/reproduce_a_figure.md.
#include <filesystem>
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/reproduce_page.hpp"
#include "experiments/report/verdict_html.hpp"
#include "experiments/reproduce/reproduce_runner.hpp"
#include "core/error.hpp"
#include "optim/run/runtime.hpp"

namespace {

struct Opts {
  std::vector<std::string> names, sets, reuse, panels;
  std::string out, seeds, sweep, page, preset;
  bool quick = false, list = false, check = false, force = false, plan_only = false, rules = false, reuse_own_variant = false;
  int jobs = 1;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  app.add_option("name", o->names, "config name in configs/paper (e.g. fig05, table1) or a path to a .json config");
  app.add_flag("--list", o->list, "list the configs in configs/paper");
  app.add_flag("--rules", o->rules, "print every config's rule (how its verdict is decided) as a Markdown table");
  app.add_flag("--check", o->check, "validate the named configs (all of configs/paper if none) without running");
  app.add_option("--page", o->page, "write DIR/index.html and DIR/index.md: every report in DIR/NAME with its verdict by rule, "
                                    "our numbers beside the paper's claim, and its pictures (scripts/reproduce_all.sh)")
      ->check(ppsynth::app::path_text());
  app.add_flag("--quick", o->quick, "small grids, few iterations, few filters (smoke test)");
  app.add_option("-o,--out", o->out, "report directory (default reports/NAME); must be new or empty")
      ->check(ppsynth::app::path_text());
  app.add_flag("--force", o->force, "replace the report directory if it holds a report of ppsynth");
  app.add_option("--reuse", o->reuse,
                 "reuse finished run directories (DIR or its subdirectories, e.g. runs/) whose resolved config equals a column's");
  app.add_flag("--reuse-own-variant", o->reuse_own_variant,
               "reuse only runs made under this machine's preset variant (its filter count and precision); "
               "the other variant's runs are made again here, so an item's arms are compared like for like");
  app.add_option("--panels", o->panels, "run only these panels (the report says which were left out)");
  app.add_option("--set", o->sets, "override a key of every panel's run config: key.path=value (method.* keys: ours only)");
  app.add_option("--preset", o->preset, "a named preset for ours' runs: fast (`ppsynth config --kind preset`); the baselines run as they are");
  app.add_option("--seeds", o->seeds, "every synthesized column over these seeds (\"95-99\" or \"95,97\"), as a sweep; "
                                      "the report adds the statistics over seeds");
  app.add_option("--sweep", o->sweep, "the sweep's directory (default sweeps/NAME)")->check(ppsynth::app::path_text());
  app.add_option("-j,--jobs", o->jobs, "the sweep's runs at once, here (--seeds)")->check(ppsynth::app::whole_number(1, 1024));
  app.add_flag("--plan-only", o->plan_only, "plan the sweep (--seeds) and stop: run it with `ppsynth sweep run DIR --slurm`, "
                                            "then run this command again to write the report");
  return [o]() {
    using namespace ppsynth;
    namespace fs = std::filesystem;
    if (o->list) {
      for (auto& f : list_reproduce_configs(paper_config_dir())) {
        try {
          auto c = load_reproduce_config(f);
          std::printf("%-24s %-10s %2zu panel(s)  %s\n", fs::path(f).stem().c_str(), c.kind.c_str(), c.panels.size(), c.title.c_str());
        } catch (const InputError& e) {
          std::printf("%-24s INVALID: %s\n", fs::path(f).stem().c_str(), e.what());
        }
      }
      return 0;
    }
    if (o->rules) {
      std::cout << rules_markdown(list_reproduce_configs(paper_config_dir()));
      return 0;
    }
    if (!o->page.empty()) {
      if (!o->names.empty()) throw InputError("--page reads the reports in DIR: give no config name");
      const size_t n = write_reproduce_page(o->page);
      std::cout << o->page << "/index.html (" << n << " reports)\n";
      return 0;
    }
    if (o->check) {
      std::vector<std::string> files;
      for (auto& n : o->names) files.push_back(find_reproduce_config(n));
      if (o->names.empty()) files = list_reproduce_configs(paper_config_dir());
      for (auto& f : files) {
        auto c = load_reproduce_config(f);  // throws InputError naming the file and key
        std::printf("ok  %s (%zu panels)\n", f.c_str(), c.panels.size());
      }
      return 0;
    }
    if (o->names.size() != 1) throw InputError("give one config name (see --list)");
    std::vector<std::pair<std::string, std::string>> flags;  // each flag sets a key a --set of it would override
    if (!o->seeds.empty()) flags.emplace_back("--seeds " + o->seeds, "seed");
    if (!o->preset.empty()) flags.emplace_back("--preset " + o->preset, "preset");
    ppsynth::app::refuse_set_conflicts(o->sets, flags);
    if (!o->preset.empty()) o->sets.push_back("preset=" + o->preset);
    const std::string config_file = find_reproduce_config(o->names.front());
    if (o->force) ppsynth::app::check_inputs_outside({"-o", o->out}, {{"config", config_file}});  // --force empties it
    auto config = load_reproduce_config(config_file);
    ReproduceOptions ro;
    ro.quick = o->quick;
    ro.out = o->out;
    ro.force = o->force;
    ro.overrides = o->sets;
    ro.reuse = o->reuse;
    ro.reuse_own_variant = o->reuse_own_variant;
    ro.panels = o->panels;
    ro.seeds = o->seeds;
    ro.sweep_dir = o->sweep;
    ro.jobs = o->jobs;
    ro.plan_only = o->plan_only;
    ro.task_binary = fs::read_symlink("/proc/self/exe").string();
    if (o->plan_only && o->seeds.empty()) throw InputError("--plan-only plans the sweep of --seeds; give --seeds");
    if (!o->plan_only) configure_runtime();  // threads, allocator, the Gabor maps' path: optim/run/runtime.hpp
    auto res = run_reproduction(config, ro);
    if (o->plan_only) {
      std::cout << "planned " << res.sweep_dir << "\nrun it with: ppsynth sweep run " << res.sweep_dir
                << " --slurm (or --local -j N), then this command again without --plan-only\n";
      return 0;
    }
    std::cout << res.dir << "/index.html\n";
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("reproduce", "re-run a figure, table or ablation of the paper from configs/paper and write a report", setup)
