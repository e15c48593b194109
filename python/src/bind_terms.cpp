// Loss terms written in Python, registered under a name like any compiled part:
//   a feature loss  (LossRegistry, losses/loss.hpp): method.losses [{"type": NAME, ...}]
//   a point term    (PointTermRegistry, optim/terms/point_term.hpp): method.terms {NAME: {...}}
//
// Tensors cross without copies through DLPack: Debian's python3-torch is the same LibTorch
// build as libtorch-dev, so a capsule of a C++ tensor is a torch.Tensor on the same memory.
// The Python side (ppsynth/terms.py) computes the term's value and, with torch.autograd, its
// gradient with respect to the inputs; GivenGradient hands both to the C++ graph, so the
// gradient flows into the optimizer with the rest of the loss. No libtorch_python is linked:
// the package imports and works without torch, and only a Python term needs it.
//
// The callables live in a registry of this module that is never destroyed (a Python object
// must not be released after the interpreter has gone); every term instance takes the GIL to
// call Python and to let go of what it holds.
#include <ATen/DLConvertor.h>
#include <pybind11/stl.h>
#include <torch/torch.h>

#include <map>
#include <set>

#include "bindings.hpp"
#include "json_python.hpp"
#include "core/error.hpp"
#include "losses/loss.hpp"
#include "optim/terms/point_term.hpp"

namespace ppsynth::python {

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

// A scalar computed outside autograd whose gradient with respect to each input was computed
// with it: forward returns the value, backward scales the given gradients.
class GivenGradient : public torch::autograd::Function<GivenGradient> {
 public:
  static torch::Tensor forward(AutogradContext* ctx, at::TensorList inputs, double value,
                               std::vector<torch::Tensor> grads) {
    ctx->saved_data["grads"] = c10::List<torch::Tensor>(grads);
    return torch::scalar_tensor(value, inputs[0].options().requires_grad(false));
  }
  static variable_list backward(AutogradContext* ctx, variable_list grad_out) {
    const auto grads = ctx->saved_data["grads"].toTensorList();
    variable_list out;
    for (size_t i = 0; i < grads.size(); ++i) out.push_back(grads.get(i) * grad_out[0]);
    out.emplace_back();  // value
    out.emplace_back();  // grads
    return out;
  }
};

// Where the Python callables are: name -> the package's glue for it. Leaked on purpose.
std::map<std::string, py::object>& python_parts() {
  static auto* parts = new std::map<std::string, py::object>();
  return *parts;
}
// Names this module registered, per registry (only these may be redefined).
std::set<std::string>& own_names(const std::string& registry) {
  static auto* names = new std::map<std::string, std::set<std::string>>();
  return (*names)[registry];
}

// DLPack carries strides: channels-last features cross as they lie, without a copy.
py::capsule to_capsule(const torch::Tensor& t) {
  DLManagedTensor* m = at::toDLPack(t.detach());
  return py::capsule(m, "dltensor", [](PyObject* o) {
    // A capsule never consumed still owns its tensor (a consumed one is renamed).
    if (PyCapsule_IsValid(o, "dltensor"))
      static_cast<DLManagedTensor*>(PyCapsule_GetPointer(o, "dltensor"))->deleter(
          static_cast<DLManagedTensor*>(PyCapsule_GetPointer(o, "dltensor")));
  });
}

torch::Tensor from_capsule(const py::handle& h, const std::string& what) {
  PyObject* o = h.ptr();
  if (!PyCapsule_IsValid(o, "dltensor")) throw InputError(what + ": expected a DLPack capsule");
  auto* m = static_cast<DLManagedTensor*>(PyCapsule_GetPointer(o, "dltensor"));
  PyCapsule_SetName(o, "used_dltensor");
  return at::fromDLPack(m);  // owns m now
}

// Calls the glue of part `name`: glue(params, [input capsules], *extra()) -> (value,
// [gradient capsules]) with one gradient per input. The GIL is taken here, for all of it
// (`extra` builds its Python arguments under it).
template <class Extra>
std::pair<double, std::vector<torch::Tensor>> call_python(const std::string& kind, const std::string& name,
                                                          const py::object& glue, const py::object& params,
                                                          const std::vector<torch::Tensor>& inputs, Extra extra) {
  py::gil_scoped_acquire gil;
  py::list caps;
  for (const auto& t : inputs) caps.append(to_capsule(t));
  py::tuple r = glue(params, caps, *extra());
  const double value = r[0].cast<double>();
  const py::list grads = r[1];
  const std::string what = kind + " '" + name + "'";
  if (!std::isfinite(value)) throw InputError(what + ": the value is not finite (" + std::to_string(value) + ")");
  if (grads.size() != inputs.size()) throw InputError(what + ": one gradient per input expected");
  std::vector<torch::Tensor> g;
  for (size_t i = 0; i < inputs.size(); ++i) {
    torch::Tensor t = from_capsule(grads[i], what + " gradient " + std::to_string(i));
    if (t.sizes() != inputs[i].sizes())
      throw InputError(what + ": gradient " + std::to_string(i) + " has another shape than its input");
    if (!torch::isfinite(t).all().item<bool>())
      throw InputError(what + ": gradient " + std::to_string(i) + " holds a value that is not finite (NaN or infinite)");
    g.push_back(t.to(inputs[i].scalar_type()));
  }
  return {value, g};
}

py::object glue_of(const std::string& name) {
  py::gil_scoped_acquire gil;
  return python_parts().at(name);
}

// A part's parameters as the dict its Python function receives, made once per part.
py::object params_of(const json& params) {
  py::gil_scoped_acquire gil;
  return pyjson::from_json(params);
}

class PythonFeatureLoss : public FeatureLoss {
 public:
  PythonFeatureLoss(std::string name, const json& params)
      : name_(std::move(name)),
        layers_(loss_layers(params, name_)),
        params_(params_of(params)),
        glue_(glue_of("loss:" + name_)) {}
  ~PythonFeatureLoss() override {
    py::gil_scoped_acquire gil;
    params_ = py::object();
    glue_ = py::object();
  }
  void set_target(const Features& exemplar, const LossContext&) override {
    targets_.clear();
    for (int l : layers_) targets_.push_back(layer_of(exemplar, l, name_).detach());
  }
  torch::Tensor forward(const Features& output) override {
    std::vector<torch::Tensor> xs;
    for (int l : layers_) xs.push_back(layer_of(output, l, name_));
    auto [value, grads] = call_python("loss", name_, glue_, params_, xs, [&] {
      py::list target_caps;
      for (const auto& t : targets_) target_caps.append(to_capsule(t));
      return py::make_tuple(target_caps);
    });
    return GivenGradient::apply(at::TensorList(xs), value, grads);
  }

