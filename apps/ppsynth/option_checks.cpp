#include "apps/ppsynth/option_checks.hpp"

#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "core/run_json.hpp"

namespace ppsynth::app {

CLI::Validator whole_number(unsigned long long lo, unsigned long long hi) {
  const std::string range = "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return "'" + text + "': " + range;
        unsigned long long v = 0;
        for (char c : text) {
          const unsigned d = static_cast<unsigned>(c - '0');
          if (v > (hi - d) / 10 || d > hi) return text + ": " + range;
          v = v * 10 + d;
        }
        return v < lo ? text + ": " + range : std::string();
      },
      "INT " + std::to_string(lo) + ".." + std::to_string(hi));
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(v) || !(v > 0)) return "'" + text + "': expected a number > 0";
        return "";
      },
      "NUMBER > 0");
}

CLI::Validator seed_number() { return whole_number(0, kMaxSeed); }

CLI::Validator path_text() {
  // No description: the help's type column stays "TEXT".
  return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "expected a path, got ''" : ""; },
                        "");
}

namespace {

// `a` is `b` or a key path above or below it ("output" and "output.size").
bool overlaps(const std::string& a, const std::string& b) {
  const std::string& shorter = a.size() <= b.size() ? a : b;
  const std::string& longer = a.size() <= b.size() ? b : a;
  return longer.compare(0, shorter.size(), shorter) == 0 && (longer.size() == shorter.size() || longer[shorter.size()] == '.');
}

}  // namespace

void refuse_set_conflicts(const std::vector<std::string>& sets,
                          const std::vector<std::pair<std::string, std::string>>& flags) {
  for (const std::string& set : sets) {
    const std::string key = set.substr(0, set.find('='));
    for (const auto& [flag, flag_key] : flags)
      if (overlaps(key, flag_key))
        throw InputError(flag + " and --set " + set + " both set the config key '" + flag_key +
                         "'; give one of them");
  }
}

}  // namespace ppsynth::app
