#include "optim/steps/position_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <utility>

#include "core/checkpoint_file.hpp"
#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

double learning_rate_for(const json& lr, int s, const std::string& kp) {
  double v = 0;
  if (lr.is_number()) v = lr.get<double>();
  else if (lr.is_array() && !lr.empty() && lr[0].is_number())
    v = lr[std::min<size_t>(static_cast<size_t>(s), lr.size() - 1)].get<double>();
  else throw config_error(kp + ".lr", "expected a number or a list of numbers");
  if (!(v > 0)) throw config_error(kp + ".lr", "must be > 0");
  return v;
}

namespace {

// The key under which LibTorch's optimizers keep a parameter's state: its TensorImpl's address,
// printed as text up to LibTorch 1.x (what c10::guts::to_string wrote, an ostream of the
// pointer) and the pointer itself from 2.x on. The map's own key type says which.
// (A template, so that the branch this LibTorch does not take is not compiled.)
template <class Key = std::decay_t<decltype(std::declval<torch::optim::Optimizer&>().state())>::key_type>
Key state_key(const torch::Tensor& p) {
  if constexpr (std::is_same_v<Key, std::string>) {
    std::ostringstream text;
    text << p.unsafeGetTensorImpl();
    return text.str();
  } else {
    return p.unsafeGetTensorImpl();
  }
}

// Checks of a restored state (optim/gabor/stages/synthesis_state.hpp reads the tensors; these are their values).
class StateReader {
 public:
  // Tensors are read on the CPU and go where the positions are (runtime.device).
  StateReader(const OptimizerState& s, std::string source, torch::Device device)
      : s_(s), source_(std::move(source)), device_(device) {}
  [[noreturn]] void refuse(const std::string& name, const std::string& what) const {
    throw checkpoint_error(source_, "optimizer state '" + name + "': " + what);
  }
  const torch::Tensor& get(const std::string& name) const {
    const auto it = s_.find(name);
    if (it == s_.end()) refuse(name, "missing");
    return it->second;
  }
  bool has(const std::string& name) const { return s_.count(name) > 0; }
  // A tensor of `shape` and `dtype`, finite, and >= 0 when `nonnegative`.
  torch::Tensor tensor(const std::string& name, at::IntArrayRef shape, torch::Dtype dtype, bool nonnegative = false) const {
    const torch::Tensor& t = get(name);
    if (t.sizes() != shape || t.scalar_type() != dtype) refuse(name, "another shape or type than the parameters'");
    if (!torch::isfinite(t).all().item<bool>()) refuse(name, "holds a value that is not finite");
    if (nonnegative && (t < 0).any().item<bool>()) refuse(name, "holds a negative value");
    return t.to(device_, /*non_blocking=*/false, /*copy=*/true);
  }
  int64_t count(const std::string& name, int64_t min, int64_t max) const {
    const torch::Tensor& t = get(name);
    if (t.dim() != 0 || t.scalar_type() != torch::kInt64) refuse(name, "expected a whole number");
    const int64_t v = t.item<int64_t>();
    if (v < min || v > max) refuse(name, std::to_string(v) + " is out of range");
    return v;
  }
  double number(const std::string& name) const {
    const torch::Tensor& t = get(name);
    if (t.dim() != 0 || t.scalar_type() != torch::kFloat64 || !std::isfinite(t.item<double>())) refuse(name, "expected a finite number");
    return t.item<double>();
  }
  void only(std::initializer_list<const char*> names) const {
    for (const auto& [k, v] : s_)
      if (std::none_of(names.begin(), names.end(), [&](const char* n) { return k == n; })) refuse(k, "not a state of this optimizer");
  }

