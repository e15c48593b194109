#include "experiments/reproduce/reproduce_runner.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>

#include "experiments/report/report_writer.hpp"
#include "experiments/execute/sweep_executors.hpp"
#include "experiments/execute/sweep_runs.hpp"
#include "experiments/reproduce/reproduce_gabor_maps.hpp"
#include "experiments/reproduce/reproduce_numbers.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "core/content_hash.hpp"
#include "core/formats/text_table.hpp"
#include "optim/run/run_store.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_synthesis.hpp"
#include "core/atomic_file.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/generators/generator.hpp"
#include "core/log.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A rule that judges runs by their CPU time (table3) reuses only runs that recorded it.
bool rule_reads_cpu_seconds(const ReproduceConfig& c) {
  return std::any_of(c.rule.checks.begin(), c.rule.checks.end(), [](const RuleCheck& k) { return k.metric == "run/cpu_seconds"; });
}

ReuseRule reuse_rule(const ReproduceConfig& c, const ReproduceOptions& o) {
  ReuseRule rule;
  rule.needs_cpu_seconds = rule_reads_cpu_seconds(c);
  rule.other_variant = !o.reuse_own_variant;
  return rule;
}

// The exemplar of a panel with "exemplar_generator", and its description.
PointSet generated_points(const PanelSpec& p, bool quick, std::string& description) {
  json spec = p.generator["generator"];
  if (quick && !p.generator["quick"].is_null()) spec = merge(spec, p.generator["quick"]);
  const size_t n = p.generator["n"].get<size_t>();
  const uint64_t seed = p.generator["seed"].get<uint64_t>();
  description = spec.dump() + ", n = " + std::to_string(n) + ", seed " + std::to_string(seed);
  return generate_points(spec, n, seed, Domain{}, "panels." + p.name + ".exemplar_generator.generator");
}

// Generated, written into the panel folder; or, over seeds, the file the sweep's runs use
// (`shared`: written before the sweep, so the panel's run is the sweep's seed run).
std::string generate_exemplar(const PanelSpec& p, const ReproduceOptions& o, const std::string& panel_dir, std::string& description) {
  const PointSet ps = generated_points(p, o.quick, description);
  if (auto it = o.generated_exemplars.find(p.name); it != o.generated_exemplars.end()) {
    description += " (" + it->second + ")";
    return it->second;
  }
  const std::string path = panel_dir + "/exemplar.txt";
  write_points(path, ps, Format::Plain);
  description += " (panels/" + p.name + "/exemplar.txt)";
  return fs::absolute(path).string();
}

void plot_pcf_comparison(const std::string& path, const PanelResult& pr) {
  CurvePlot cp;
  cp.title = pr.name + ": PCF, exemplar vs outputs (4-quadrant mean)";
  cp.xlabel = "r / r_max";
  cp.ylabel = "g(r)";
  bool have_ex = false;
  for (const auto& c : pr.columns) {
    if (c.status != "ok" || !c.metrics.contains("all") || !c.metrics["all"].contains("pcf")) continue;
    const auto& pcf = c.metrics["all"]["pcf"];
    const auto r = pcf["r"].get<std::vector<double>>();
    if (!have_ex) {
      cp.series.push_back(Series{"exemplar", r, pcf["exemplar"].get<std::vector<double>>(), true});
      have_ex = true;
    }
    cp.series.push_back(Series{c.column, r, pcf["output"].get<std::vector<double>>(), false});
  }
  if (have_ex) plot_curves(path, cp, 640, 380);
}

