// `ppsynth gather DIR... [-o OUT] [--reference [EXEMPLAR=]FILE ...] [--bound B] [--baseline GROUP ...]
//                 [--protocol quadrants|crops|auto] [--stage N ...] [--force]`
// Statistics over seeds of every finished run under the directories (sweeps, run directories,
// folders of them): prints the table; with -o writes gather.csv, gather.md, gather.json,
// per_seed.csv and index.html (strip plots). The library: experiments/gather/gather.hpp.
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "experiments/gather/gather.hpp"

namespace {

struct Opts {
  std::vector<std::string> dirs;
  std::string out;
  std::vector<std::string> references, baselines;
  double bound = 1.25;
  std::string protocol;
  std::vector<std::string> stages;
  bool force = false;
};

ppsynth::app::RunFn setup(CLI::App& cmd) {
  auto o = std::make_shared<Opts>();
  cmd.add_option("dirs", o->dirs, "sweep directories, run directories, or folders of them")
      ->required()
      ->check(ppsynth::app::path_text());
  cmd.add_option("-o,--out", o->out, "write the tables, JSON and HTML page here (new or empty directory)")
      ->check(ppsynth::app::path_text());
  cmd.add_flag("--force", o->force, "replace an earlier gather's directory");
  cmd.add_option("--reference", o->references,
                 "a point file (e.g. the published output), evaluated against its exemplar and compared with the runs "
                 "from that exemplar: FILE, or EXEMPLAR=FILE when the runs come from several exemplars (repeatable)");
  cmd.add_option("--bound", o->bound, "a seed is within when its value <= BOUND x the reference's (default 1.25)");
  cmd.add_option("--baseline", o->baselines,
                 "a group label (e.g. the default config's, \"lines\"): every group of its exemplar gets the ratio of its "
                 "medians to the baseline's with a 90 % bootstrap interval (repeatable)");
  cmd.add_option("--protocol", o->protocol,
                 "evaluate every run's output (and reference) again with this protocol instead of reading its metrics.json: "
                 "quadrants (the paper's), crops (20 random exemplar-sized crops: the pattern away from the output's frame) or auto");
  cmd.add_option("--stage", o->stages,
                    "also each run's points after stage N (its snapshots/stageNN.txt; unfinished runs once past it) as a group "
                    "\"<label> @ stage N\", e.g. the published stages' output inside runs that append a border relax, for "
                    "--baseline; N, FIRST-LAST or a list (\"1-4,16\"); repeatable")
      ->allow_extra_args(false);
  return [o]() -> int {
    ppsynth::GatherOptions opts;
    if (!o->protocol.empty()) opts.protocol = ppsynth::parse_patch_protocol(o->protocol);
    opts.baselines = o->baselines;
    std::vector<ppsynth::app::NamedPath> references;
    for (const auto& r : o->references) {
      opts.references.push_back(ppsynth::parse_reference(r));
      references.push_back({"--reference", opts.references.back().file});
    }
    if (o->force) ppsynth::app::check_inputs_outside({"-o", o->out}, references);  // --force empties it
    opts.bound = o->bound;
    if (!o->stages.empty())
      for (const uint64_t stage : ppsynth::parse_number_list(nlohmann::json(o->stages), "--stage", "stage", 100000))
        opts.stages.push_back(static_cast<int>(stage));
    const auto r = ppsynth::gather_runs(o->dirs, opts);
    if (r.runs.empty()) throw ppsynth::InputError("gather: no finished run under the given directories");
    std::cout << ppsynth::format_gather(r);
    if (!o->out.empty()) {
      ppsynth::write_gather(r, o->out, o->force);
      std::cout << o->out << "/index.html\n";
    }
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("gather", "statistics over seeds of finished runs (sweeps, run directories): tables and plots", setup)
