#pragma once
// Test support: an observer that keeps the output at every stage's end with the stage's label,
// and the note of every stage's beginning (what a stage kind said it moves).
#include <string>
#include <vector>

#include "optim/method/method.hpp"

namespace ppsynth::test {

struct StageEnds : SynthesisObserver {
  std::vector<std::string> labels, notes;
  std::vector<PointSet> points;
  void on_stage_begin(const ProgressEvent& e) override { notes.push_back(e.note); }
  void on_stage_end(const ProgressEvent& e, const PointSet& p) override {
    labels.push_back(e.stage);
    points.push_back(p);
  }
};

}  // namespace ppsynth::test
