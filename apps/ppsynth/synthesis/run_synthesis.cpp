#include "apps/ppsynth/synthesis/run_synthesis.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/synthesis/run_config.hpp"
#include "apps/ppsynth/synthesis/run_observers.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/pcf.hpp"
#include "core/paths.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"
#include "optim/method.hpp"

namespace fs = std::filesystem;

namespace ppsynth::app {

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

}  // namespace

void write_run(RunOutcome& o, const nlohmann::json& r, const std::string& name, const std::string& partial, bool quick,
               std::chrono::steady_clock::time_point t0);

RunOutcome run_synthesis(const nlohmann::json& r, const std::string& dir_in, bool quick) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  RunOutcome o;
  o.config = r;
  o.exemplar = load_exemplar(r);
  std::string name = r["name"];
  if (name.empty()) name = fs::path(resolve_data_path(r["exemplar"])).stem().string();
  o.dir = dir_in.empty() ? "runs/" + name : dir_in;
  const std::string partial = o.dir + ".partial";
  fs::remove_all(partial);
  fs::create_directories(partial + "/snapshots");
  try {
    write_run(o, r, name, partial, quick, t0);
  } catch (...) {
    fs::remove_all(partial);  // an interrupted run leaves no half-written directory
    throw;
  }
  fs::remove_all(o.dir);
  fs::rename(partial, o.dir);
  spdlog::info("[{}] wrote {} ({:.1f} s)", name, o.dir, o.seconds);
  return o;
}

void write_run(RunOutcome& o, const nlohmann::json& r, const std::string& name, const std::string& partial, bool quick,
               std::chrono::steady_clock::time_point t0) {
  using Clock = std::chrono::steady_clock;

  SynthesisContext ctx;
  ctx.seed = r["seed"].get<uint64_t>();
  ctx.upscale = r["upscale"].get<int>();
  ctx.quick = quick;
  auto explicit_init = load_initialization(r);
  PointSet init_ps = explicit_init ? *explicit_init : PointSet();
  if (explicit_init) ctx.initialization = &init_ps;
  ProgressLog progress(name, quick ? 1 : 10);
  LossRecorder losses;
  SnapshotWriter snaps(partial + "/snapshots");
  ctx.observers = {&progress, &losses, &snaps};
  snaps.set_enabled(r["snapshots"].get<bool>());
  nlohmann::json stats;
  ctx.stats = &stats;

  auto method = MethodRegistry::instance().create(r["method"], "method");
  spdlog::info("[{}] {} points, {} classes -> {} points ({}), seed {}", name, o.exemplar.size(), o.exemplar.num_classes(),
               o.exemplar.size() * ctx.upscale * ctx.upscale, r["method"]["type"].get<std::string>(), ctx.seed);
  const auto ts = Clock::now();
  o.output = method->synthesize(o.exemplar, ctx);
  const double synth_seconds = std::chrono::duration<double>(Clock::now() - ts).count();
  o.stats = stats;

  // --- outputs ------------------------------------------------------------------
  write_points(partial + "/output.txt", o.output, Format::Plain);
  Format ex_format = detect_format(resolve_data_path(r["exemplar"]));
  if (ex_format == Format::GaborInt) write_points(partial + "/output.gabor.txt", o.output, Format::GaborInt);
  std::vector<std::pair<std::string, PointSet>> panels = {{"exemplar (" + std::to_string(o.exemplar.size()) + ")", o.exemplar}};
  o.initialization = snaps.initial();
  if (!o.initialization.empty()) {
    panels.push_back({"initialisation", o.initialization});
    write_points(partial + "/init.txt", o.initialization, Format::Plain);
  }
  panels.push_back({"output (" + std::to_string(o.output.size()) + ")", o.output});
  plot_panels(partial + "/exemplar_vs_output.png", panels, PointStyle{}, 420);
  write_text_atomic(partial + "/loss.csv", losses.csv());
  losses.plot(partial + "/loss.png", name + ": loss per iteration");
  write_text_atomic(partial + "/config.json", r.dump(2) + "\n");
  // The exemplar as synthesised (after scaling and class merging): the run stays
  // self-contained when a generated exemplar's file is gone, and --reuse compares contents.
  write_points(partial + "/exemplar.txt", o.exemplar, Format::Plain);
  if (r["evaluate"].get<bool>()) {
    o.metrics = evaluate(o.exemplar, o.output);
    write_text_atomic(partial + "/metrics.json", o.metrics.dump(2) + "\n");
    plot_pcf(partial + "/pcf.png", o.metrics);
  }
  o.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  nlohmann::json run = {{"name", name},
                        {"seed", ctx.seed},
                        {"revision", revision()},
                        {"quick", quick},
                        {"synthesis_seconds", synth_seconds},
                        {"total_seconds", o.seconds},
                        {"method_stats", stats}};
  write_text_atomic(partial + "/run.json", run.dump(2) + "\n");
}

