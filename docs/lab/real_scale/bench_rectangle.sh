#!/usr/bin/env bash
# What a Gabor synthesis costs per grid position, run against run (a rectangle
# output on one grid against a square one of about as many positions). Each NAME=ARGS is one
# `ppsynth synthesize ARGS FLAGS` into OUT_DIR/NAME, one after the other (run back to back,
# their ratios hold on a loaded machine where their times do not); then, per run, the plan
# (grid columns x rows per sigma, windows), the synthesis time, the seconds per iteration and
# per million grid positions and iteration at each sigma (all classes and windows together),
# the phases (run.json's phase_seconds; what is left of the synthesis time: the stages' and
# windows' bookkeeping) and the peak memory. A benchmark: it prints numbers.
#
# Usage: docs/lab/real_scale/bench_rectangle.sh OUT_DIR NAME=ARGS... [-- FLAGS...]
#   docs/lab/real_scale/bench_rectangle.sh /tmp/b "amacrine=-e data/spatstat/amacrine.txt" \
#     "poisson_u4=-e shared:data/exemplars/gabor-paper/poisson_n64c2_point.txt --set upscale=4" \
#     -- --preset fast --set method.max_iterations=3
#   PPSYNTH    the binary (default build/ppsynth); PPSYNTH_THREADS as for any run (default 1)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
[ $# -ge 2 ] || { echo "usage: docs/lab/real_scale/bench_rectangle.sh OUT_DIR NAME=ARGS... [-- FLAGS...]" >&2; exit 2; }
out=$1
shift
runs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do runs+=("$1"); shift; done
[ $# -gt 0 ] && shift
flags=("$@")
bin=${PPSYNTH:-$here/build/ppsynth}
export PPSYNTH_THREADS=${PPSYNTH_THREADS:-1}
mkdir -p "$out"
names=()
for r in "${runs[@]}"; do
  name=${r%%=*}
  args=${r#*=}
  [ -e "$out/$name" ] && { echo "$out/$name exists: give a new OUT_DIR or remove it" >&2; exit 2; }
  echo "== $name: $bin synthesize $args ${flags[*]}  (load $(cut -d' ' -f1-3 /proc/loadavg))"
  # shellcheck disable=SC2086  # ARGS is a list of words
  "$bin" synthesize $args "${flags[@]}" --set evaluate=false --set snapshots=false -q -o "$out/$name"
  names+=("$name")
done
python3 - "$out" "${names[@]}" <<'EOF'
import json, sys
out, names = sys.argv[1], sys.argv[2:]
for n in names:
    r = json.load(open(f"{out}/{n}/run.json"))
    m = r["method_stats"]
    cols, rows = m["output_grid_res_per_sigma"], m.get("output_grid_rows_per_sigma", m["output_grid_res_per_sigma"])
    w = m.get("windows", {"nx": 1, "ny": 1})
    print(f"{n}: {r['synthesis_seconds']:.1f} s, peak {r['peak_rss_mib']:.0f} MiB, {r['threads']} threads, "
          f"windows {w['nx']} x {w['ny']}, grid per sigma {' '.join(f'{c}x{q}' for c, q in zip(cols, rows))}")
    per = {}
    for s in m["stages"]:
        label = s["stage"]
        if "sigma " not in label or s["iterations"] == 0:
            continue
        i = int(label.split("sigma ")[1].split("/")[0]) - 1
        t = per.setdefault(i, [0.0, 0, 0.0])
        t[0] += s["seconds"]
        t[1] += s["iterations"]
        t[2] += s["iterations"] * cols[i] * rows[i]
    for i in sorted(per):
        sec, its, pos = per[i]
        # An iteration of the whole output is one of every window's (exact with a fixed cap).
        print(f"  sigma {i + 1}: {its} iterations, {sec * w['nx'] * w['ny'] / its:.2f} s per iteration of the whole output, "
              f"{1e6 * sec / pos:.2f} s per million grid positions and iteration")
    ph = m["phase_seconds"]
    rest = r["synthesis_seconds"] - sum(ph.values())
    print("  phases: " + ", ".join(f"{k} {v:.1f}" for k, v in ph.items()) + f", other {rest:.1f} s")
EOF