ColumnResult synthesize(const ReproduceConfig& c, const PanelSpec& p, const std::string& column, const ReproduceOptions& o,
                        const std::string& generated_exemplar, const std::string& report_dir, PanelResult& pr,
                        PointSet& ours_init, std::string& ours_init_source) {
  json run = column_run_config(c, p, column, o.overrides);
  if (!generated_exemplar.empty()) {
    run["exemplar"] = generated_exemplar;
    run["format"] = "plain";
  }
  json resolved;
  try {
    resolved = resolve_run_config(run, {});
  } catch (const InputError& e) {
    throw InputError(c.source + ": panel '" + p.name + "', column '" + column + "': " + e.what());
  }
  const std::string rel = "panels/" + p.name + "/" + column;
  RunOutcome out;
  const std::string reused = o.reuse.empty() ? "" : find_matching_run(resolved, o.quick, o.reuse, reuse_rule(c, o));
  if (!reused.empty()) {
    spdlog::info("[{}/{}] '{}': reusing the finished run {}", c.name, p.name, column, reused);
    fs::create_directories(fs::path(report_dir + "/" + rel).parent_path());
    fs::copy(reused, report_dir + "/" + rel, fs::copy_options::recursive);
    out = load_run(report_dir + "/" + rel);
  } else {
    RunRequest req;
    req.dir = report_dir + "/" + rel;
    req.quick = o.quick;
    out = run_synthesis(resolved, req);
  }
  ColumnResult r;
  r.column = column;
  r.output = out.output;
  r.metrics = out.metrics.is_null() ? evaluate(out.exemplar, out.output) : out.metrics;
  r.run_dir = rel;
  r.source = reused.empty() ? rel : rel + " (reused from " + reused + ")";
  r.config = out.config;
  r.stages = out.stages;
  r.seconds = out.seconds;
  r.cpu_seconds = out.cpu_seconds;
  r.iterations = total_iterations(out);
  const RunRecord record = read_run_record(out.dir + "/run.json");
  r.synthesis_seconds = record.synthesis_seconds;
  r.processor = record.processor;
  r.preset_variant = record.preset_variant;
  if (pr.exemplar.empty()) pr.exemplar = out.exemplar;
  if (column == "ours") {
    ours_init = out.initialization;
    ours_init_source = rel + "/init.txt";
  }
  return r;
}

void run_panel(const ReproduceConfig& c, const PanelSpec& p, const ReproduceOptions& o, const std::string& report_dir, PanelResult& pr) {
  const auto t0 = Clock::now();
  pr.name = p.name;
  const std::string panel_dir = report_dir + "/panels/" + p.name;
  fs::create_directories(panel_dir);
  std::string generated;
  if (!p.generator.is_null()) {
    const auto tg = Clock::now();
    generated = generate_exemplar(p, o, panel_dir, pr.exemplar_source);
    spdlog::info("[{}/{}] generated exemplar in {:.1f} s", c.name, p.name, since(tg));
  }

  if (p.kind == "gabor_maps") {
    json run = column_run_config(c, p, "ours", o.overrides);
    if (!generated.empty()) run["exemplar"] = generated;
    json r = resolve_run_config(run, {});
    pr.exemplar = load_exemplar(r);
    if (pr.exemplar_source.empty()) pr.exemplar_source = r["exemplar"];
    for (auto& [file, caption] : render_gabor_map_figure(pr.exemplar, p.maps, o.quick, panel_dir))
      pr.images.push_back({"panels/" + p.name + "/" + file, caption});
    pr.seconds = since(t0);
    return;
  }

  // Synthesized columns first ("ours" before the others), then init and reference.
  std::map<std::string, ColumnResult> done;
  PointSet ours_init;
  std::string ours_init_source;
  std::vector<std::string> order;
  if (std::count(p.methods.begin(), p.methods.end(), "ours")) order.push_back("ours");
  for (auto& m : p.methods)
    if (m != "ours") order.push_back(m);
  for (auto& m : order) {
    if (m == "init" || m == "reference") continue;
    if (!method_available(m)) {
      ColumnResult r;
      r.column = m;
      r.status = "pending";
      spdlog::warn("[{}/{}] method '{}' is not registered in this build: column left empty", c.name, p.name, m);
      done[m] = r;
      continue;
    }
    spdlog::info("[{}/{}] running '{}'", c.name, p.name, m);
    done[m] = synthesize(c, p, m, o, generated, report_dir, pr, ours_init, ours_init_source);
  }
  if (pr.exemplar.empty()) {  // only init/reference columns: still need the exemplar
    json run = column_run_config(c, p, "ours", o.overrides);
    if (!generated.empty()) run["exemplar"] = generated, run["format"] = "plain";
    pr.exemplar = load_exemplar(resolve_run_config(run, {}));
  }
  if (pr.exemplar_source.empty()) pr.exemplar_source = p.run.value("exemplar", "");
  for (auto& m : p.methods) {
    if (m == "init") {
      ColumnResult r;
      r.column = "init";
      r.output = ours_init;
      r.source = ours_init_source;
      if (ours_init.empty()) r.status = "missing";
      else r.metrics = evaluate(pr.exemplar, ours_init);
      pr.columns.push_back(r);
    } else if (m == "reference") {
      ColumnResult r;
      r.column = "reference";
      if (p.reference.empty()) {
        r.status = "missing";
      } else {
        r.source = p.reference;
        r.output = read_points(p.reference);
        r.metrics = evaluate(pr.exemplar, r.output);
      }
      pr.columns.push_back(r);
    } else {
      pr.columns.push_back(done.at(m));
    }
  }

  // Exemplar and every column side by side (the paper's layout), and the PCFs together.
  std::vector<std::pair<std::string, PointSet>> sets = {{"exemplar", pr.exemplar}};
  for (auto& col : pr.columns) sets.push_back({col.status == "ok" ? col.column : col.column + " (n/a)", col.output});
  plot_panels(panel_dir + "/side_by_side.png", sets, PointStyle{}, 320);
  pr.images.push_back({"panels/" + p.name + "/side_by_side.png", p.title + ": exemplar and outputs"});
  plot_pcf_comparison(panel_dir + "/pcf_compare.png", pr);
  if (fs::exists(panel_dir + "/pcf_compare.png"))
    pr.images.push_back({"panels/" + p.name + "/pcf_compare.png", p.title + ": PCF of the exemplar and of each output"});
  pr.seconds = since(t0);
}


