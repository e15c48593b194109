#!/usr/bin/env bash
# Runs `ppsynth bench` on the shipped published-run configs and prints one summary line each
# (iteration, convolution floor, ratio, set-up, peak memory); the full tables and JSON go to
# bench/ (or $1). A benchmark, not a test: run it on an otherwise idle machine.
# Extra arguments after the output folder go to every bench call (e.g. --reps 3 --skip-setup).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$here/bench}"
shift || true
bin="${PPSYNTH_BIN:-$here/build/ppsynth}"
[ -x "$bin" ] || { echo "bench.sh: $bin not built (run scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$out"
configs=(lines poisson_n64c2_point poisson_n64c2_disk lemon_4c_v2)
for c in "${configs[@]}"; do
  echo "== $c" >&2
  "$bin" bench "$here/configs/runs/$c.json" --json "$out/$c.json" "$@" | tee "$out/$c.txt" >&2
done
python3 - "$out" "${configs[@]}" <<'EOF'
import json, sys
out, names = sys.argv[1], sys.argv[2:]
print(f"{'config':<22}{'iteration s':>12}{'floor s':>9}{'ratio':>7}{'set-up s (all sigmas)':>23}{'peak MiB':>10}")
for n in names:
    b = json.load(open(f"{out}/{n}.json"))
    setup = b["setup_first_s"] + sum(b.get("setup_per_sigma_s", [])[1:])  # first sigma counted once
    print(f"{n:<22}{b['iteration_median_s']:>12.3f}{b['floor_s']:>9.3f}{b['iteration_over_floor']:>7.2f}"
          f"{setup:>23.2f}{b['peak_rss_mib']:>10.0f}")
EOF
