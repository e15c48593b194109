#!/usr/bin/env bash
# How a synthesis's cost grows with its output: a one-class exemplar (lines) and a two-class
# one (poisson_n64c2_point) at 4, 16, 64, 256 and 1024 copies of the exemplar's area, square
# and 2:1, each run for a few iterations per stage. Prints, per output: the plan (grid
# positions, windows), the time of one iteration of the whole output at the finest sigma and
# at every sigma (each stage's iteration timed after its first, summed over windows and
# classes), that time per output point, its ratio to the smallest output's, and the peak
# memory. A benchmark, not a test: run it on an otherwise idle machine.
#
#   scripts/bench_scaling.sh OUT [--copies "4 16 64"] [--shapes "square wide"]
#       [--presets "fast default"] [--exemplars "lines poisson_n64c2_point"] [--iterations N]
#       [-- EXTRA SYNTHESIZE ARGS...]
#
# Runs land in OUT/runs/<exemplar>_<preset>_<shape>_<copies>; a finished one is read again,
# not rerun, so an interrupted benchmark resumes where it stopped. The table goes to stdout
# and OUT/scaling.tsv. PPSYNTH_THREADS sets the threads (default 2); PPSYNTH_PYTHON the python3
# that sizes the outputs and prints the table (default Debian's /usr/bin/python3; a GPU
# machine of the device tool has only its torch venv's python3).

# One brace group, read whole before it runs: bash reads a script as it goes, so a `git pull`
# during an hours-long run would otherwise splice the new text into the running one.
{
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage='usage: scripts/bench_scaling.sh OUT [--copies "4 16 64 256 1024"] [--shapes "square wide"] [--presets "fast default"] [--exemplars "lines poisson_n64c2_point"] [--iterations N] [-- SYNTHESIZE ARGS...]'
out=${1:?$usage}
shift
copies="4 16 64 256 1024"
shapes="square wide"
presets="fast default"
exemplars="lines poisson_n64c2_point"
iterations=3
extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --copies) copies=${2:?$usage}; shift 2 ;;
    --shapes) shapes=${2:?$usage}; shift 2 ;;
    --presets) presets=${2:?$usage}; shift 2 ;;
    --exemplars) exemplars=${2:?$usage}; shift 2 ;;
    --iterations) iterations=${2:?$usage}; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "bench_scaling: unknown argument '$1'" >&2; echo "$usage" >&2; exit 2 ;;
  esac
done
[[ $iterations =~ ^[0-9]+$ ]] && [ "$iterations" -ge 2 ] ||
  { echo "bench_scaling: --iterations must be a whole number of at least 2 (the first of a stage is not timed)" >&2; exit 2; }
for s in $shapes; do
  [[ $s == square || $s == wide ]] || { echo "bench_scaling: unknown shape '$s' (square, wide)" >&2; exit 2; }
done
for c in $copies; do
  [[ $c =~ ^[0-9]+$ ]] && [ "$c" -ge 1 ] || { echo "bench_scaling: --copies holds '$c', not a positive whole number" >&2; exit 2; }
done
for ex in $exemplars; do
  [ -f "$here/configs/runs/$ex.json" ] || { echo "bench_scaling: no config $here/configs/runs/$ex.json (--exemplars names configs/runs/NAME.json)" >&2; exit 2; }
done
bin="${PPSYNTH_BIN:-$here/build/ppsynth}"
[ -x "$bin" ] || { echo "bench_scaling: $bin not built (run scripts/setup.sh)" >&2; exit 1; }
export PPSYNTH_THREADS=${PPSYNTH_THREADS:-2}
python=${PPSYNTH_PYTHON:-/usr/bin/python3}
# GNU time's line in each run's log where it is installed (run.json has the times either way).
timer=()
[ -x /usr/bin/time ] && timer=(/usr/bin/time -f "%e s wall, %M KiB peak")
mkdir -p "$out/runs"

# The output's sides in exemplar sides: `copies` exemplar areas, square or twice as wide as high.
sides() {
  "$python" -c 'import math, sys; n = float(sys.argv[1])
print("%.6g %.6g" % ((math.sqrt(n), math.sqrt(n)) if sys.argv[2] == "square" else (math.sqrt(2 * n), math.sqrt(n / 2))))' "$1" "$2"
}

