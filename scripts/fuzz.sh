#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/fuzz_<target>.cpp; clang-14, ASan + UBSan, torch
# off) into build-fuzz, replays the seed corpus (tests/fuzz/corpus/<target>/) and fuzzes each
# target for a bounded time. New corpus entries go to a scratch folder, not the repo, unless
# --merge is given (then only inputs that add coverage are merged into the repo corpus).
# A crash, leak, UB, timeout or any exception other than ppsynth::InputError is a finding:
# its input is saved under the artifacts folder and the script exits non-zero.
#
# Usage: scripts/fuzz.sh [--seconds N] [--targets "gabor_int config ..."] [--scratch DIR]
#                        [--replay-only] [--merge] [--no-build] [-- libFuzzer flags...]
#   --seconds N    fuzzing time per target (default 30; 0 = replay only)
#   --scratch DIR  where new corpus entries and crash artifacts go (default: a temp folder,
#                  kept and printed when there are findings)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

seconds=30 targets="" scratch="" merge=0 build=1 extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --targets) targets="$2"; shift 2 ;;
    --scratch) scratch="$2"; shift 2 ;;
    --replay-only) seconds=0; shift ;;
    --merge) merge=1; shift ;;
    --no-build) build=0; shift ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
  esac
done

if [ "$build" = 1 ]; then
  export CCACHE_BASEDIR="$here"
  export CCACHE_SLOPPINESS="pch_defines,time_macros,include_file_mtime,include_file_ctime"
  export CCACHE_NOHASHDIR=1
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
        -DPPSYNTH_FUZZ=ON > /dev/null
  cmake --build build-fuzz -j"$(nproc)"
fi
if [ -z "$targets" ]; then
  targets=$(ls tests/fuzz/corpus)
fi
own_scratch=0
if [ -z "$scratch" ]; then scratch=$(mktemp -d /tmp/ppsynth_fuzz.XXXXXX); own_scratch=1; fi
mkdir -p "$scratch"

# Leaks are findings (LeakSanitizer runs at the end of each input); UB aborts (built with
# -fno-sanitize-recover=undefined).
export ASAN_OPTIONS="detect_leaks=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [ -x /usr/lib/llvm-14/bin/llvm-symbolizer ]; then
  export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
fi
# -timeout: one input taking longer than this is a finding (a hang); -rss_limit_mb likewise.
common=(-timeout=25 -rss_limit_mb=2048 -print_final_stats=1)

failed=()
summary=()
for t in $targets; do
  bin="build-fuzz/fuzz_$t"
  seeds="tests/fuzz/corpus/$t"
  [ -x "$bin" ] || { echo "fuzz.sh: no target $bin" >&2; exit 2; }
  art="$scratch/artifacts/$t/"
  mkdir -p "$art" "$scratch/corpus/$t"
  echo "[fuzz] $t: replaying $(ls "$seeds" | wc -l) seed(s)"
  if ! "$bin" "${common[@]}" -artifact_prefix="$art" -runs=0 "$seeds" > "$scratch/$t.replay.log" 2>&1; then
    tail -40 "$scratch/$t.replay.log"
    failed+=("$t (replay)")
    continue
  fi
  [ "$seconds" -gt 0 ] || { summary+=("$t: replay ok"); continue; }
  echo "[fuzz] $t: fuzzing ${seconds} s"
  if ! "$bin" "${common[@]}" -artifact_prefix="$art" -max_total_time="$seconds" "${extra[@]}" \
       "$scratch/corpus/$t" "$seeds" > "$scratch/$t.log" 2>&1; then
    tail -60 "$scratch/$t.log"
    failed+=("$t")
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$scratch/$t.log" | grep -o '[0-9]*$' || true)
  summary+=("$t: ${execs:-?} executions, $(ls "$scratch/corpus/$t" | wc -l) new corpus entries")
  if [ "$merge" = 1 ]; then
    "$bin" -merge=1 "$seeds" "$scratch/corpus/$t" > "$scratch/$t.merge.log" 2>&1
  fi
done

printf '[fuzz] %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "[fuzz] FINDINGS in: ${failed[*]}; inputs and logs under $scratch" >&2
  find "$scratch/artifacts" -type f >&2
  exit 1
fi
echo "[fuzz] no findings"
if [ "$own_scratch" = 1 ]; then rm -rf "$scratch"; fi
