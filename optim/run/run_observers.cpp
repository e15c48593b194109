#include "optim/run/run_observers.hpp"

#include <cstdio>
#include <map>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/memory_budget.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"

namespace ppsynth {

namespace {
std::string fmt_duration(double s) {
  char b[32];
  if (s < 90) std::snprintf(b, sizeof b, "%.0fs", s);
  else if (s < 5400) std::snprintf(b, sizeof b, "%.1fm", s / 60);
  else std::snprintf(b, sizeof b, "%.1fh", s / 3600);
  return b;
}
}  // namespace

void ProgressLog::on_stage_begin(const ProgressEvent& e) {
  spdlog::info("[{}] stage {}/{}: {}{}{}", name_, e.stage_index + 1, e.stage_count, e.stage, e.note.empty() ? "" : ": ", e.note);
}

void ProgressLog::on_iteration(const ProgressEvent& e) {
  if (e.iteration % every_ != 0) return;
  const double rate = e.seconds > 0 ? (e.iteration + 1) / e.seconds : 0;
  // ETA of the stage at its iteration cap (the convergence rule usually stops earlier).
  const double eta = rate > 0 ? (e.max_iterations - e.iteration - 1) / rate : 0;
  spdlog::info("[{}] {} it {:>4}/{} loss {:.6e}  {:.2f} it/s  stage ETA <= {}", name_, e.stage, e.iteration,
               e.max_iterations, e.loss, rate, fmt_duration(eta));
}

void ProgressLog::on_stage_end(const ProgressEvent& e, const PointSet&) {
  spdlog::info("[{}] {} done: {} iterations in {}", name_, e.stage, e.iteration, fmt_duration(e.seconds));
  if (e.windows <= 1 || !e.window_ends) return;
  ++windows_done_here_;  // the ETA assumes the windows still to come cost what these did
  const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  const int left = e.windows - e.window - 1;
  // The peak memory so far: a window run's should stay that of one window (docs/lab/large_outputs.md).
  spdlog::info("[{}] canvas: {}/{} windows done ({:.0f} %), {} in this process, ETA {}, peak {:.0f} MiB", name_, e.window + 1,
               e.windows, 100.0 * (e.window + 1) / e.windows, fmt_duration(spent), fmt_duration(spent / windows_done_here_ * left),
               peak_resident_mib());
}

void ProgressLog::on_resume(const std::vector<ProgressEvent>& earlier) {
  if (earlier.empty()) return spdlog::info("[{}] resumed at the start", name_);
  const auto& e = earlier.back();
  spdlog::info("[{}] resumed after {}, iteration {} ({} iterations before)", name_, e.stage, e.iteration, earlier.size());
}

void LossRecorder::on_iteration(const ProgressEvent& e) {
  rows_.push_back({e.stage_index, e.stage, e.iteration, e.loss, e.seconds});
}

void LossRecorder::on_resume(const std::vector<ProgressEvent>& earlier) {
  for (const auto& e : earlier) on_iteration(e);
}

std::string LossRecorder::csv() const {
  std::ostringstream s;
  s << "stage_index,stage,iteration,loss,seconds\n";
  s.precision(10);
  for (auto& r : rows_) s << r.stage_index << ",\"" << r.stage << "\"," << r.iteration << "," << r.loss << "," << r.seconds << "\n";
  return s.str();
}

void LossRecorder::plot(const std::string& png, const std::string& title) const {
  CurvePlot cp;
  cp.title = title;
  cp.xlabel = "iteration (all stages)";
  cp.ylabel = "loss";
  cp.log_y = true;
  std::map<int, Series> by_stage;
  // Large outputs repeat the same stages in every window: one color and one legend entry
  // per stage kind ("sigma 2/4"), not per window (a 10,000-point canvas has 100 stages).
  const std::string kWindow = "window ";
  std::map<std::string, int> kinds;
  int x = 0;
  for (auto& r : rows_) {
    auto& s = by_stage[r.stage_index];
    std::string kind = r.stage;
    const bool windowed = kind.rfind(kWindow, 0) == 0 && kind.find(", ") != std::string::npos;
    if (windowed) kind = kind.substr(kind.find(", ") + 2);
    const auto known = kinds.find(kind);
    s.color = known != kinds.end() ? known->second : static_cast<int>(kinds.size());
    s.label = !windowed ? r.stage : known == kinds.end() || s.label == kind ? kind : "";
    if (known == kinds.end()) kinds.emplace(kind, s.color);
    s.x.push_back(x++);
    s.y.push_back(r.loss);
  }
  for (auto& [_, s] : by_stage) cp.series.push_back(s);
  if (!cp.series.empty()) plot_curves(png, cp);
}

void SnapshotWriter::on_stage_end(const ProgressEvent& e, const PointSet& current) {
  if (!enabled_ || !e.window_ends) return;  // large outputs: one snapshot per window
  char base[64];
  std::snprintf(base, sizeof base, "/stage%02d", e.stage_index + 1);
  // A window of a large output: its grid's part (the window's points and what they saw).
  const PointSet shown = e.windows > 1 ? current.crop(e.window_grid) : current;
  write_points(dir_ + base + ".txt", shown, Format::Plain);
  PointStyle st;
  st.title = e.stage;
  plot_points(dir_ + base + ".png", shown, st, 400);
  pngs_.push_back(dir_ + base + ".png");
  titles_.push_back(e.stage);
}

}  // namespace ppsynth
