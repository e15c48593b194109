#include "optim/sweep/sweep_runs.hpp"

#include <ctime>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"
#include "core/run_directory.hpp"
#include "optim/run/run_synthesis.hpp"

namespace fs = std::filesystem;

namespace ppsynth {

namespace {

std::string failure_file(const std::string& sweep_dir, const SweepRow& row) {
  return (fs::path(sweep_dir) / "logs" / (row.id + ".failed")).string();
}

}  // namespace

const char* row_state_name(RowState s) {
  switch (s) {
    case RowState::Pending: return "pending";
    case RowState::Running: return "running";
    case RowState::Interrupted: return "interrupted";
    case RowState::Failed: return "failed";
    case RowState::Done: return "done";
  }
  return "?";
}

std::vector<RowStatus> sweep_status(const std::string& sweep_dir, const SweepManifest& m) {
  std::vector<RowStatus> out;
  for (const auto& row : m.rows) {
    RowStatus s;
    s.row = &row;
    const std::string dir = (fs::path(sweep_dir) / row.dir).string();
    const std::string failed = failure_file(sweep_dir, row);
    switch (run_dir_state(dir)) {
      case RunDirState::Complete: {
        s.state = RowState::Done;
        try {
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.1f s", read_run_json(dir + "/run.json").value("total_seconds", 0.0));
          s.detail = buf;
        } catch (const InputError&) {
        }
        break;
      }
      case RunDirState::Unfinished:
        s.state = run_dir_locked(dir) ? RowState::Running : RowState::Interrupted;
        s.detail = run_progress_text(run_dir_marker(dir), static_cast<long long>(std::time(nullptr)));
        break;
      case RunDirState::Foreign:
        s.state = RowState::Failed;
        s.detail = dir + " holds files that are not a ppsynth run";
        break;
      default:
        s.state = fs::exists(failed) ? RowState::Failed : RowState::Pending;
        if (s.state == RowState::Failed) s.detail = read_file_text(failed);
    }
    if (s.state == RowState::Interrupted && fs::exists(failed))
      s.detail += (s.detail.empty() ? "" : "; ") + read_file_text(failed);
    while (!s.detail.empty() && s.detail.back() == '\n') s.detail.pop_back();
    out.push_back(s);
  }
  return out;
}

RowState run_sweep_task(const std::string& sweep_dir, size_t index, const std::atomic<bool>* stop) {
  const SweepManifest m = load_sweep(sweep_dir);
  if (index >= m.rows.size())
    throw InputError("sweep " + sweep_dir + ": no row " + std::to_string(index) + " (the plan has " +
                     std::to_string(m.rows.size()) + ")");
  const SweepRow& row = m.rows[index];
  const std::string dir = (fs::path(sweep_dir) / row.dir).string();
  const std::string failed = failure_file(sweep_dir, row);
  RunRequest req;
  req.dir = dir;
  req.quick = row.quick;
  req.stop = stop;
  try {
    switch (run_dir_state(dir)) {
      case RunDirState::Complete:
        spdlog::info("[{}] {} is done already", row.id, row.label);
        return RowState::Done;
      case RunDirState::Unfinished:
        if (fs::exists(dir + "/checkpoint.bin")) {
          spdlog::info("[{}] resuming {}", row.id, row.label);
          resume_synthesis(dir, req);
          break;
        }
        req.force = true;  // this sweep's own run, stopped before its first checkpoint
        [[fallthrough]];
      default:
        spdlog::info("[{}] running {}", row.id, row.label);
        run_synthesis(row.config, req);
    }
  } catch (const RunInterrupted&) {
    throw;
  } catch (const std::exception& e) {
    write_text_atomic(failed, std::string(e.what()) + "\n");
    throw;
  }
  std::error_code ec;
  fs::remove(failed, ec);
  return RowState::Done;
}

}  // namespace ppsynth