for ex in $exemplars; do
  config="$here/configs/runs/$ex.json"
  for preset in $presets; do
    for shape in $shapes; do
      for c in $copies; do
        run="$out/runs/${ex}_${preset}_${shape}_${c}"
        [ -f "$run/run.json" ] && continue
        read -r w h <<< "$(sides "$c" "$shape")"
        preset_arg=()
        [ "$preset" != default ] && preset_arg=(--preset "$preset")
        echo "== $ex, $preset, $shape, $c copies ($w x $h exemplar sides)" >&2
        "${timer[@]}" "$bin" synthesize "$config" "${preset_arg[@]}" --size "$w" "$h" \
          --set method.max_iterations="$iterations" --set evaluate=false --set snapshots=false \
          --out "$run" -q "${extra[@]}" 2> "$out/runs/${ex}_${preset}_${shape}_${c}.log" >&2 ||
          { echo "bench_scaling: the run failed; see $out/runs/${ex}_${preset}_${shape}_${c}.log" >&2; exit 1; }
      done
    done
  done
done

"$python" - "$out" <<'EOF'
import csv, json, os, sys
out = sys.argv[1]
runs = sorted(d for d in os.listdir(os.path.join(out, "runs")) if os.path.isfile(os.path.join(out, "runs", d, "run.json")))

def stage_iteration_seconds(run):
    """Per stage: its iteration time, from the loss log's clock, the stage's first iteration
    (warm-up, targets) left out."""
    at = {}
    with open(os.path.join(run, "loss.csv")) as f:
        for row in csv.DictReader(f):
            at.setdefault(int(row["stage_index"]), []).append(float(row["seconds"]))
    return {i: (t[-1] - t[0]) / (len(t) - 1) for i, t in at.items() if len(t) > 1}

rows = []
for name in runs:
    run = os.path.join(out, "runs", name)
    r = json.load(open(os.path.join(run, "run.json")))
    m = r["method_stats"]
    ex, rest = name.split("_fast_") if "_fast_" in name else name.split("_default_")
    preset = "fast" if "_fast_" in name else "default"
    shape, copies = rest.split("_")
    per_stage = stage_iteration_seconds(run)
    nsig = len(m["sigmas"])
    finest = sum(s for i, s in per_stage.items() if m["stages"][i]["stage"].endswith("sigma %d/%d" % (nsig, nsig)))
    every = sum(per_stage.values())
    points = sum(1 for line in open(os.path.join(run, "output.txt")) if line.strip() and not line.startswith("#"))
    win = m.get("windows")
    rows.append(dict(exemplar=ex, preset=preset, shape=shape, copies=int(copies), points=points,
                     grid="%dx%d" % (m["output_grid_res"], m["output_grid_rows"]),
                     positions=m["output_grid_res"] * m["output_grid_rows"],
                     windows="%dx%d" % (win["nx"], win["ny"]) if win else "1",
                     window_grid="%dx%d" % tuple(win["grid"]) if win else "",
                     stages=len(m["stages"]), finest_s=finest, every_s=every,
                     us_per_point=1e6 * every / points, peak_mib=r["peak_rss_mib"],
                     run_s=r["synthesis_seconds"]))
rows.sort(key=lambda x: (x["exemplar"], x["preset"], x["shape"], x["copies"]))
base = {}
for x in rows:
    key = (x["exemplar"], x["preset"], x["shape"])
    base.setdefault(key, x["us_per_point"])
    x["ratio"] = x["us_per_point"] / base[key]
cols = ["exemplar", "preset", "shape", "copies", "points", "grid", "positions", "windows", "window_grid", "stages",
        "finest_s", "every_s", "us_per_point", "ratio", "peak_mib", "run_s"]
with open(os.path.join(out, "scaling.tsv"), "w") as f:
    f.write("\t".join(cols) + "\n")
    for x in rows:
        f.write("\t".join(str(x[c]) for c in cols) + "\n")
print("finest s: one iteration of the whole output at the finest sigma (summed over windows and classes);")
print("every s: one iteration of every stage; us/pt: every s per output point; ratio: to the smallest output of its row group")
print("%-20s %-7s %-6s %6s %7s %11s %8s %13s %7s %9s %9s %8s %6s %9s" %
      ("exemplar", "preset", "shape", "copies", "points", "grid", "windows", "window grid", "stages", "finest s", "every s", "us/pt", "ratio", "peak MiB"))
for x in rows:
    print("%-20s %-7s %-6s %6d %7d %11s %8s %13s %7d %9.3f %9.3f %8.1f %6.2f %9.0f" %
          (x["exemplar"], x["preset"], x["shape"], x["copies"], x["points"], x["grid"], x["windows"], x["window_grid"],
           x["stages"], x["finest_s"], x["every_s"], x["us_per_point"], x["ratio"], x["peak_mib"]))
EOF
exit
}
