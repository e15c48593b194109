#!/usr/bin/env bash
# Reproduces every figure, table and ablation of the paper (configs/paper/*.json), one report
# per config in OUT_DIR/NAME/index.html, then the page over all of them: OUT_DIR/index.html
# (and index.md): each paper claim beside our numbers, its verdict by the config's rule, and
# the pictures (`ppsynth reproduce --page`). Prints the wall time of each config and the total.
#
# Usage: scripts/reproduce_all.sh [OUT_DIR] [PPSYNTH_BINARY] [--quick] [--seeds 95-99] [-j N]
#                                 [--only "fig04 table1"] [--preset fast] [--set key=value ...]
#   --seeds S   every synthesized column over the seeds S, as one sweep per config in
#               OUT_DIR/sweeps/NAME; a run any earlier config's sweep holds already (the same
#               resolved config and seed: lines' default run feeds a dozen items) is copied,
#               not run again, and a rerun of this script resumes where it stopped.
#   -j N        runs at once per sweep (default 1)
#   --only L    only these configs (names, space-separated)
#   --preset P  ours' runs at a preset (fast: bf16 where the CPU has it, the stopping rule that
#               keeps a stage's best); the baselines run as their configs say
#   --keep-runs K  (with --seeds) a compact copy of every finished run of a sweep goes to
#               K/NAME/RUN within a minute of its end: its points, resolved config and numbers,
#               no pictures or curves; runs found in K are reused like the sweeps' own. A sweep
#               outlives the machine it ran on when K does (a folder you keep, or commit): a
#               later run of this script elsewhere picks up where the last one stopped. Nothing
#               in K is replaced; a run already kept under its name stays as it is, and a run
#               one item reused from another's is kept once. A run still going keeps its last
#               checkpoint in K/NAME/.inflight/RUN (refreshed each minute, dropped once the run is
#               kept finished), and a later run of the script resumes it from there: a machine
#               lost mid-run loses a minute and a checkpoint interval, not the run.
#   --kept-only (with --keep-runs) no new run: each item's sweep is planned, what K holds is
#               reused, and an item is reported only when every run of it is there; the others
#               are listed with the runs they lack (the page then says "not run"). The page over
#               what a kept sweep holds, in minutes, on any machine.
# Full settings take hours on a CPU; --quick is a smoke run. A config that fails is reported
# and the others still run; the page shows what exists; the exit status is 1 when any failed.
# A report already in OUT_DIR/NAME is replaced (--force): this script made it.

# One brace group, read whole before it runs: bash reads a script as it goes, so a `git pull`
# during an hours-long run would otherwise splice the new text into the running one.
{
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit 0
fi
# The two positional arguments come first: an option in their place (`--seeds 95-99` before
# OUT_DIR) would otherwise become a directory named after it and start the whole plan there.
for positional in "${1:-}" "${2:-}"; do
  if [[ "$positional" == -* ]]; then
    echo "reproduce_all: '$positional' where OUT_DIR and PPSYNTH_BINARY go; the options come after them (--help)" >&2
    exit 2
  fi
done
out="${1:-reports}"
bin="${2:-$root/build/ppsynth}"
shift $(( $# >= 2 ? 2 : $# ))
extra=()
seeds=""
only=""
keep=""
kept_only=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds="${2:?--seeds needs a value, e.g. 95-99}"; shift 2 ;;
    --only) only="${2:?--only needs config names}"; shift 2 ;;
    --keep-runs) keep="${2:?--keep-runs needs a directory}"; shift 2 ;;
    --kept-only) kept_only=1; shift ;;
    *) extra+=("$1"); shift ;;
  esac
done
if [[ ! -x "$bin" ]]; then
  echo "reproduce_all: no ppsynth binary at $bin (build it, or pass its path as the 2nd argument)" >&2
  exit 2
fi
if [[ -n "$kept_only" && -z "$keep" ]]; then
  echo "reproduce_all: --kept-only reports what --keep-runs K holds; give --keep-runs too" >&2
  exit 2
fi
if [[ -n "$keep" && -z "$seeds" ]]; then
  echo "reproduce_all: --keep-runs keeps the runs of sweeps over seeds; give --seeds too" >&2
  exit 2
fi
for name in $only; do
  if [[ ! -f "$root/configs/paper/$name.json" ]]; then
    echo "reproduce_all: --only names '$name', which is not a config in configs/paper" >&2
    exit 2
  fi
