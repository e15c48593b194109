#include "optim/run/run_store.hpp"

#include <ATen/Parallel.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/memory_budget.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/paths.hpp"
#include "core/processor.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"
#include "core/revision.hpp"
#include "core/run_directory.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

// PCF of the exemplar vs the output (quadrant average): all classes, each class, each
// class pair (cross PCF).
void plot_pcf(const std::string& path, const nlohmann::json& m) {
  auto curve_plot = [](const std::string& title, const nlohmann::json& pcf) {
    CurvePlot cp;
    cp.title = title;
    cp.xlabel = "r / r_max";
    cp.ylabel = "g(r)";
    const auto r = pcf["r"].get<std::vector<double>>();
    cp.series.push_back(Series{"exemplar", r, pcf["exemplar"].get<std::vector<double>>(), true});
    cp.series.push_back(Series{"output (4 quadrants)", r, pcf["output"].get<std::vector<double>>(), false});
    return cp;
  };
  std::vector<CurvePlot> plots;
  if (m.contains("all") && m["all"].contains("pcf")) plots.push_back(curve_plot("all classes", m["all"]["pcf"]));
  if (m.contains("classes") && m["classes"].size() > 1)
    for (auto& c : m["classes"])
      if (c.contains("pcf")) plots.push_back(curve_plot("class " + c["class"].dump(), c["pcf"]));
  if (m.contains("cross"))
    for (auto& c : m["cross"])
      if (c.contains("pcf")) plots.push_back(curve_plot("cross " + c["ci"].dump() + "-" + c["cj"].dump(), c["pcf"]));
  if (plots.size() == 1) plot_curves(path, plots[0]);
  else if (!plots.empty()) plot_curve_grid(path, plots, std::min<int>(3, static_cast<int>(plots.size())));
}

bool same_points(const PointSet& a, const PointSet& b) {
  if (a.size() != b.size() || a.classes() != b.classes() || a.attribute_names() != b.attribute_names()) return false;
  const double tol = 1e-9;  // plain text keeps 17 digits; tolerance only for the text round trip
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::abs(a[i].x - b[i].x) > tol || std::abs(a[i].y - b[i].y) > tol) return false;
    for (size_t k = 0; k < a.num_attributes(); ++k)
      if (std::abs(a.attr(i, k) - b.attr(i, k)) > tol * (1 + std::abs(a.attr(i, k)))) return false;
  }
  return true;
}

// A run made with another thread count or processor gives other bits than a new run here.
std::string note_made_differently(const std::string& dir) {
  const std::string differences = made_differently(read_run_json(dir + "/run.json"));
  if (!differences.empty()) spdlog::warn("{} was made with {}: a new run here may differ from it", dir, differences);
  return dir;
}

}  // namespace

nlohmann::json group_key(const nlohmann::json& resolved, bool quick) {
  nlohmann::json key = synthesis_key(resolved);
  key.erase("seed");
  key["exemplar"] = resolved["exemplar"];
  key["quick"] = quick;
  return key;
}

std::string made_differently(const nlohmann::json& recorded) {
  std::string out;
  if (recorded.contains("threads") && recorded["threads"] != at::get_num_threads())
    out = recorded["threads"].dump() + " threads (this process " + std::to_string(at::get_num_threads()) + ")";
  if (recorded.contains("processor") && recorded["processor"].is_string() && recorded["processor"] != processor_kind())
    out += (out.empty() ? "" : " and ") + ("the processor " + recorded["processor"].get<std::string>() + " (this one " +
                                           processor_kind() + ")");
  return out;
}

nlohmann::json synthesis_key(nlohmann::json c) {
  for (const char* k : {"name", "description", "snapshots", "evaluate", "exemplar", "format", "checkpoint_seconds"}) c.erase(k);
  return c;
}

std::string run_name(const nlohmann::json& r) {
  const std::string name = r["name"];
  return name.empty() ? fs::path(resolve_data_path(r["exemplar"])).stem().string() : name;
}

