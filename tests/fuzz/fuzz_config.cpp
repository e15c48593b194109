// libFuzzer target: the config loader (core/config/config.hpp).
// Input: a config text, then optionally '\0'-separated "--set" assignments, e.g.
//   {"method": {"type": "pcf2017"}}\0method.iterations=3\0seed=7
// The text is loaded with load_config from a scratch folder that also holds base.json, so
// a "parent" chain can resolve; the loaded config goes through apply_defaults against every
// registered torch-free part's defaults (and each top-level member naming a registered
// "type" against that part's), then the assignments through set_override, then dump() as
// a run directory's config.json would. Contract: fuzz_common.hpp.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/config/config.hpp"
#include "core/config/defaults_catalog.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

namespace {

fs::path g_dir;
std::string g_config;
json g_catalog;

void remove_dir() {
  std::error_code ec;
  fs::remove_all(g_dir, ec);
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
}

// Every registered part's defaults: (key path, defaults).
std::vector<std::pair<std::string, const json*>> parts() {
  std::vector<std::pair<std::string, const json*>> v;
  for (auto k = g_catalog.begin(); k != g_catalog.end(); ++k)
    for (auto p = k->begin(); p != k->end(); ++p) v.emplace_back(k.key() + "." + p.key(), &(*p)["defaults"]);
  return v;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::quiet_logging();
  g_catalog = defaults_catalog();
  char tmpl[] = "/tmp/ppsynth_fuzz_config_XXXXXX";
  if (!::mkdtemp(tmpl)) std::abort();
  g_dir = tmpl;
  std::atexit(remove_dir);
  g_config = (g_dir / "fuzz.json").string();
  write(g_dir / "base.json", R"({"seed": 1, "method": {"type": "pcf2017"}, "output": {"points": 64}})");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t nul = input.find('\0');
  write(g_config, input.substr(0, nul));

  json config = json::object();
  if (fuzz::accepts([&] { config = load_config(g_config); })) {
    static const auto all = parts();
    for (const auto& part : all) {  // (no structured bindings: clang 14 cannot capture them)
      json resolved;
      if (fuzz::accepts([&] { resolved = apply_defaults(*part.second, config, part.first); })) (void)resolved.dump();
    }
    for (auto it = config.begin(); it != config.end(); ++it) {
      if (!it->is_object() || !it->contains("type") || !(*it)["type"].is_string()) continue;
      const std::string type = (*it)["type"];
      for (const auto& part : all) {
        if (part.first.substr(part.first.find('.') + 1) != type) continue;
        json params = *it;
        params.erase("type");
        json resolved;
        if (fuzz::accepts([&] { resolved = apply_defaults(*part.second, params, it.key()); })) (void)resolved.dump();
      }
    }
  }
  if (nul != std::string::npos) {
    size_t start = nul + 1;
    while (start <= input.size()) {
      size_t end = input.find('\0', start);
      if (end == std::string::npos) end = input.size();
      const std::string assignment = input.substr(start, end - start);
      fuzz::accepts([&] { set_override(config, assignment); });
      start = end + 1;
    }
  }
  (void)config.dump(2);  // the resolved config a run directory writes
  return 0;
}
