#pragma once
// A stage kind is a policy: what a stage of the plan (optim/gabor/stages/stage_plan.hpp) does with the
// points it is given, asked by the engine (optim/gabor/engine/gabor_engine.hpp), which never asks
// which kind it runs:
//
//   start    which moving points get a gradient, and why (shown where the user watches)
//   cap      how many iterations at most; judged: whether the stopping rule may end it sooner
//   measure  whether the torus is rolled every iteration
//   step     the optimizer's spec (a learning rate of its own)
//   terms    point terms of its own, beside the run's method.terms
//
// The paper's stage is SigmaStage (optim/gabor/stages/sigma_stage.hpp). Kinds that follow each
// class's sigma stages (BorderRelaxStage, optim/gabor/stages/border_relax/border_relax_stage.hpp)
// register under a name with PPSYNTH_REGISTER_STAGE_KIND, declaring their options block
// method.<name> by its table (core/config/params.hpp: each key's default, range and doc line,
// once; the method's defaults, bounds and reference list it): a factory gets that block read
// through the table, typed, with the resolved settings, and returns the kind, or null when the
// block does not ask for it. A kind's record fields are its own: the checkpoint keeps them
// as they are, and record_problem() checks them when a run resumes. A new kind is one file:
// its class and its registration (tests/optim/gabor/test_stage_kinds.cpp adds one,
// test_stage_kind_options.cpp one with options and a record it resumes from).
#include <torch/torch.h>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"
#include "core/registry.hpp"
#include "optim/method/stage_record.hpp"
#include "optim/terms/point_term.hpp"

namespace ppsynth {

struct GaborSettings;
struct Stage;

// What a kind sees when one of its stages starts (or restarts from a checkpoint: the same
// view, since the output changes only at stage ends and a checkpoint holds it).
struct StageStartView {
  const Stage& stage;
  const GaborSettings& settings;
  const PointSet& output;                 // every output point, as the stage starts
  const std::vector<size_t>& moving;      // output indices of the stage's moving points
  const std::vector<StageRecord>& finished_stages;  // the records of the stages before (run.json "stages")
};

// What a kind decides as its stage starts.
struct StageStart {
  // [moving x 1] bool (CPU): the moving points that get a gradient; the others stay where
  // they are. Undefined: all move. None true: the stage ends at once.
  torch::Tensor moving_mask;
  std::string note;  // with the stage's first progress event: why it moves what it moves
  nlohmann::json record = nlohmann::json::object();  // the kind's fields of the stage's record (StageRecord::details)
};

class StageKind {
 public:
  virtual ~StageKind() = default;
  // A class-end kind's stage label, after "class i/K, " ("border relax").
  virtual std::string label() const = 0;
  virtual int iteration_cap(const GaborSettings& settings) const = 0;
  virtual bool judged() const = 0;      // the stopping rule judges its iterations (else it runs its cap)
  virtual bool rolls_grid() const = 0;  // the torus is measured rolled by a new offset every iteration
  // A class-end kind: its stages follow every class's sigma stages, each a group of its own
  // measuring every class (true), or each last in its own class's group (false).
  virtual bool after_all_classes() const { return false; }
  // Whether the plan holds its stages for an exemplar of `classes` classes (a kind that moves
  // a class beside the others has nothing to do with one).
  virtual bool acts_on(int /*classes*/) const { return true; }
  virtual nlohmann::json optimizer(nlohmann::json spec, const GaborSettings& /*settings*/) const { return spec; }
  virtual StageStart start(const StageStartView& /*view*/) const { return {}; }
  // Its point terms (weights in the stage's loss units, as method.terms'), and their entry in
  // run.json's stats.
  std::vector<WeightedPointTerm>& terms() { return terms_; }
  virtual void describe(nlohmann::json& /*stats*/) const {}
  // What is wrong with the kind's own fields in a stage record read back from a checkpoint
  // (StageStart::record's; a resumed run reads them), or "" when nothing is.
  virtual std::string record_problem(const nlohmann::json& /*details*/) const { return ""; }

 protected:
  std::vector<WeightedPointTerm> terms_;
};

// Class-end kinds by name. The factory gets the kind's block method.<name> (GaborSettings::
// stage_kinds), its key path and the settings; it returns null when the block does not ask for
// the kind, and throws config_error naming the key for a block it cannot run. A kind registers
// with PPSYNTH_REGISTER_STAGE_KIND (below), whose factory gets the block read through its table.
using StageKindRegistry = Registry<StageKind, const GaborSettings&>;

// The class-end kinds the settings ask for, in name order.
std::vector<std::shared_ptr<StageKind>> class_end_kinds(const GaborSettings& settings);

// Registers a class-end kind, and its block under the "gabor" method's defaults and bounds
// (whichever of the two registers first; PPSYNTH_REGISTER_STAGE_KIND).
bool register_stage_kind(const std::string& name, StageKindRegistry::Entry entry);

}  // namespace ppsynth

// PPSYNTH_REGISTER_STAGE_KIND("name", Options::params(), "description",
//     [](const Options& o, const std::string& key_path, const GaborSettings& s) -> std::unique_ptr<StageKind> { ... }):
// a kind declared by its table, as PPSYNTH_REGISTER_PARAMS declares a part (core/registry.hpp).
// Its block method.<name>'s defaults and bounds come from the table, so do the reference's doc
// lines (under the "gabor" method's, whose block it is), and the factory gets the block read
// through it (read_through). A kind without options declares an empty table.
#define PPSYNTH_REGISTER_STAGE_KIND(NAME, TABLE, DESC, ...)                                                    \
  namespace {                                                                                                   \
  [[maybe_unused]] const bool PPSYNTH_CONCAT(ppsynth_stage_kind_, __LINE__) = ::ppsynth::register_stage_kind(   \
      NAME, ::ppsynth::StageKindRegistry::Entry{::ppsynth::read_through(TABLE, __VA_ARGS__), (TABLE).defaults(), \
                                                (TABLE).bounds(), DESC});                                       \
  }                                                                                                             \
  PPSYNTH_PARAM_DOCS("method", "gabor", [] { return nlohmann::json{{NAME, (TABLE).docs()}}; })
