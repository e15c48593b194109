#pragma once
// A checkpoint on disk (checkpoint.bin): typed arrays and JSON that prove where they belong
// and that they are intact. Torch-free, so that its reader is fuzzed (tests/fuzz) like the
// point readers; optim/gabor/stages/synthesis_state.hpp puts a synthesis's state into one.
//
// Layout (integers little-endian):
//   "ppsynth-checkpoint\n"      magic
//   u64 H, then H bytes of JSON  {"format": 1, "key": {...}, "meta": {...},
//                                 "arrays": [{"name": "positions", "type": "f64", "shape": [n, 2]}, ...]}
//   the arrays' bytes            one after another, in the header's order
//   u64                          FNV-1a 64 (core/content_hash.hpp) of every byte before it
//
// The reader refuses, as an InputError naming the file (and the array or key): a wrong magic
// or format, a checksum that does not match (a flipped byte anywhere), a header that is not
// the layout above, sizes that do not add up to the file, and any float array holding a NaN
// or an infinity. `key` says which synthesis the checkpoint continues (checkpoint_key_difference);
// `meta` is the writer's.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace ppsynth {

// A checkpoint that cannot be continued from (damaged, of another version, or of another
// synthesis): an InputError a front end can tell apart, to say how to start afresh.
class CheckpointError : public InputError {
 public:
  using InputError::InputError;
};
// "source: what" as a CheckpointError.
CheckpointError checkpoint_error(const std::string& source, const std::string& what);

enum class ArrayType { F64, F32, I64, U8 };
const char* array_type_name(ArrayType t);
size_t array_type_size(ArrayType t);

struct CheckpointArray {
  ArrayType type = ArrayType::F64;
  std::vector<int64_t> shape;  // empty: a scalar
  std::string bytes;           // count() elements of the type, little-endian
  size_t count() const;
};

class CheckpointFile {
 public:
  nlohmann::json key = nlohmann::json::object();
  nlohmann::json meta = nlohmann::json::object();
  std::string source = "checkpoint";  // names the file in errors

  // Adds (or replaces) an array; its byte count must match the shape.
  void put(const std::string& name, CheckpointArray array);
  void put_doubles(const std::string& name, const std::vector<double>& v, std::vector<int64_t> shape = {});
  void put_ints(const std::string& name, const std::vector<int64_t>& v);
  void put_bytes(const std::string& name, const std::vector<uint8_t>& v);

  bool has(const std::string& name) const { return arrays_.count(name) > 0; }
  // The array `name`, of `type` and `rank` dimensions (rank < 0: any); InputError naming the
  // file and the array when it is absent or another type or rank.
  const CheckpointArray& get(const std::string& name, ArrayType type, int rank) const;
  std::vector<double> doubles(const std::string& name) const;  // f64, rank 1
  std::vector<int64_t> ints(const std::string& name) const;    // i64, rank 1
  std::vector<uint8_t> bytes(const std::string& name) const;   // u8, rank 1
  const std::vector<std::string>& names() const { return order_; }
  const CheckpointArray& raw(const std::string& name) const { return arrays_.at(name); }  // one of names()

 private:
  std::map<std::string, CheckpointArray> arrays_;
  std::vector<std::string> order_;  // insertion order: the file's
};

std::string encode_checkpoint(const CheckpointFile& file);
// Every check above; `source` names the file in errors.
CheckpointFile decode_checkpoint(const std::string& bytes, const std::string& source);

// How the key a checkpoint carries (`found`) differs from the synthesis about to continue
// from it (`expected`), in words, e.g. "seed 96 (the checkpoint's: 95)" or "config key
// 'method.c2' = 2 (the checkpoint's: 1)"; "" when they agree. Keys: "method", "method_version",
// "seed", "quick", "exemplar" (a content hash of the points), "config_hash" and "config" (the
// resolved config, for naming the keys that differ).
std::string checkpoint_key_difference(const nlohmann::json& expected, const nlohmann::json& found);

}  // namespace ppsynth
