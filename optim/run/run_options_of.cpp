#include "optim/run/run_options_of.hpp"

#include "core/config/config.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"
#include "core/run_json.hpp"
#include "optim/run/runtime.hpp"

namespace ppsynth {

TypedRunOptions run_options_of(const nlohmann::json& config, const std::string& source) {
  check_run_config(config, source);  // an object; seed in [0, 2^63); method an object with a string type
  TypedRunOptions t;
  try {
    // A run made before a key existed ("runtime", "output") ran with what is now its default;
    // a key since retired is not read (the reader's unread keys are not refused): a finished run
    // stays readable.
    const nlohmann::json merged = merge(run_defaults(), config);
    ParamReader r(merged, "");
    t.options = RunOptions::params().read(r);
    check_runtime(merged.at("runtime"));
  } catch (const InputError& e) {
    throw file_error(source, 0, e.what());
  }
  t.seed = t.options.seed.get<uint64_t>();
  t.method_type = t.options.method["type"].get<std::string>();
  return t;
}

}  // namespace ppsynth