// The config restricted to the panels named in `names` (all when empty); an unknown name is
// an error listing the panels there are.
ReproduceConfig select_panels(const ReproduceConfig& c, const std::vector<std::string>& names) {
  if (names.empty()) return c;
  ReproduceConfig r = c;
  r.panels.clear();
  std::string all, left_out;
  for (const auto& p : c.panels) all += (all.empty() ? "" : ", ") + p.name;
  for (const auto& n : names)
    if (std::none_of(c.panels.begin(), c.panels.end(), [&](const PanelSpec& p) { return p.name == n; }))
      throw InputError((c.source.empty() ? c.name : c.source) + ": --panels: no panel '" + n + "' (panels: " + all + ")");
  for (const auto& p : c.panels) {
    if (std::find(names.begin(), names.end(), p.name) != names.end()) r.panels.push_back(p);
    else left_out += (left_out.empty() ? "" : ", ") + p.name;
  }
  r.description += (r.description.empty() ? "" : " ") + std::string("Partial report: panel(s) ") + left_out +
                   " not run (--panels).";
  return r;
}

std::string sweep_dir_of(const ReproduceConfig& c, const ReproduceOptions& o) {
  return o.sweep_dir.empty() ? "sweeps/" + c.name + (o.quick ? "-quick" : "") : o.sweep_dir;
}

// Over seeds, a panel's generated exemplar is one file that every seed's runs and the report's
// panel share, in generated-exemplars/ beside the sweep directory, named by its content: the
// sweeps there that generate the same exemplar (Table 1 and Fig. 5's CCVT) name the same file,
// so --reuse matches their runs, and a changed generator makes a new file, so new runs, never a
// stale match. The sweep plans from a copy of the figure config (there too) whose generated
// panels read that file. Returns the config file to plan.
std::string write_sweep_inputs(const ReproduceConfig& c, ReproduceOptions& o, const std::string& sweep_dir) {
  if (std::none_of(c.panels.begin(), c.panels.end(), [](const PanelSpec& p) { return !p.generator.is_null(); })) return c.source;
  const fs::path dir = fs::absolute(sweep_dir).lexically_normal().parent_path() / "generated-exemplars";
  fs::create_directories(dir);
  json figure = c.raw;
  figure["name"] = c.name;
  figure.erase("rule");  // it may name panels left out below; planning needs the runs only
  json panels = json::array();
  for (json pj : figure["panels"]) {
    const auto p = std::find_if(c.panels.begin(), c.panels.end(), [&](const PanelSpec& s) { return s.name == pj.value("name", ""); });
    if (p == c.panels.end()) continue;  // left out by --panels
    pj["run"] = p->run;                 // its "parent" merged already: the copy lives elsewhere
    panels.push_back(pj);
    if (p->generator.is_null()) continue;
    std::string description;
    const PointSet ps = generated_points(*p, o.quick, description);
    const std::string tmp = (dir / (c.name + "-" + p->name + ".partial")).string();
    write_points(tmp, ps, Format::Plain);
    const fs::path file = dir / ("exemplar-" + content_hash(read_file_text(tmp)).substr(0, 12) + ".txt");
    fs::rename(tmp, file);
    o.generated_exemplars[p->name] = file.string();
    panels.back().erase("exemplar_generator");
    panels.back()["run"]["exemplar"] = file.string();
    panels.back()["run"]["format"] = "plain";
  }
  figure["panels"] = panels;
  const std::string text = figure.dump(2) + "\n";
  const std::string path = (dir / (c.name + "-" + content_hash(text).substr(0, 12) + ".json")).string();
  write_text_atomic(path, text);
  return path;
}

// Runs of the sweep not made yet whose resolved config a finished run under --reuse has: copied
// in, seed by seed, so they are not run again.
void reuse_into_sweep(const std::string& sweep_dir, const std::vector<std::string>& reuse, ReuseRule rule) {
  if (reuse.empty()) return;
  for (const SweepRow& row : load_sweep(sweep_dir).rows) {
    const fs::path d = fs::path(sweep_dir) / row.dir;
    if (fs::exists(d)) continue;
    const std::string found = find_matching_run(row.config, row.quick, reuse, rule);
    if (found.empty()) continue;
    spdlog::info("[{}] {}: reusing the finished run {}", row.id, row.label, found);
    fs::create_directories(d.parent_path());
    fs::copy(found, d, fs::copy_options::recursive);
  }
}

