#pragma once
// Everything a synthesis needs to continue exactly where it stopped: a checkpoint. Small on
// purpose (positions, the optimizer's moments, the generator's state, the loss history; no
// feature maps or targets, which are recomputed from the exemplar and the seed). Restoring it
// and running on gives the same bits as never stopping (same config, seed and thread count).
#include <torch/torch.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/checkpoint_file.hpp"

#include "core/point_set.hpp"
#include "optim/method/stage_record.hpp"
#include "optim/steps/position_optimizer.hpp"

namespace ppsynth {

struct LossRecord {
  int stage = 0;
  int iteration = 0;
  double loss = 0;
  double seconds = 0;  // wall time since the stage began
};

struct SynthesisState {
  std::vector<Vec2> positions;       // the whole output; moving points as of their stage's start
  int stage = 0;                     // the stage in progress (or next to start)
  int iteration = 0;                 // iterations done in `stage`
  torch::Tensor moving;              // the group's optimized positions, unwrapped (undefined: none yet)
  // The group's points (output indices): chosen as the group starts (windows choose by
  // position, so a resumed run must not choose again), and the points no window moves again.
  std::vector<int64_t> group_moving, group_frozen;
  std::vector<uint8_t> final_points;  // windows only (empty otherwise)
  OptimizerState optimizer;          // the optimizer's state (empty at a stage start)
  std::string rng;                   // the jitter generator (std::mt19937_64, text form)
  std::vector<double> stage_losses;  // losses of `stage` so far (the convergence window)
  std::vector<double> stage_watch;   // the stopping rule's record of `stage` (optim/steps/stopping_rule.hpp)
  torch::Tensor stage_best;          // `moving` at the stage's best iterate, when the rule keeps one (else undefined)
  double stage_scale = -1;           // the point terms' unit (the stage's first loss), -1 unset
  std::vector<LossRecord> history;   // every iteration of every stage so far
  std::vector<StageRecord> stages;   // one record per finished stage
  nlohmann::json phase_seconds = nlohmann::json::object();
  // Which synthesis the state continues (core/checkpoint_file.hpp's key; SynthesisContext).
  nlohmann::json key = nlohmann::json::object();
};

// Bytes <-> state: a checkpoint file (core/checkpoint_file.hpp: tensors bit for bit, a
// checksum over everything). Reading checks the file, and the type and shape of every array
// (InputError naming `source` and the array); the engine restoring it checks the values
// against its plan (indices in range, optim/gabor/engine/gabor_engine.cpp).
std::string serialize_state(const SynthesisState& state);
SynthesisState deserialize_state(const std::string& bytes, const std::string& source);

// A tensor as a checkpoint array and back (float32, float64, int64 and uint8, any shape), bit
// for bit.
CheckpointArray tensor_array(const torch::Tensor& t);
torch::Tensor array_tensor(const CheckpointArray& a);

}  // namespace ppsynth