void write_run_outputs(RunOutcome& o, const RunOptions& options, const std::string& name, bool quick, const LossRecorder& losses,
                       double synthesis_seconds, std::chrono::steady_clock::time_point started) {
  const std::string& dir = o.dir;
  write_points(dir + "/output.txt", o.output, Format::Plain);
  if (o.exemplar_format == Format::GaborInt) write_points(dir + "/output.gabor.txt", o.output, Format::GaborInt);
  std::vector<std::pair<std::string, PointSet>> panels = {{"exemplar (" + std::to_string(o.exemplar.size()) + ")", o.exemplar}};
  if (!o.initialization.empty()) {
    panels.push_back({"initialization", o.initialization});
    write_points(dir + "/init.txt", o.initialization, Format::Plain);
  }
  panels.push_back({"output (" + std::to_string(o.output.size()) + ")", o.output});
  plot_panels(dir + "/exemplar_vs_output.png", panels, PointStyle{}, 420);
  write_text_atomic(dir + "/loss.csv", losses.csv());
  losses.plot(dir + "/loss.png", name + ": loss per iteration");
  // The exemplar as synthesized (after scaling and class merging): the run stays
  // self-contained when a generated exemplar's file is gone, and --reuse compares contents.
  write_points(dir + "/exemplar.txt", o.exemplar, Format::Plain);
  if (!o.metrics.is_null()) {
    write_text_atomic(dir + "/metrics.json", o.metrics.dump(2) + "\n");
    plot_pcf(dir + "/pcf.png", o.metrics);
  }
  // A resumed run's total includes the processes before (up to their last checkpoint).
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() + o.seconds_before_resume;
  // run.json's method_stats: what the method measured, with its stages where it has them.
  nlohmann::json method_stats = o.stats;
  if (!o.stages.empty()) {
    method_stats["stages"] = to_json(o.stages);
    method_stats["seconds_before_resume"] = o.seconds_before_resume;
  }
  nlohmann::json run = {{"name", name},
                        {"seed", options.seed},
                        {"revision", revision()},
                        {"quick", quick},
                        // results depend on it in the last bits (reductions split across threads)
                        {"threads", at::get_num_threads()},
                        // and on the processor's instruction set (core/processor.hpp)
                        {"processor", processor_kind()},
                        // a preset may differ by processor class (optim/run/presets.hpp)
                        {"preset", preset_record(options.preset, options.runtime.device)},
                        {"synthesis_seconds", synthesis_seconds},
                        // the synthesis's CPU time: what its work cost, whatever ran beside it
                        {"cpu_seconds", o.cpu_seconds},
                        {"total_seconds", o.seconds},
                        {"peak_rss_mib", peak_resident_mib()},
                        {"method_stats", method_stats}};
  write_text_atomic(dir + "/run.json", run.dump(2) + "\n");
}

PointSet run_exemplar(const std::string& dir, const nlohmann::json& config) {
  const std::string copy = dir + "/exemplar.txt";
  return fs::exists(copy) ? read_points(copy) : load_exemplar(config);
}

RunOutcome load_run(const std::string& dir) {
  RunOutcome o;
  o.dir = dir;
  o.config = read_run_config(dir + "/config.json");
  const RunRecord run = read_run_record(dir + "/run.json");
  o.stats = run.method_stats;
  if (o.stats.is_object() && o.stats.contains("stages")) {
    try {
      o.stages = stage_records_from_json(o.stats["stages"]);
    } catch (const std::invalid_argument& e) {
      throw InputError(dir + "/run.json: method_stats.stages: " + e.what());
    }
    o.seconds_before_resume = o.stats.value("seconds_before_resume", 0.0);
    o.stats.erase("stages");
    o.stats.erase("seconds_before_resume");
  }
  o.seconds = run.total_seconds;
  o.cpu_seconds = run.cpu_seconds;
  o.exemplar = run_exemplar(dir, o.config);
  o.output = read_points(dir + "/output.txt");
  if (fs::exists(dir + "/init.txt")) o.initialization = read_points(dir + "/init.txt");
  if (fs::exists(dir + "/metrics.json")) o.metrics = read_run_json(dir + "/metrics.json");
  return o;
}