 private:
  const OptimizerState& s_;
  std::string source_;
  torch::Device device_;
};

constexpr int64_t kMaxSteps = 1000000000;

class AdamPositions : public PositionOptimizer {
 public:
  AdamPositions(torch::Tensor p, double lr) : params_(p), adam_({p}, torch::optim::AdamOptions(lr)) {}
  OptimizerState save_state() const override {
    const auto it = adam_.state().find(state_key(params_));
    if (it == adam_.state().end()) return {};
    const auto& st = static_cast<const torch::optim::AdamParamState&>(*it->second);
    return {{"step", torch::tensor(st.step())}, {"exp_avg", st.exp_avg()}, {"exp_avg_sq", st.exp_avg_sq()}};
  }
  void load_state(const OptimizerState& s, const std::string& source) override {
    const StateReader r(s, source, params_.device());
    r.only({"step", "exp_avg", "exp_avg_sq"});
    auto st = std::make_unique<torch::optim::AdamParamState>();
    st->step(r.count("step", 1, kMaxSteps));  // bias corrections divide by 1 - beta^step
    st->exp_avg(r.tensor("exp_avg", params_.sizes(), params_.scalar_type()));
    st->exp_avg_sq(r.tensor("exp_avg_sq", params_.sizes(), params_.scalar_type(), true));
    adam_.state()[state_key(params_)] = std::move(st);
  }
  double step(const std::function<torch::Tensor()>& closure) override {
    adam_.zero_grad();
    auto loss = closure();
    adam_.step();
    return loss.item<double>();
  }

 private:
  torch::Tensor params_;
  torch::optim::Adam adam_;
};

class LbfgsPositions : public PositionOptimizer {
 public:
  LbfgsPositions(torch::Tensor p, double lr, int max_iter)
      : params_(p), lbfgs_({p}, torch::optim::LBFGSOptions(lr).max_iter(max_iter)) {}
  // Its history (old_dirs, old_stps, ro) as stacked tensors; `al` is scratch space that every
  // step writes before reading, so it is not kept.
  OptimizerState save_state() const override {
    const auto it = lbfgs_.state().find(state_key(params_));
    if (it == lbfgs_.state().end()) return {};
    const auto& st = static_cast<const torch::optim::LBFGSParamState&>(*it->second);
    OptimizerState s = {{"func_evals", torch::tensor(st.func_evals())}, {"n_iter", torch::tensor(st.n_iter())}};
    if (st.n_iter() == 0) return s;  // a first step that ended at once: t and prev_loss were never set
    s["t"] = torch::tensor(st.t(), torch::kFloat64);
    s["prev_loss"] = torch::tensor(st.prev_loss(), torch::kFloat64);
    for (const auto& [name, t] : {std::pair<const char*, torch::Tensor>{"d", st.d()}, {"H_diag", st.H_diag()},
                                  {"prev_flat_grad", st.prev_flat_grad()}})
      if (t.defined()) s[name] = t;
    if (!st.old_dirs().empty()) {
      s["old_dirs"] = torch::stack(std::vector<torch::Tensor>(st.old_dirs().begin(), st.old_dirs().end()));
      s["old_stps"] = torch::stack(std::vector<torch::Tensor>(st.old_stps().begin(), st.old_stps().end()));
      s["ro"] = torch::stack(std::vector<torch::Tensor>(st.ro().begin(), st.ro().end()));
    }
    return s;
  }
  void load_state(const OptimizerState& s, const std::string& source) override {
    const StateReader r(s, source, params_.device());
    r.only({"func_evals", "n_iter", "t", "prev_loss", "d", "H_diag", "prev_flat_grad", "old_dirs", "old_stps", "ro"});
    const auto dtype = params_.scalar_type();
    const int64_t n = params_.numel(),
                  history = static_cast<const torch::optim::LBFGSOptions&>(lbfgs_.defaults()).history_size();
    auto st = std::make_unique<torch::optim::LBFGSParamState>();
    st->func_evals(r.count("func_evals", 0, kMaxSteps));
    st->n_iter(r.count("n_iter", 0, kMaxSteps));
    if (st->n_iter() > 0) {
      st->t(r.number("t"));
      st->prev_loss(r.number("prev_loss"));
    }
    if (r.has("d")) st->d(r.tensor("d", {n}, dtype));
    if (r.has("H_diag")) st->H_diag(r.tensor("H_diag", {}, dtype));
    if (r.has("prev_flat_grad")) st->prev_flat_grad(r.tensor("prev_flat_grad", {n}, dtype));
    if (r.has("old_dirs")) {
      const int64_t m = r.get("old_dirs").dim() == 2 ? r.get("old_dirs").size(0) : -1;
      if (m < 1 || m > history) r.refuse("old_dirs", "expected 1 to " + std::to_string(history) + " directions");
      const auto dirs = r.tensor("old_dirs", {m, n}, dtype), stps = r.tensor("old_stps", {m, n}, dtype), ro = r.tensor("ro", {m}, dtype);
      for (int64_t i = 0; i < m; ++i) {
        st->old_dirs().push_back(dirs[i].clone());
        st->old_stps().push_back(stps[i].clone());
        st->ro().push_back(ro[i].clone());
      }
    } else if (r.has("old_stps") || r.has("ro")) {
      r.refuse("old_dirs", "missing beside old_stps and ro");
    }
    lbfgs_.state()[state_key(params_)] = std::move(st);
  }
  double step(const std::function<torch::Tensor()>& closure) override {
    double first = 0;
    bool have = false;
    lbfgs_.step([&] {
      lbfgs_.zero_grad();
      auto l = closure();
      if (!have) first = l.item<double>(), have = true;
      return l;
    });
    return first;
  }