namespace {

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw file_error(path, 0, "missing (not a finished run directory?)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw file_error(path, 0, std::string("not valid JSON: ") + e.what());
  }
}

// The keys that decide a synthesis, without the exemplar's file name: exemplars are
// compared by content (a generated exemplar lives in each report's own folder).
nlohmann::json synthesis_key(nlohmann::json c) {
  for (const char* k : {"name", "description", "snapshots", "evaluate", "exemplar", "format"}) c.erase(k);
  return c;
}

// The exemplar a finished run synthesised from: its own copy, else the config's file.
PointSet run_exemplar(const std::string& dir, const nlohmann::json& config) {
  const std::string copy = dir + "/exemplar.txt";
  return fs::exists(copy) ? read_points(copy) : load_exemplar(config);
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

}  // namespace

RunOutcome load_run(const std::string& dir) {
  RunOutcome o;
  o.dir = dir;
  o.config = read_json_file(dir + "/config.json");
  const nlohmann::json run = read_json_file(dir + "/run.json");
  o.stats = run.value("method_stats", nlohmann::json::object());
  o.seconds = run.value("total_seconds", 0.0);
  o.exemplar = run_exemplar(dir, o.config);
  o.output = read_points(dir + "/output.txt");
  if (fs::exists(dir + "/init.txt")) o.initialization = read_points(dir + "/init.txt");
  if (fs::exists(dir + "/metrics.json")) o.metrics = read_json_file(dir + "/metrics.json");
  return o;
}

bool same_synthesis(const nlohmann::json& a, const nlohmann::json& b) { return synthesis_key(a) == synthesis_key(b); }

std::string find_matching_run(const nlohmann::json& resolved, bool quick, const std::vector<std::string>& roots) {
  const PointSet wanted = load_exemplar(resolved);
  auto matches = [&](const fs::path& d) {
    std::error_code ec;
    if (!fs::is_regular_file(d / "config.json", ec) || !fs::is_regular_file(d / "run.json", ec) ||
        !fs::is_regular_file(d / "output.txt", ec))
      return false;
    try {
      const nlohmann::json config = read_json_file((d / "config.json").string());
      return same_synthesis(config, resolved) &&
             read_json_file((d / "run.json").string()).value("quick", !quick) == quick &&
             same_points(run_exemplar(d.string(), config), wanted);
    } catch (const InputError&) {
      return false;  // a damaged directory is simply not a match
    }
  };
  for (auto& root : roots) {
    std::error_code ec;
    if (!fs::is_directory(root, ec)) throw InputError("--reuse " + root + ": not a directory");
    if (matches(root)) return root;
    std::vector<fs::path> subdirs;
    for (auto& e : fs::directory_iterator(root, ec))
      if (e.is_directory() && e.path().extension() != ".partial") subdirs.push_back(e.path());
    std::sort(subdirs.begin(), subdirs.end());  // deterministic choice when several match
    for (auto& d : subdirs)
      if (matches(d)) return d.string();
  }
  return "";
}

}  // namespace ppsynth::app
