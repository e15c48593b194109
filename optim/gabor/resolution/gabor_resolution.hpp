#pragma once
// The Gabor method's parameters into its settings: the method's defaults and ranges (its own
// keys, its blocks and its parts' specs, each declared once in its block's file), the params
// read once when the method is created (read_gabor_params), and resolve_gabor_settings, which
// resolves them for one exemplar and output into GaborSettings
// (optim/gabor/settings/gabor_settings.hpp); errors name the key.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/output_shape.hpp"
#include "core/point_set.hpp"
#include "optim/gabor/settings/gabor_settings.hpp"

namespace ppsynth {

// The "gabor" method's defaults (the published code's settings, method.md §2-5): its own keys
// and blocks, and the block (method.<name>) of each class-end stage kind registered so far as
// the kind declares it; a kind registered after the method adds its block to the method's
// entry itself (register_stage_kind, optim/gabor/stages/stage_kind.hpp).
nlohmann::json gabor_defaults();
// The range of each numeric default (core/config/param_bounds.hpp), checked on creation.
nlohmann::json gabor_bounds();

// The method's params as read when it is created: its own keys, typed by GaborOptions' table,
// and each class-end kind's block (method.<name>) as its registry entry merged and checked it,
// which the kind reads through its own table when the settings resolve.
struct GaborParams {
  GaborOptions options;
  std::map<std::string, nlohmann::json> stage_kinds;
};

// From the method's (defaults-merged) params; errors name `key_path`.<key>. Every key is read,
// by the table or as a kind's block: a key read that the params lack, or a key they hold that
// nothing reads, is a std::logic_error (declared but not read, or read but not declared).
GaborParams read_gabor_params(const nlohmann::json& params, const std::string& key_path = "method");

// Resolves settings from the method's params for an output of `shape`; errors name the key.
GaborSettings resolve_gabor_settings(const GaborParams& params, const PointSet& exemplar, const OutputShape& shape, bool quick);
// The same for params as JSON (read_gabor_params, then resolved).
GaborSettings resolve_gabor_settings(const nlohmann::json& params, const PointSet& exemplar, const OutputShape& shape, bool quick);

// The map weights of Eq. 5 for a config's "map_attributes": null or "auto" = every attribute column
// that is not constant; or an explicit list of names. Returns column indices.
std::vector<int> map_attribute_columns(const PointSet& exemplar, const nlohmann::json& spec);


}  // namespace ppsynth
