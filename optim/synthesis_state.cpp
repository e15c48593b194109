#include "optim/synthesis_state.hpp"

#include <sstream>

#include "core/error.hpp"

namespace ppsynth {

namespace {

// Bump when the layout changes: old checkpoints are then refused. 2: the group's points and
// the final flags (windows); 3: the stopping rule's record of the stage.
const int64_t kFormat = 3;

torch::Tensor doubles(const std::vector<double>& v) {
  return torch::from_blob(const_cast<double*>(v.data()), {static_cast<int64_t>(v.size())}, torch::kFloat64).clone();
}

torch::Tensor longs(const std::vector<int64_t>& v) {
  return torch::from_blob(const_cast<int64_t*>(v.data()), {static_cast<int64_t>(v.size())}, torch::kInt64).clone();
}

template <class T>
std::vector<T> to_vector_of(const torch::Tensor& t) {
  auto c = t.contiguous();
  return std::vector<T>(c.data_ptr<T>(), c.data_ptr<T>() + c.numel());
}

std::vector<double> to_vector(const torch::Tensor& t) {
  auto c = t.contiguous();
  return std::vector<double>(c.data_ptr<double>(), c.data_ptr<double>() + c.numel());
}

}  // namespace

std::string serialize_state(const SynthesisState& s) {
  torch::serialize::OutputArchive a;
  std::vector<double> xy;
  xy.reserve(2 * s.positions.size());
  for (const auto& p : s.positions) xy.insert(xy.end(), {p.x, p.y});
  a.write("positions", doubles(xy));
  a.write("has_moving", torch::tensor(int64_t{s.moving.defined() ? 1 : 0}));
  if (s.moving.defined()) a.write("moving", s.moving.detach().cpu());  // read back on the CPU, moved by the engine
  a.write("stage_losses", doubles(s.stage_losses));
  a.write("stage_watch", doubles(s.stage_watch));
  if (s.stage_best.defined()) a.write("stage_best", s.stage_best.detach().cpu());
  a.write("group_moving", longs(s.group_moving));
  a.write("group_frozen", longs(s.group_frozen));
  a.write("final_points", torch::from_blob(const_cast<uint8_t*>(s.final_points.data()),
                                           {static_cast<int64_t>(s.final_points.size())}, torch::kUInt8).clone());
  std::vector<double> losses, seconds;
  nlohmann::json where = nlohmann::json::array();
  for (const auto& r : s.history) {
    losses.push_back(r.loss);
    seconds.push_back(r.seconds);
    where.push_back({r.stage, r.iteration});
  }
  a.write("history_loss", doubles(losses));
  a.write("history_seconds", doubles(seconds));
  const nlohmann::json meta = {{"format", kFormat},         {"stage", s.stage},
                               {"iteration", s.iteration},  {"stage_scale", s.stage_scale},
                               {"rng", s.rng},              {"optimizer", !s.optimizer.empty()},
                               {"history_where", where},    {"stages", s.stages},
                               {"phase_seconds", s.phase_seconds}};
  a.write("meta", c10::IValue(meta.dump()));
  if (!s.optimizer.empty())  // raw bytes, as a byte tensor (strings in an archive are text)
    a.write("optimizer", torch::from_blob(const_cast<char*>(s.optimizer.data()), {static_cast<int64_t>(s.optimizer.size())},
                                          torch::kUInt8).clone());
  std::ostringstream out;
  a.save_to(out);
  return out.str();
}

SynthesisState deserialize_state(const std::string& bytes, const std::string& source) {
  SynthesisState s;
  try {
    torch::serialize::InputArchive a;
    std::istringstream in(bytes);
    a.load_from(in);
    c10::IValue meta_v;
    a.read("meta", meta_v);
    const nlohmann::json meta = nlohmann::json::parse(meta_v.toStringRef());
    if (meta.value("format", int64_t{0}) != kFormat)
      throw file_error(source, 0, "a checkpoint of another ppsynth version (format " + meta["format"].dump() + ")");
    // A fresh tensor per key: reading into a defined tensor would set_() it in place.
    auto read = [&](const char* key) {
      torch::Tensor t;
      a.read(key, t);
      return t;
    };
    const auto xy = to_vector(read("positions"));
    for (size_t i = 0; i + 1 < xy.size(); i += 2) s.positions.push_back(Vec2{xy[i], xy[i + 1]});
    if (read("has_moving").item<int64_t>() != 0) s.moving = read("moving");
    s.stage_losses = to_vector(read("stage_losses"));
    s.stage_watch = to_vector(read("stage_watch"));
    {  // absent when the stage has no best iterate kept (and in checkpoints of earlier versions)
      torch::Tensor best;
      if (a.try_read("stage_best", best)) s.stage_best = best;
    }
    s.group_moving = to_vector_of<int64_t>(read("group_moving"));
    s.group_frozen = to_vector_of<int64_t>(read("group_frozen"));
    s.final_points = to_vector_of<uint8_t>(read("final_points"));
    const auto losses = to_vector(read("history_loss")), seconds = to_vector(read("history_seconds"));
    const auto& where = meta.at("history_where");
    for (size_t i = 0; i < losses.size(); ++i)
      s.history.push_back({where.at(i).at(0).get<int>(), where.at(i).at(1).get<int>(), losses[i], seconds.at(i)});
    s.stage = meta.at("stage").get<int>();
    s.iteration = meta.at("iteration").get<int>();
    s.stage_scale = meta.at("stage_scale").get<double>();
    s.rng = meta.at("rng").get<std::string>();
    s.stages = meta.at("stages");
    s.phase_seconds = meta.at("phase_seconds");
    if (meta.at("optimizer").get<bool>()) {
      torch::Tensor o = read("optimizer").contiguous();
      s.optimizer.assign(reinterpret_cast<const char*>(o.data_ptr<uint8_t>()), static_cast<size_t>(o.numel()));
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw file_error(source, 0, std::string("not a readable checkpoint: ") + e.what());
  }
  return s;
}

}  // namespace ppsynth
