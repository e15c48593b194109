#pragma once
// StageRecord: one finished stage of a method that works in stages (the Gabor method's class
// and sigma stages, its border relaxes, its windows), typed from the method to synthesize(),
// the command and the Python package. run.json shows each as one flat object
// (method_stats.stages); a checkpoint keeps them in that form too.
//
// Torch-free, as optim/method/method.hpp.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

struct StageRecord {
  std::string stage;      // its label: "class 1/2 (id 0), sigma 3/4", "window 2/6, ..."
  int iterations = 0;     // run in this stage (0: it had no point to move, or nothing to do)
  double final_loss = 0;  // the loss at its last iteration (0 when it ran none)
  double seconds = 0;     // its wall time
  // What the method and the stage's kind add of their own (the Gabor method: class, sigma,
  // k; a border relax: parked_over_uniform, relaxed; a new kind: its fields), shown in run.json
  // beside the four above.
  nlohmann::json details = nlohmann::json::object();
};

// What a method that works in stages reports of them (SynthesisContext::stages).
struct StagesReport {
  std::vector<StageRecord> stages;   // in order; a resumed run's earlier stages included
  double seconds_before_resume = 0;  // the wall time of the processes before a resume, up to their last checkpoint
  double cpu_seconds_before_resume = 0;  // their CPU time (core/process_cpu.hpp), likewise; -1: unknown
};

// run.json's form: one flat object of the four fields and the details'.
nlohmann::json to_json(const StageRecord& r);
nlohmann::json to_json(const std::vector<StageRecord>& records);
// Back from that form; std::invalid_argument saying which field is missing or malformed
// (the reader that calls it names its file).
StageRecord stage_record_from_json(const nlohmann::json& j);
std::vector<StageRecord> stage_records_from_json(const nlohmann::json& list);

}  // namespace ppsynth
