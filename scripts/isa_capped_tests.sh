#!/usr/bin/env bash
# The ISA-sensitive test cases (tag [isa]: bf16 paths, statistical checks of trajectories,
# the per-processor presets) as a processor of the AVX2 class runs them, on any x86-64
# machine: oneDNN and ATen capped to AVX2 (core/processor.hpp). Where the caps change nothing,
# the processor is of that class already and the suite's own run covered them: skipped
# (exit 77, CTest's skip code here).
# Usage: scripts/isa_capped_tests.sh PPSYNTH_TESTS PPSYNTH
set -euo pipefail
tests="$1" ppsynth="$2"
caps=(ONEDNN_MAX_CPU_ISA=AVX2 ATEN_CPU_CAPABILITY=avx2)
kind() { env "$@" "$ppsynth" -q doctor --grid 0 | sed -n 's/^processor: *//p'; }
native=$(kind) capped=$(kind "${caps[@]}")
if [ "$native" = "$capped" ]; then
  echo "skipped: the AVX2 caps change nothing on this processor ($native); the suite ran its [isa] cases as they are"
  exit 77
fi
echo "[isa] cases on $capped"
exec env "${caps[@]}" "$tests" "[isa]"