 private:
  std::string name_;
  std::vector<int> layers_;
  py::object params_, glue_;
  std::vector<torch::Tensor> targets_;
};

class PythonPointTerm : public PointTerm {
 public:
  PythonPointTerm(std::string name, const json& params)
      : name_(std::move(name)), params_(params_of(params)), glue_(glue_of("point_term:" + name_)) {}
  ~PythonPointTerm() override {
    py::gil_scoped_acquire gil;
    params_ = py::object();
    glue_ = py::object();
    stage_ = py::object();
  }
  void begin_class(const ClassStage& s) override {
    py::gil_scoped_acquire gil;
    py::dict d;
    d["exemplar"] = to_python(s.exemplar);
    d["output"] = to_python(s.output);
    d["moving"] = s.moving;
    d["frozen"] = s.frozen;
    d["upscale"] = s.upscale;
    stage_ = d;
  }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& frozen) override {
    auto [value, grads] = call_python("point term", name_, glue_, params_, {moving},
                                      [&] { return py::make_tuple(to_capsule(frozen), stage_); });
    return GivenGradient::apply(at::TensorList(moving), value, grads);
  }

 private:
  std::string name_;
  py::object params_, glue_, stage_;
};

// Registers (or redefines) a Python part in `Reg`: `defaults` are merged over `base` (the
// parameters every part of the kind takes), `bounds` likewise.
template <class Reg, class Make>
void register_part(const std::string& kind, const std::string& name, const py::object& glue, json base,
                   json base_bounds, const py::object& defaults, const std::string& description, Make make) {
  if (name.empty() || name.find_first_of(" .=\"'") != std::string::npos)
    throw InputError(kind + " name '" + name + "': letters, digits, '_' or '-' only (it is a config key)");
  const json extra = from_python_json(defaults, kind + " '" + name + "' defaults");
  if (!extra.is_object()) throw InputError(kind + " '" + name + "': defaults must be a dict");
  for (auto it = extra.begin(); it != extra.end(); ++it) {
    if (it.key() == "type") throw InputError(kind + " '" + name + "': 'type' is not a parameter");
    base[it.key()] = it.value();
  }
  python_parts()[kind + ":" + name] = glue;
  typename Reg::Entry e{[name, make](const json& p, const std::string&) { return make(name, p); }, base, base_bounds,
                        description.empty() ? kind + " written in Python" : description};
  auto& reg = Reg::instance();
  auto& mine = own_names(kind);
  if (reg.contains(name)) {
    if (!mine.count(name)) throw InputError(kind + " '" + name + "' is a compiled-in part of ppsynth; choose another name");
    reg.replace(name, std::move(e));
  } else {
    reg.add(name, std::move(e));
    mine.insert(name);
  }
}

}  // namespace

