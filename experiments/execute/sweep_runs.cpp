#include "experiments/execute/sweep_runs.hpp"

#include <algorithm>
#include <ctime>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"
#include "core/run_directory.hpp"
#include "core/run_json.hpp"
#include "optim/run/checkpoint_store.hpp"
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
          const RunRecord run = read_run_record(dir + "/run.json");
          char buf[64];
          // The CPU time beside the wall time: runs sharing the cores inflate only the latter.
          if (run.cpu_seconds > 0)
            std::snprintf(buf, sizeof buf, "%.1f s (CPU %.1f s)", run.total_seconds, run.cpu_seconds);
          else
            std::snprintf(buf, sizeof buf, "%.1f s", run.total_seconds);
          s.detail = buf;
        } catch (const InputError& e) {
          s.detail = e.what();
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

RowState run_sweep_task(const std::string& sweep_dir, const std::string& row_id, const std::string& manifest_hash,
                        const std::atomic<bool>* stop) {
  const SweepManifest m = load_sweep(sweep_dir);
  const auto it = std::find_if(m.rows.begin(), m.rows.end(), [&](const SweepRow& r) { return r.id == row_id; });
  if (it == m.rows.end())
    throw InputError("sweep " + sweep_dir + ": no row " + row_id + " in its plan (" + std::to_string(m.rows.size()) +
                     " rows): it was planned again without it since this task was given it; nothing was run");
  if (!manifest_hash.empty() && manifest_hash != sweep_manifest_hash(m))
    spdlog::warn("sweep {}: planned again since this task was given it (manifest {}, now {}); row {} is in the new plan "
                 "with the same config (an id is its config's hash), so it runs as planned",
                 sweep_dir, manifest_hash, sweep_manifest_hash(m), row_id);
  const SweepRow& row = *it;
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
        if (CheckpointStore(checkpoint_file_in(dir)).exists()) {
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
