#include "core/processor.hpp"

#include <fstream>
#include <set>
#include <sstream>

namespace ppsynth {

std::string processor_kind_from_cpuinfo(const std::string& cpuinfo) {
  std::string model, flags;
  std::istringstream in(cpuinfo);
  for (std::string line; std::getline(in, line) && (model.empty() || flags.empty());) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string key = line.substr(0, colon);
    key.erase(key.find_last_not_of(" \t") + 1);
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    if (key == "model name" && model.empty()) model = value;
    if (key == "flags" && flags.empty()) flags = value;
  }
  if (model.empty() && flags.empty()) return "unknown";
  std::set<std::string> have;
  std::istringstream words(flags);
  for (std::string w; words >> w;) have.insert(w);
  std::string isa = "baseline";
  for (const char* f : {"amx_bf16", "avx512_bf16", "avx512f", "avx2"})
    if (have.count(f)) {
      isa = f;
      break;
    }
  return (model.empty() ? std::string("unknown model") : model) + " (" + isa + ")";
}

std::string processor_kind() {
  static const std::string kind = [] {  // read once: a process does not change its processor kind
    std::ifstream in("/proc/cpuinfo");
    if (!in) return std::string("unknown");
    std::stringstream text;
    text << in.rdbuf();
    return processor_kind_from_cpuinfo(text.str());
  }();
  return kind;
}

}  // namespace ppsynth