void bind_terms(py::module_& m) {
  m.def(
      "register_loss",
      [](const std::string& name, const py::object& glue, const py::object& defaults, const std::string& description) {
        register_part<LossRegistry>(
            "loss", name, glue, json{{"weight", 1.0}, {"layers", {0, 1, 2}}},
            json{{"weight", "[0, inf)"}, {"layers", "int [0, 15]"}}, defaults, description,
            [](const std::string& n, const json& p) -> std::unique_ptr<FeatureLoss> {
              return std::make_unique<PythonFeatureLoss>(n, p);
            });
      },
      py::arg("name"), py::arg("glue"), py::arg("defaults"), py::arg("description"));
  m.def(
      "register_point_term",
      [](const std::string& name, const py::object& glue, const py::object& defaults, const std::string& description) {
        register_part<PointTermRegistry>(
            "point_term", name, glue, json{{"weight", 0.0}}, json{{"weight", "[0, inf)"}}, defaults, description,
            [](const std::string& n, const json& p) -> std::unique_ptr<PointTerm> {
              return std::make_unique<PythonPointTerm>(n, p);
            });
      },
      py::arg("name"), py::arg("glue"), py::arg("defaults"), py::arg("description"));

  // Checking a term, compiled or Python, outside a synthesis: its value and gradient through
  // the same C++ path a synthesis takes (inputs and gradients as DLPack capsules).
  m.def(
      "point_term_value_and_grad",
      [](const py::object& term_spec, const py::dict& exemplar, const py::dict& output, const std::vector<size_t>& moving,
         const std::vector<size_t>& frozen, int upscale, const py::capsule& moving_xy, const py::capsule& frozen_xy) {
        const json spec = from_python_json(term_spec, "term");
        auto term = PointTermRegistry::instance().create(spec, "terms");
        const PointSet ex = from_python(exemplar, "exemplar"), out = from_python(output, "output");
        torch::Tensor x = from_capsule(moving_xy, "moving").clone().requires_grad_(true);
        torch::Tensor f = from_capsule(frozen_xy, "frozen").clone();
        torch::Tensor value;
        {
          py::gil_scoped_release unlocked;
          term->begin_class(ClassStage{ex, out, moving, frozen, upscale});
          value = term->evaluate(x, f);
          value.backward();
        }
        return py::make_tuple(value.item<double>(), to_capsule(x.grad()));
      });
  m.def(
      "loss_value_and_grad",
      [](const py::object& loss_spec, const py::list& output_caps, const py::list& target_caps) {
        const json spec = from_python_json(loss_spec, "loss");
        auto loss = LossRegistry::instance().create(spec, "losses");
        Features out, tgt;
        for (auto c : output_caps) out.push_back(from_capsule(c, "output").clone().requires_grad_(true));
        for (auto c : target_caps) tgt.push_back(from_capsule(c, "target").clone());
        torch::Tensor value;
        {
          py::gil_scoped_release unlocked;
          loss->set_target(tgt, LossContext{});
          value = loss->forward(out);
          value.backward();
        }
        py::list grads;
        for (const auto& t : out) grads.append(t.grad().defined() ? py::object(to_capsule(t.grad())) : py::none());
        return py::make_tuple(value.item<double>(), grads);
      });
}

}  // namespace ppsynth::python
