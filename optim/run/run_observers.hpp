#pragma once
// Observers the commands attach to a synthesis (optim never prints or writes files):
//   ProgressLog     : a line per stage and every few iterations: loss, it/s, ETA; for large
//                     outputs a line per window: windows done / total, canvas ETA.
//   LossRecorder    : every iteration's loss, per stage, for the CSV and the curve plot.
//   SnapshotWriter  : the initialization and the output after every stage (paper Fig. 4), or
//                     the window's grid after every window of a large output.
#include <chrono>
#include <string>
#include <vector>

#include "optim/method/method.hpp"

namespace ppsynth {

class ProgressLog : public SynthesisObserver {
 public:
  explicit ProgressLog(std::string name, int every = 10) : name_(std::move(name)), every_(every) {}
  void on_stage_begin(const ProgressEvent& e) override;
  void on_iteration(const ProgressEvent& e) override;
  void on_stage_end(const ProgressEvent& e, const PointSet&) override;
  void on_resume(const std::vector<ProgressEvent>& earlier) override;

 private:
  std::string name_;
  int every_;
  // Canvas progress: windows finished since this process began, and when it began.
  int windows_done_here_ = 0;
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
};

class LossRecorder : public SynthesisObserver {
 public:
  void on_iteration(const ProgressEvent& e) override;
  void on_resume(const std::vector<ProgressEvent>& earlier) override;
  struct Row {
    int stage_index;
    std::string stage;
    int iteration;
    double loss, seconds;
  };
  const std::vector<Row>& rows() const { return rows_; }
  std::string csv() const;
  void plot(const std::string& png_path, const std::string& title) const;

 private:
  std::vector<Row> rows_;
};

class SnapshotWriter : public SynthesisObserver {
 public:
  explicit SnapshotWriter(std::string dir) : dir_(std::move(dir)) {}
  void on_start(const PointSet& initial) override { initial_ = initial; }
  const PointSet& initial() const { return initial_; }
  void set_enabled(bool on) { enabled_ = on; }  // off: record the initialization only
  void on_stage_end(const ProgressEvent& e, const PointSet& current) override;
  const std::vector<std::string>& pngs() const { return pngs_; }
  const std::vector<std::string>& titles() const { return titles_; }

 private:
  std::string dir_;
  PointSet initial_;
  bool enabled_ = true;
  std::vector<std::string> pngs_, titles_;
};

}  // namespace ppsynth
