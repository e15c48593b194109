#include "optim/gabor/stages/synthesis_state.hpp"

#include <cstring>

#include "core/error.hpp"

namespace ppsynth {

namespace {

// Bump when the layout of the arrays or the meta changes: older checkpoints are then refused.
// 4: a checkpoint file of core/checkpoint_file.hpp (checksum, key, typed arrays).
const int64_t kLayout = 4;

torch::Dtype dtype_of(ArrayType t) {
  switch (t) {
    case ArrayType::F64: return torch::kFloat64;
    case ArrayType::F32: return torch::kFloat32;
    case ArrayType::I64: return torch::kInt64;
    case ArrayType::U8: return torch::kUInt8;
  }
  return torch::kFloat64;
}

const char* kOptimizerPrefix = "optimizer.";

}  // namespace

CheckpointArray tensor_array(const torch::Tensor& t_in) {
  const torch::Tensor t = t_in.detach().contiguous().cpu();
  CheckpointArray a;
  switch (t.scalar_type()) {
    case torch::kFloat64: a.type = ArrayType::F64; break;
    case torch::kFloat32: a.type = ArrayType::F32; break;
    case torch::kInt64: a.type = ArrayType::I64; break;
    case torch::kUInt8: a.type = ArrayType::U8; break;
    default: throw std::logic_error(std::string("a checkpoint holds no tensors of type ") + c10::toString(t.scalar_type()));
  }
  a.shape.assign(t.sizes().begin(), t.sizes().end());
  a.bytes.assign(static_cast<const char*>(t.data_ptr()), t.numel() * t.element_size());
  return a;
}

torch::Tensor array_tensor(const CheckpointArray& a) {
  torch::Tensor t = torch::empty(a.shape, torch::TensorOptions().dtype(dtype_of(a.type)));
  if (!a.bytes.empty()) std::memcpy(t.data_ptr(), a.bytes.data(), a.bytes.size());
  return t;
}

std::string serialize_state(const SynthesisState& s) {
  CheckpointFile f;
  f.key = s.key;
  std::vector<double> xy;
  xy.reserve(2 * s.positions.size());
  for (const auto& p : s.positions) xy.insert(xy.end(), {p.x, p.y});
  f.put_doubles("positions", xy, {static_cast<int64_t>(s.positions.size()), 2});
  if (s.moving.defined()) f.put("moving", tensor_array(s.moving));
  if (s.stage_best.defined()) f.put("stage_best", tensor_array(s.stage_best));
  f.put_doubles("stage_losses", s.stage_losses);
  f.put_doubles("stage_watch", s.stage_watch);
  f.put_ints("group_moving", s.group_moving);
  f.put_ints("group_frozen", s.group_frozen);
  f.put_bytes("final_points", s.final_points);
  std::vector<double> losses, seconds;
  std::vector<int64_t> where;
  for (const auto& r : s.history) {
    losses.push_back(r.loss);
    seconds.push_back(r.seconds);
    where.insert(where.end(), {r.stage, r.iteration});
  }
  f.put_doubles("history_loss", losses);
  f.put_doubles("history_seconds", seconds);
  f.put_ints("history_where", where);
  for (const auto& [name, t] : s.optimizer) f.put(kOptimizerPrefix + name, tensor_array(t));
  f.meta = {{"layout", kLayout},   {"stage", s.stage},   {"iteration", s.iteration}, {"stage_scale", s.stage_scale},
            {"rng", s.rng},        {"stages", to_json(s.stages)}, {"phase_seconds", s.phase_seconds}};
  return encode_checkpoint(f);
}

SynthesisState deserialize_state(const std::string& bytes, const std::string& source) {
  const CheckpointFile f = decode_checkpoint(bytes, source);
  auto refuse = [&](const std::string& what) { return checkpoint_error(source, what); };
  const nlohmann::json& m = f.meta;
  if (m.value("layout", nlohmann::json()) != kLayout)
    throw refuse("a checkpoint of another ppsynth version (layout " + m.value("layout", nlohmann::json()).dump() + ")");
  auto whole = [&](const char* k) {
    if (!m.contains(k) || !m[k].is_number_integer() || m[k].get<int64_t>() < 0 || m[k].get<int64_t>() > 1000000000)
      throw refuse(std::string("meta '") + k + "': expected a whole number");
    return m[k].get<int>();
  };
  SynthesisState s;
  s.key = f.key;
  s.stage = whole("stage");
  s.iteration = whole("iteration");
  if (!m.contains("stage_scale") || !m["stage_scale"].is_number()) throw refuse("meta 'stage_scale': expected a number");
  s.stage_scale = m["stage_scale"].get<double>();
  if (!m.contains("rng") || !m["rng"].is_string()) throw refuse("meta 'rng': expected the generator's state");
  s.rng = m["rng"].get<std::string>();
  // Each finished stage's record, as finish_stage writes it: its four fields checked by the
  // record's reader; its details are the method's and its stage kind's, kept as they are (the
  // engine and each kind check their own when a run resumes).
  try {
    s.stages = stage_records_from_json(m.contains("stages") ? m["stages"] : nlohmann::json());
  } catch (const std::invalid_argument& e) {
    throw refuse(std::string("meta 'stages': ") + e.what());
  }
  if (!m.contains("phase_seconds") || !m["phase_seconds"].is_object()) throw refuse("meta 'phase_seconds': expected an object");
  for (const auto& [k, v] : m["phase_seconds"].items())
    if (!v.is_number() || !(v.get<double>() >= 0)) throw refuse("meta 'phase_seconds." + k + "': expected seconds >= 0");
  s.phase_seconds = m["phase_seconds"];

  const CheckpointArray& xy = f.get("positions", ArrayType::F64, 2);
  if (xy.shape[1] != 2) throw refuse("array 'positions': expected n x 2");
  const std::vector<double> p(reinterpret_cast<const double*>(xy.bytes.data()),
                              reinterpret_cast<const double*>(xy.bytes.data()) + xy.count());
  for (size_t i = 0; i + 1 < p.size(); i += 2) s.positions.push_back(Vec2{p[i], p[i + 1]});
  for (const char* k : {"moving", "stage_best"})
    if (f.has(k)) {
      const CheckpointArray& a = f.get(k, ArrayType::F32, 2);
      if (a.shape[1] != 2) throw refuse(std::string("array '") + k + "': expected n x 2");
      (std::strcmp(k, "moving") == 0 ? s.moving : s.stage_best) = array_tensor(a);
    }
  s.stage_losses = f.doubles("stage_losses");
  s.stage_watch = f.doubles("stage_watch");
  s.group_moving = f.ints("group_moving");
  s.group_frozen = f.ints("group_frozen");
  s.final_points = f.bytes("final_points");
  const auto losses = f.doubles("history_loss"), seconds = f.doubles("history_seconds");
  const auto where = f.ints("history_where");
  if (seconds.size() != losses.size() || where.size() != 2 * losses.size())
    throw refuse("arrays 'history_*': of different lengths");
  for (size_t i = 0; i < losses.size(); ++i) {
    if (where[2 * i] < 0 || where[2 * i] > 1000000000 || where[2 * i + 1] < 0 || where[2 * i + 1] > 1000000000)
      throw refuse("array 'history_where': a stage or iteration out of range");
    s.history.push_back({static_cast<int>(where[2 * i]), static_cast<int>(where[2 * i + 1]), losses[i], seconds[i]});
  }
  const std::string prefix = kOptimizerPrefix;
  for (const auto& name : f.names())
    if (name.rfind(prefix, 0) == 0) s.optimizer[name.substr(prefix.size())] = array_tensor(f.raw(name));
  return s;
}

}  // namespace ppsynth
