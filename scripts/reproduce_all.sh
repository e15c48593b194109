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
#               one item reused from another's is kept once.
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
# keep_runs RUNS KEPT: the finished runs under RUNS, each copied to KEPT/RUN with the files a
# reuse and a report read (load_run: config, records, points, metrics, the completion marker),
# not the pictures, snapshots and logs, which a report draws again from the points. Through a
# temporary name and a rename, so a kill leaves no half-kept run that would count as finished.
keep_runs() {
  local runs="$1" kept="$2" run name kept_records
  [[ -d "$runs" ]] || return 0
  mkdir -p "$kept"
  # The run records kept so far, by content: a run reused from K under another name (a run
  # the other kind of processor made, whose config resolves otherwise here) is kept once.
  kept_records="$(for f in "$(dirname "$kept")"/*/*/run.json; do if [[ -f "$f" ]]; then md5sum < "$f"; fi; done)"
  for run in "$runs"/*/; do
    run="${run%/}"
    name="$(basename "$run")"
    # kept already, here or under an earlier item (the sweeps name a run by its config and
    # seed, and an item that reused another's run holds the same run)
    compgen -G "$(dirname "$kept")/*/$name" > /dev/null && continue
    grep -q '"state": *"complete"' "$run/.ppsynth-run" 2>/dev/null || continue
    if [[ -f "$run/run.json" ]] && grep -qxF "$(md5sum < "$run/run.json")" <<< "$kept_records"; then continue; fi
    rm -rf "$kept/.$name.partial"
    mkdir -p "$kept/.$name.partial"
    for f in .ppsynth-run config.json run.json output.txt output.*.txt init.txt exemplar.txt; do
      [[ -f "$run/$f" ]] && cp "$run/$f" "$kept/.$name.partial/"
    done
    # metrics.json without the K/L/g and mark-correlation curves (nine tenths of its bytes):
    # the numbers a gather and a report read (l_sup, the verdict, the scorecard, the PCF) stay.
    [[ -f "$run/metrics.json" ]] && /usr/bin/python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))
so = m.get("second_order")
if isinstance(so, dict):
    so.pop("mark_correlation", None)
    for row in so.get("rows", []):
        for curve in ("r", "exemplar", "output"):
            row.pop(curve, None)
json.dump(m, open(sys.argv[2], "w"), separators=(",", ":"))
' "$run/metrics.json" "$kept/.$name.partial/metrics.json"
    mv "$kept/.$name.partial" "$kept/$name"
  done
}
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
