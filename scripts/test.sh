#!/usr/bin/env bash
# The test command (README, .ci/run): installs what is missing, builds every target the
# first command left out (the test binary, the library example, the Python module; an
# up-to-date target is not rebuilt), runs the one Catch2 binary and the Python tests under
# CTest, then replays and briefly runs the fuzz targets (scripts/fuzz.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" --all
cd "$here"
ctest --test-dir build --output-on-failure --parallel 2
# The point-file readers and the config loader under libFuzzer (clang, ASan + UBSan, its own
# build dir build-fuzz): the seed corpus replayed, then each target fuzzed briefly
# (PPSYNTH_FUZZ_SECONDS per target, default 15; 0 = replay only). A fixed libFuzzer seed
# (PPSYNTH_FUZZ_SEED, default 1) makes a failing test run repeatable; exploring with fresh
# seeds is scripts/fuzz.sh's own default.
"$here/scripts/fuzz.sh" --seconds "${PPSYNTH_FUZZ_SECONDS:-15}" -- -seed="${PPSYNTH_FUZZ_SEED:-1}"
