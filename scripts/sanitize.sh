#!/usr/bin/env bash
# Builds every ppsynth target with AddressSanitizer + UBSan (PPSYNTH_SANITIZE=ON: UB is fatal)
# into build-asan (torch on, the default compiler) and runs the whole test suite under it.
# Usage: scripts/sanitize.sh [--no-test] [ctest args...]
# Leak checking stays on; scripts/lsan.supp suppresses only leaks whose allocation stack lies
# entirely in third-party libraries (LibTorch's and its dependencies' process-lifetime
# caches), never one with a ppsynth frame (README "Fuzzing and sanitizers").
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
run_tests=1
if [ "${1:-}" = "--no-test" ]; then run_tests=0; shift; fi

export CCACHE_BASEDIR="$here"
export CCACHE_SLOPPINESS="pch_defines,time_macros,include_file_mtime,include_file_ctime"
export CCACHE_NOHASHDIR=1
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DPPSYNTH_SANITIZE=ON
cmake --build build-asan -j"$(nproc)"
[ "$run_tests" = 1 ] || exit 0

# Sanitizer reports go to stderr (kept by --output-on-failure) and fail the test run.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:strict_init_order=1:detect_stack_use_after_return=0:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
start=$(date +%s)
status=0
ctest --test-dir build-asan --output-on-failure "$@" || status=$?
echo "[sanitize] tests under ASan+UBSan: $(( $(date +%s) - start )) s, exit status $status"
exit $status