 private:
  torch::Tensor params_;
  torch::optim::LBFGS lbfgs_;
};

}  // namespace
}  // namespace ppsynth

namespace ppsynth {
namespace {
constexpr const char* kLrDoc = "the step size: a number, or a list with one per sigma (the last repeats)";

struct AdamOptions {
  json lr = json::array({0.005, 0.002, 0.002, 0.002});
  static const ParamTable<AdamOptions>& params() {
    using O = AdamOptions;
    static const ParamTable<O> t("method.optimizer", {param("lr", &O::lr, "(0, inf)", kLrDoc)});
    return t;
  }
};

struct LbfgsOptions {
  json lr = json::array({0.5, 0.2, 0.2, 0.2});
  int max_iter = 20;
  static const ParamTable<LbfgsOptions>& params() {
    using O = LbfgsOptions;
    static const ParamTable<O> t("method.optimizer", {
        param("lr", &O::lr, "(0, inf)", kLrDoc),
        param("max_iter", &O::max_iter, "int [1, 10000]", "the loss evaluations one step may take"),
    });
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::OptimizerRegistry, "optimizer", "adam", ppsynth::AdamOptions::params(),
                        "Adam, fresh state per stage; lr per sigma (published: 0.005, 0.002, 0.002, 0.002)",
                        [](const ppsynth::AdamOptions& o, const std::string& key, torch::Tensor params,
                           int s) -> std::unique_ptr<ppsynth::PositionOptimizer> {
                          return std::make_unique<ppsynth::AdamPositions>(params, ppsynth::learning_rate_for(o.lr, s, key));
                        })
PPSYNTH_REGISTER_PARAMS(ppsynth::OptimizerRegistry, "optimizer", "lbfgs", ppsynth::LbfgsOptions::params(),
                        "L-BFGS (published: lr 100x Adam's); one step = up to max_iter evaluations",
                        [](const ppsynth::LbfgsOptions& o, const std::string& key, torch::Tensor params,
                           int s) -> std::unique_ptr<ppsynth::PositionOptimizer> {
                          return std::make_unique<ppsynth::LbfgsPositions>(params, ppsynth::learning_rate_for(o.lr, s, key),
                                                                          o.max_iter);
                        })
PPSYNTH_DEFAULTS_KIND("optimizer", ppsynth::OptimizerRegistry)
