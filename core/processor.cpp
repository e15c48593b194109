#include "core/processor.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace ppsynth {

namespace {

// oneDNN's ISA names, narrowest first (its ONEDNN_MAX_CPU_ISA values), and the /proc/cpuinfo
// flag that reaches each level of ours. A level is the index in this list.
const std::vector<std::string> k_onednn_isas = {"SSE41", "AVX", "AVX2", "AVX2_VNNI", "AVX512_CORE", "AVX512_CORE_VNNI",
                                                "AVX512_CORE_BF16", "AVX512_CORE_FP16", "AVX512_CORE_AMX", "ALL"};
struct FlagLevel {
  const char* flag;
  const char* onednn;
};
// Widest first: the first flag the CPU lists names its class.
const FlagLevel k_flag_levels[] = {
    {"amx_bf16", "AVX512_CORE_AMX"}, {"avx512_bf16", "AVX512_CORE_BF16"}, {"avx512f", "AVX512_CORE"}, {"avx2", "AVX2"}};

int onednn_level(const std::string& name) {
  auto it = std::find(k_onednn_isas.begin(), k_onednn_isas.end(), name);
  return it == k_onednn_isas.end() ? -1 : static_cast<int>(it - k_onednn_isas.begin());
}

// Our class name ("avx2", ...) for a oneDNN level: the widest class at or below it.
std::string class_at(int level) {
  for (const auto& f : k_flag_levels)
    if (onednn_level(f.onednn) <= level) return f.flag;
  return "baseline";
}

int class_level(const std::string& cls) {
  for (const auto& f : k_flag_levels)
    if (cls == f.flag) return onednn_level(f.onednn);
  return 0;
}

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

CpuIsa cpu_isa_from(const std::string& cpuinfo, const std::function<std::string(const char*)>& getenv) {
  CpuIsa isa;
  std::string flags;
  bool any = false;
  std::istringstream in(cpuinfo);
  for (std::string line; std::getline(in, line) && (isa.model.empty() || flags.empty());) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string key = line.substr(0, colon);
    key.erase(key.find_last_not_of(" \t") + 1);
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    if (key == "model name" && isa.model.empty()) isa.model = value, any = true;
    if ((key == "flags" || key == "Features") && flags.empty()) flags = value, any = true;  // x86-64; arm64
  }
  if (any) {
    std::set<std::string> have;
    std::istringstream words(flags);
    for (std::string w; words >> w;) have.insert(w);
    isa.widest = "baseline";
    for (const auto& f : k_flag_levels)
      if (have.count(f.flag)) {
        isa.widest = f.flag;
        break;
      }
  }
  isa.onednn_cap = upper(getenv("ONEDNN_MAX_CPU_ISA"));
  if (isa.onednn_cap.empty()) isa.onednn_cap = upper(getenv("DNNL_MAX_CPU_ISA"));
  isa.aten_cap = lower(getenv("ATEN_CPU_CAPABILITY"));
  isa.effective = isa.widest;
  const int cap = onednn_level(isa.onednn_cap);  // oneDNN ignores a name it does not know: so do we
  if (!isa.widest.empty() && cap >= 0 && cap < class_level(isa.widest)) isa.effective = class_at(cap);
  isa.native_bf16 = !isa.effective.empty() && class_level(isa.effective) >= onednn_level("AVX512_CORE_BF16");
  isa.bf16_unavailable = !isa.widest.empty() && class_level(isa.widest) >= onednn_level("AVX512_CORE") &&
                         class_level(isa.effective) < onednn_level("AVX512_CORE");
  return isa;
}

std::string CpuIsa::kind() const {
  if (widest.empty()) return "unknown";
  std::string k = (model.empty() ? std::string("unknown model") : model) + " (" + widest;
  std::vector<std::string> caps;
  if (effective != widest) caps.push_back("oneDNN to " + effective + " by ONEDNN_MAX_CPU_ISA=" + onednn_cap);
  // ATen's own vectorized kernels: avx512 where the CPU has AVX-512, avx2 below it.
  const std::string aten_native = class_level(widest) >= onednn_level("AVX512_CORE") ? "avx512"
                                  : widest == "avx2"                                  ? "avx2"
                                                                                      : "default";
  const std::vector<std::string> aten_levels = {"default", "avx2", "avx512"};
  auto aten_rank = [&](const std::string& s) {
    auto it = std::find(aten_levels.begin(), aten_levels.end(), s);
    return it == aten_levels.end() ? -1 : static_cast<int>(it - aten_levels.begin());
  };
  if (aten_rank(aten_cap) >= 0 && aten_rank(aten_cap) < aten_rank(aten_native))
    caps.push_back("ATen to " + aten_cap + " by ATEN_CPU_CAPABILITY");
  for (size_t i = 0; i < caps.size(); ++i) k += (i == 0 ? ", capped: " : "; ") + caps[i];
  return k + ")";
}

const CpuIsa& cpu_isa() {
  static const CpuIsa isa = [] {  // read once: a process does not change its processor, and the libraries read the caps once
    std::ifstream in("/proc/cpuinfo");
    std::stringstream text;
    if (in) text << in.rdbuf();
    return cpu_isa_from(text.str(), [](const char* name) {
      const char* v = std::getenv(name);
      return std::string(v ? v : "");
    });
  }();
  return isa;
}

std::string processor_kind() { return cpu_isa().kind(); }

}  // namespace ppsynth