// Every synthesized column of the selected panels over the seeds, as a sweep planned and run
// here (or only planned). Returns the sweep's directory once every run of it is done.
std::string run_seed_sweep(const ReproduceConfig& c, ReproduceOptions& o) {
  if (c.source.empty()) throw InputError("--seeds: the figure config must be a file (a sweep names it)");
  const std::string dir = sweep_dir_of(c, o);
  const std::string figure = write_sweep_inputs(c, o, dir);
  json spec = {{"name", c.name + "-seeds"}, {"figures", {figure}}, {"seeds", o.seeds}, {"quick", o.quick}, {"set", o.overrides}};
  std::vector<std::string> panels;
  for (const auto& p : c.panels) panels.push_back(p.name);
  if (!o.panels.empty()) spec["panels"] = panels;
  const PlanSummary plan = plan_sweep(expand_sweep_spec(spec, c.source, fs::path(c.source).parent_path().string()), dir);
  spdlog::info("[{}] over seeds {}: {} runs in the sweep {}", c.name, o.seeds, plan.rows, plan.dir);
  reuse_into_sweep(plan.dir, o.reuse, reuse_rule(c, o));
  if (o.plan_only) return plan.dir;
  if (o.task_binary.empty()) throw InputError("--seeds: no executable to run the sweep's tasks with");
  LocalExecution how;
  how.binary = o.task_binary;
  how.jobs = o.jobs;
  execute_local(plan.dir, how, nullptr);
  size_t open = 0;
  for (const auto& st : sweep_status(plan.dir, load_sweep(plan.dir))) open += st.state == RowState::Done ? 0 : 1;
  if (open > 0)
    throw InputError(std::to_string(open) + " run(s) of the sweep " + plan.dir + " did not finish; see `ppsynth sweep status " +
                     plan.dir + "` and its logs/, then run this again (finished runs are kept)");
  return plan.dir;
}

}  // namespace

ReproduceResult run_reproduction(const ReproduceConfig& config, const ReproduceOptions& options) {
  const ReproduceConfig c = select_panels(config, options.panels);
  ReproduceOptions o = options;
  const auto t0 = Clock::now();
  try {
    check_reproduce_runs(c, o.overrides);  // a bad --set fails before anything is written
  } catch (const InputError& e) {
    if (c.source.empty()) throw;
    throw InputError(c.source + ": " + e.what());
  }
  ReproduceResult res;
  res.quick = o.quick;
  // Fig. 3 draws maps only: over seeds there is nothing to run, and its report is the one seed's.
  const bool synthesizes = std::any_of(c.panels.begin(), c.panels.end(), [](const PanelSpec& p) {
    return p.kind == "synthesis" && std::any_of(p.methods.begin(), p.methods.end(), [](const std::string& m) {
             return m != "init" && m != "reference" && method_available(m);
           });
  });
  if (!o.seeds.empty() && synthesizes) {
    res.sweep_dir = run_seed_sweep(c, o);
    if (o.plan_only) return res;
    o.reuse.push_back(res.sweep_dir + "/runs");  // the panels show the config seed's runs
  }
  RunDirOptions dir_options;
  dir_options.kind = "report";
  dir_options.force = o.force;
  RunDirectory dir = RunDirectory::open(o.out.empty() ? "reports/" + c.name : o.out, dir_options);
  res.dir = dir.path();
  try {
    fs::create_directories(res.dir + "/panels");
    for (const auto& p : c.panels) {
      res.panels.emplace_back();
      run_panel(c, p, o, res.dir, res.panels.back());
      spdlog::info("[{}] panel {} done in {:.1f} s", c.name, p.name, res.panels.back().seconds);
    }
    if (!res.sweep_dir.empty()) {
      res.seeds = gather_runs({res.sweep_dir}, GatherOptions{});
      write_gather(res.seeds, res.dir + "/seeds", false);
    }
    res.numbers = collect_item_numbers(c, res);
    res.seconds = since(t0);
    write_reproduce_report(c, res, o);
    dir.mark_complete();
  } catch (...) {
    dir.discard();  // a failed report leaves nothing of its own behind
    throw;
  }
  spdlog::info("[{}] wrote {}/index.html ({:.1f} s)", c.name, res.dir, res.seconds);
  return res;
}

}  // namespace ppsynth
