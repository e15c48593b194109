#pragma once
// Checks of command-line values with messages a user can act on ("--seed -5: expected a
// whole number from 0 to 9223372036854775807"), where CLI11's own print the limits of a
// double. Each is a CLI11 validator: its failure is a usage error (exit 2, main.cpp). Digits
// are checked on the text, before any conversion, so a value past the type's range is refused,
// never saturated.
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace ppsynth::app {

// A whole number from lo to hi (lo >= 0): digits only, no sign, exponent or fraction.
CLI::Validator whole_number(unsigned long long lo, unsigned long long hi);
// A finite number > 0.
CLI::Validator positive_number();
// A seed: a whole number in [0, 2^63) (core/run_json.hpp's kMaxSeed).
CLI::Validator seed_number();
// A path: not empty ("-o ''" is a mistake, never "no -o").
CLI::Validator path_text();

// A flag that sets a config key (--seed: "seed") and a --set of that key, or of a key above or
// below it, on one line: which should win is not for ppsynth to guess, so it is a usage error
// (InputError naming both). `flags`: {"--seed 7", "seed"} for each such flag given.
void refuse_set_conflicts(const std::vector<std::string>& sets,
                          const std::vector<std::pair<std::string, std::string>>& flags);

}  // namespace ppsynth::app