done
# keep_runs, restore_inflight: what --keep-runs keeps and gives back (scripts/lib/kept_runs.sh).
source "$root/scripts/lib/kept_runs.sh"
mkdir -p "$out"
[[ -n "$keep" ]] && mkdir -p "$keep"
start=$(date +%s)
summary=()
failed=()
for cfg in "$root"/configs/paper/*.json; do
  name="$(basename "$cfg" .json)"
  if [[ -n "$only" && " $only " != *" $name "* ]]; then continue; fi
  args=(reproduce "$cfg" -o "$out/$name" "${extra[@]}")
  [[ -f "$out/$name/report.json" ]] && args+=(--force)
  if [[ -n "$seeds" ]]; then
    args+=(--seeds "$seeds" --sweep "$out/sweeps/$name")
    for runs in "$out"/sweeps/*/runs; do
      [[ -d "$runs" && "$runs" != "$out/sweeps/$name/runs" ]] && args+=(--reuse "$runs")
    done
    if [[ -n "$keep" ]]; then
      for runs in "$keep"/*/; do
        [[ -d "$runs" ]] && args+=(--reuse "${runs%/}")
      done
    fi
  fi
  t0=$(date +%s)
  echo "=== $name"
  if [[ -n "$kept_only" ]]; then
    # Planned, with what K holds copied in. An item without runs (Fig. 3's maps) has no sweep:
    # planning it draws its report, and that is all it needs.
    if ! "$bin" "${args[@]}" --plan-only > /dev/null; then
      failed+=("$name"); summary+=("$(printf '%-26s %6s    %s' "$name" - "FAILED (its plan)")"); continue
    fi
    if [[ ! -f "$out/sweeps/$name/manifest.json" ]]; then
      summary+=("$(printf '%-26s %6d s  %s' "$name" $(($(date +%s) - t0)) "ok (nothing to run)")"); continue
    else
      # sed reads the whole listing: `head -1` would close the pipe on a long one (pipefail).
      counts="$("$bin" sweep status "$out/sweeps/$name" | sed -n -E '1s/.*: ([0-9]+) runs: ([0-9]+) done.*/\1 \2/p')"
      read -r planned done_runs <<< "$counts"
      if [[ "$planned" != "$done_runs" ]]; then
        echo "$name: $((planned - done_runs)) of its $planned runs are not kept; not reported (--kept-only)"
        summary+=("$(printf '%-26s %6s    %s' "$name" - "not reported: $((planned - done_runs)) of $planned runs not kept")")
        continue
      fi
    fi
  fi
  status=ok
  if [[ -n "$keep" && -z "$kept_only" ]] && compgen -G "$keep/$name/.inflight/*/" > /dev/null; then
    # A run a lost machine left unfinished: plan the sweep (it reuses what is kept), give the
    # planned row its kept checkpoint, then run the sweep, which resumes it.
    if "$bin" "${args[@]}" --plan-only > /dev/null; then
      restore_inflight "$keep/$name" "$out/sweeps/$name"
    else
      echo "reproduce_all: $name: its plan failed; the kept unfinished runs start afresh" >&2
    fi
  fi
  keeper=""
  if [[ -n "$keep" && -z "$kept_only" ]]; then  # keeps each run as it finishes, so a machine lost mid-config loses no finished run
    # The sleep away from our stdout: killing the loop leaves it running out its minute, and
    # holding the pipe it would keep a caller reading our output (`| tee`) waiting for it.
    ( while sleep 60 < /dev/null > /dev/null 2>&1; do keep_runs "$out/sweeps/$name/runs" "$keep/$name"; done ) &
    keeper=$!
  fi
  "$bin" "${args[@]}" || { status=FAILED; failed+=("$name"); }
  if [[ -n "$keeper" ]]; then
    kill "$keeper" 2>/dev/null || true
    wait "$keeper" 2>/dev/null || true
  fi
  if [[ -n "$keep" && -z "$kept_only" ]]; then
    keep_runs "$out/sweeps/$name/runs" "$keep/$name"
  fi
  t1=$(date +%s)
  summary+=("$(printf '%-26s %6d s  %s' "$name" $((t1 - t0)) "$status")")
done
end=$(date +%s)
"$bin" reproduce --page "$out" || failed+=("(the page)")
echo
echo "wall time per config:"
printf '  %s\n' "${summary[@]}"
total=$((end - start))
printf 'TOTAL wall time: %d s (%d min %d s) for %d configs; reports in %s, the page %s/index.html\n' \
  "$total" $((total / 60)) $((total % 60)) "${#summary[@]}" "$out" "$out"
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "FAILED: ${failed[*]}" >&2
  exit 1
fi
exit
}
