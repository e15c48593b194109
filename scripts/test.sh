#!/usr/bin/env bash
# The test command (README, .ci/run): installs what is missing, builds, runs the one Catch2
# binary under CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
cd "$here"
ctest --test-dir build --output-on-failure
