#!/usr/bin/env bash
# Kills a real synthesis with SIGKILL at random times, resumes it each time, and compares the
# result with the same run made without interruption: every output file (run.json and
# loss.csv's seconds column aside) must be byte-identical. Prints the kill times and the
# SHA-256 of both runs' files.
#
# Usage: scripts/kill_resume_check.sh CONFIG OUT_DIR --within SECONDS [--kills N] [--seed S]
#          [-- SYNTHESIZE_ARGS...]
#   e.g. scripts/kill_resume_check.sh configs/runs/poisson_n64c2_disk.json /tmp/kr \
#          --within 1100 --kills 2 -- --set method.max_iterations=100
# Both runs go at once, one thread each (PPSYNTH_THREADS=1: results depend on the thread
# count in the last bits). The N kill times are drawn uniformly from (0, SECONDS) of the
# interrupted run's own running time (the segments added up; give about the run's length, as
# the progress line's ETA says), so a kill can fall anywhere: mid-stage, at a boundary,
# before the first checkpoint (then the run starts over).
# OUT_DIR must not exist; it gets reference/, interrupted/ and kills.txt.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${PPSYNTH_BIN:-$here/build/ppsynth}"

[ $# -ge 2 ] || { sed -n 2,17p "$0"; exit 2; }
config="$1"; out="$2"; shift 2
kills=2; seed=""; within=""
while [ $# -gt 0 ]; do
  case "$1" in
    --kills) kills="$2"; shift 2 ;;
    --seed) seed="--seed $2"; shift 2 ;;
    --within) within="$2"; shift 2 ;;
    --) shift; break ;;
    *) echo "kill_resume_check: unknown option $1" >&2; exit 2 ;;
  esac
done
extra=("$@")
[ -n "$within" ] || { echo "kill_resume_check: give --within SECONDS (about the run's length)" >&2; exit 2; }
[ ! -e "$out" ] || { echo "kill_resume_check: $out exists; name a new directory" >&2; exit 2; }
mkdir -p "$out"
export PPSYNTH_THREADS=1

start=$(date +%s.%N)
"$bin" synthesize "$config" $seed "${extra[@]}" -o "$out/reference" > "$out/reference.log" 2>&1 &
ref_pid=$!

elapsed() { awk -v s="$1" -v n="$(date +%s.%N)" 'BEGIN { printf "%.3f", n - s }'; }
less_than() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }
: > "$out/kills.txt"
seg=0
"$bin" synthesize "$config" $seed "${extra[@]}" -o "$out/interrupted" > "$out/interrupted.$seg.log" 2>&1 &
pid=$!
seg_start=$(date +%s.%N)
ran=0  # the interrupted run's running time before this segment
times=$(awk -v n="$kills" -v w="$within" -v seed="$RANDOM" 'BEGIN { srand(seed); for (i = 0; i < n; i++) print w * rand() }' | sort -g)
k=0
for at in $times; do
  k=$((k + 1))
  while less_than "$(awk -v r="$ran" -v e="$(elapsed "$seg_start")" 'BEGIN { print r + e }')" "$at" && kill -0 "$pid" 2>/dev/null; do
    sleep 0.2
  done
  if ! kill -0 "$pid" 2>/dev/null; then echo "run finished before kill $k" | tee -a "$out/kills.txt"; break; fi
  kill -9 "$pid"; wait "$pid" || true
  last=$(grep -aoE 'it +[0-9]+/[0-9]+' "$out/interrupted.$seg.log" | tail -1 || true)
  seg_s=$(elapsed "$seg_start"); ran=$(awk -v r="$ran" -v e="$seg_s" 'BEGIN { print r + e }')
  line="kill $k: SIGKILL at $(printf %.1f "$ran") s of running time ($(printf %.1f "$seg_s") s into segment $seg; last progress: ${last:-none})"
  echo "$line" | tee -a "$out/kills.txt"
  seg=$((seg + 1))
  if [ -f "$out/interrupted/checkpoint.bin" ]; then
    "$bin" synthesize --resume "$out/interrupted" > "$out/interrupted.$seg.log" 2>&1 &
  else  # killed before its first checkpoint: nothing to resume, the run starts over
    echo "  (no checkpoint yet: started again with --force)" | tee -a "$out/kills.txt"
    "$bin" synthesize "$config" $seed "${extra[@]}" -o "$out/interrupted" --force > "$out/interrupted.$seg.log" 2>&1 &
  fi
  pid=$!
  seg_start=$(date +%s.%N)
done
wait "$pid"
wait "$ref_pid"
echo "both runs finished after $(printf %.0f "$(elapsed "$start")") s" | tee -a "$out/kills.txt"

status=0
cd "$out"
for f in $(cd reference && find . -type f ! -name run.json ! -name .ppsynth-run | sort); do
  if [ "$(basename "$f")" = loss.csv ]; then
    a=$(sed 's/,[^,]*$//' "reference/$f" | sha256sum | cut -c1-16); b=$(sed 's/,[^,]*$//' "interrupted/$f" | sha256sum | cut -c1-16)
  else
    a=$(sha256sum < "reference/$f" | cut -c1-16); b=$( [ -f "interrupted/$f" ] && sha256sum < "interrupted/$f" | cut -c1-16 || echo missing)
  fi
  mark=same; [ "$a" = "$b" ] || { mark=DIFFERENT; status=1; }
  printf '%-40s %s %s %s\n' "$f" "$a" "$b" "$mark"
done | tee hashes.txt
grep -q DIFFERENT hashes.txt && status=1
[ $status -eq 0 ] && echo "kill_resume_check: every file equal" || echo "kill_resume_check: files differ"
exit $status
