#include "apps/ppsynth/option_checks.hpp"

#include <cmath>
#include <cstdlib>

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

}  // namespace ppsynth::app