bool same_synthesis(const nlohmann::json& a, const nlohmann::json& b) { return synthesis_key(a) == synthesis_key(b); }

std::string find_matching_run(const nlohmann::json& resolved, bool quick, const std::vector<std::string>& roots, ReuseRule rule) {
  const PointSet wanted = load_exemplar(resolved);
  // The preset's variant this process resolved `resolved` under: a run of the same request made
  // under the other variant (a machine of the other kind) is the preset's run too.
  std::string wanted_variant;
  try {
    const nlohmann::json& runtime = resolved.contains("runtime") ? resolved["runtime"] : nlohmann::json::object();
    const nlohmann::json preset = preset_record(resolved.value("preset", nlohmann::json()), runtime.value("device", nlohmann::json()));
    if (preset.is_object()) wanted_variant = preset["variant"].get<std::string>();
  } catch (const InputError&) {
    // a device this machine lacks: only runs of the identical config match
  }
  // First pass: runs made under this machine's own variant (the identical config); only when
  // none exists, a run of the other variant. An item's arms are then compared like for like
  // wherever this machine made their runs: 64 float32 filters against 120 bf16 ones is the
  // same request, but not the same network.
  bool other_variant_allowed = false;
  auto same_request = [&](const nlohmann::json& config, const RunRecord& record) {
    if (same_synthesis(config, resolved)) return true;
    if (!other_variant_allowed || wanted_variant.empty() || record.preset_variant.empty() || record.preset_variant == wanted_variant) return false;
    return same_synthesis(as_every_processor_variant(config, record.preset_variant), as_every_processor_variant(resolved, wanted_variant));
  };
  std::string without_cpu;  // a match left out for want of its CPU time: said once, below
  auto matches = [&](const fs::path& d) {
    if (run_dir_state(d.string()) != RunDirState::Complete) return false;  // only finished runs of ppsynth
    try {
      const nlohmann::json config = read_run_config((d / "config.json").string());
      const RunRecord record = read_run_record((d / "run.json").string());
      if (record.quick != quick || !same_request(config, record) || !same_points(run_exemplar(d.string(), config), wanted))
        return false;
      if (rule.needs_cpu_seconds && record.cpu_seconds <= 0) {
        if (without_cpu.empty()) without_cpu = d.string();
        return false;
      }
      if (other_variant_allowed && !same_synthesis(config, resolved))
        spdlog::info("{}: its preset ran as '{}', where this processor takes '{}': the same request, reused as the preset's run", d.string(),
                     record.preset_variant, wanted_variant);
      return true;
    } catch (const InputError&) {
      return false;  // a damaged directory is simply not a match
    }
  };
  auto none = [&]() {
    if (!without_cpu.empty())
      spdlog::info("not reusing {}: it did not record its CPU time, which the report's rule reads; running it again", without_cpu);
    return std::string();
  };
  std::vector<fs::path> candidates;  // each root itself, then its subdirectories in name order
  for (auto& root : roots) {
    std::error_code ec;
    if (!fs::is_directory(root, ec)) throw InputError("--reuse " + root + ": not a directory");
    candidates.push_back(root);
    std::vector<fs::path> subdirs;
    for (auto& e : fs::directory_iterator(root, ec))
      if (e.is_directory()) subdirs.push_back(e.path());
    std::sort(subdirs.begin(), subdirs.end());  // deterministic choice when several match
    candidates.insert(candidates.end(), subdirs.begin(), subdirs.end());
  }
  for (bool other : {false, true}) {
    if (other && !rule.other_variant) break;
    other_variant_allowed = other;
    for (auto& d : candidates)
      if (matches(d)) return note_made_differently(d.string());
  }
  return none();
}

}  // namespace ppsynth
