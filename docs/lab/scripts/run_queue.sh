#!/usr/bin/env bash
# Runs the given configs one after another (each into runs/<config stem>), logging to
# runs/<stem>.log; extra ppsynth arguments after "--" apply to every run.
# PPSYNTH_BIN overrides the binary (e.g. a copy, so a rebuild does not disturb a long queue).
# Example: docs/lab/scripts/run_queue.sh configs/runs/ps_Tree1.json configs/runs/ps_Cattles.json -- --set method.max_iterations=200
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
configs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do configs+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
mkdir -p "$here/runs"
for c in "${configs[@]}"; do
  stem="$(basename "$c" .json)"
  start=$(date +%s)
  "${PPSYNTH_BIN:-$here/build/ppsynth}" synthesize "$c" -o "$here/runs/$stem" "$@" > "$here/runs/$stem.log" 2>&1
  echo "$stem exit $? in $(( $(date +%s) - start )) s" | tee -a "$here/runs/queue.log"
done
