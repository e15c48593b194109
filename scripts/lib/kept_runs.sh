# Sourced by scripts/reproduce_all.sh (--keep-runs K): a sweep's runs kept in a folder that
# outlives the machine (docs/lab/reproduce_runs), and given back to a later sweep elsewhere.
#   keep_runs RUNS KEPT          finished runs -> KEPT/RUN; unfinished ones' checkpoints ->
#                                KEPT/.inflight/RUN
#   restore_inflight KEPT SWEEP  the kept checkpoints -> the planned SWEEP's rows, to resume
# Bash functions only: sourcing this file runs nothing.

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
  keep_inflight "$runs" "$kept"
}
# keep_inflight RUNS KEPT: each unfinished run under RUNS with a checkpoint newer than the one
# kept, copied to KEPT/.inflight/RUN with what a resume reads (its marker, config, exemplar copy
# and checkpoint); through a temporary name and a rename, like a finished run.
keep_inflight() {
  local runs="$1" kept="$2" run name
  for run in "$runs"/*/; do
    run="${run%/}"
    name="$(basename "$run")"
    if grep -q '"state": *"complete"' "$run/.ppsynth-run" 2>/dev/null; then
      rm -rf "$kept/.inflight/$name"  # finished (and kept by keep_runs): its checkpoint is done with
      continue
    fi
    [[ -f "$run/checkpoint.bin" && -f "$run/.ppsynth-run" ]] || continue
    cmp -s "$run/checkpoint.bin" "$kept/.inflight/$name/checkpoint.bin" && continue
    rm -rf "$kept/.inflight/.$name.partial"
    mkdir -p "$kept/.inflight/.$name.partial"
    cp "$run/.ppsynth-run" "$run/config.json" "$run/checkpoint.bin" "$kept/.inflight/.$name.partial/"
    [[ -f "$run/exemplar.txt" ]] && cp "$run/exemplar.txt" "$kept/.inflight/.$name.partial/"
    rm -rf "$kept/.inflight/$name"
    mv "$kept/.inflight/.$name.partial" "$kept/.inflight/$name"
  done
}
# restore_inflight KEPT SWEEP: each run KEPT/.inflight holds whose row the planned SWEEP has,
# unfinished there and with the same config, gets the kept checkpoint: the sweep resumes it.
restore_inflight() {
  local kept="$1" sweep="$2" held name
  for held in "$kept"/.inflight/*/; do
    [[ -d "$held" ]] || continue
    held="${held%/}"
    name="$(basename "$held")"
    # a row of this plan (planning names a row's folder; its task makes it)
    grep -q "\"dir\": *\"runs/$name\"" "$sweep/manifest.json" 2>/dev/null || continue
    grep -q '"state": *"complete"' "$sweep/runs/$name/.ppsynth-run" 2>/dev/null && continue
    [[ -f "$sweep/runs/$name/checkpoint.bin" ]] && continue  # its own, at least as new as the kept one
    if [[ -f "$sweep/runs/$name/config.json" ]] && ! cmp -s "$held/config.json" "$sweep/runs/$name/config.json"; then
      echo "reproduce_all: $held was kept from a run of another config than the sweep's row $name; not resumed" >&2
      continue
    fi
    echo "reproduce_all: resuming $name from the checkpoint kept in $held"
    mkdir -p "$sweep/runs/$name"
    cp "$held"/.ppsynth-run "$held"/* "$sweep/runs/$name/"
  done
}
