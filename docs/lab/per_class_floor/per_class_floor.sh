#!/usr/bin/env bash
# What the per-class quadrant PCF MSE can tell apart on a scene (docs/lab/method_measurements.md, "What the
# per-class criterion measures"). Over seeds 1..N it evaluates two reference patterns against
# the exemplar with `ppsynth eval`:
#   init  - each class drawn alone by the synthesizer's initializer (best candidate, u^2 x
#           the class's exemplar count): the baseline of "half the initialization"
#   copy  - the exemplar tiled u x u at a seeded random torus offset (method "tiled_copy"):
#           locally the exemplar itself, the best any structure-preserving method can do
# and prints, per class and for all classes, the median of each and the fraction of copies
# whose MSE is at most half the median initialization's. A class where even the copy rarely
# meets that bound is one the metric cannot judge at this exemplar size.
#
#   docs/lab/per_class_floor/per_class_floor.sh EXEMPLAR [N=40] [UPSCALE=2]
#   e.g. docs/lab/per_class_floor/per_class_floor.sh shared:data/exemplars/gabor-paper/lemon_4c_v2.txt 40
# Needs build/ppsynth (scripts/setup.sh). Writes only under a temporary directory.
set -euo pipefail
cd "$(dirname "$0")/../../.."  # the checkout: this script is in docs/lab/<topic>/
exemplar=${1:?usage: docs/lab/per_class_floor/per_class_floor.sh EXEMPLAR [N] [UPSCALE]}
n=${2:-40}
u=${3:-2}
bin=build/ppsynth
[[ -x $bin ]] || { echo "per_class_floor: $bin not built (scripts/setup.sh)" >&2; exit 1; }
# "shared:" as in the configs (PPSYNTH_SHARED, else ../shared beside the checkout).
[[ $exemplar == shared:* ]] && exemplar="${PPSYNTH_SHARED:-$(cd .. && pwd)/shared}/${exemplar#shared:}"
[[ -f $exemplar ]] || { echo "per_class_floor: no exemplar file $exemplar" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" convert -q "$exemplar" "$tmp/ex.txt" --to plain
# Class counts of the exemplar (plain format: x y class ...).
awk '!/^#/ {c[$3]++} END {for (k in c) print k, c[k]}' "$tmp/ex.txt" | sort -n > "$tmp/counts"

evaluate() {  # file -> "all c0 c1 ..." pcf_mse values
  "$bin" eval -q --exemplar "$exemplar" --output "$1" |
    awk '/^all classes/ {a = $3} /^class / {v = v " " $3} END {print a v}'
}

for s in $(seq 1 "$n"); do
  { printf '# ppsynth points\n# domain 0 0 1 1\n# x y class\n'
    while read -r cls cnt; do
      "$bin" generate -q best_candidate -n $((cnt * u * u)) --seed $((s * 1000 + cls)) --force -o "$tmp/c.txt" > /dev/null 2>&1
      awk -v k="$cls" '!/^#/ {print $1, $2, k}' "$tmp/c.txt"
    done < "$tmp/counts"; } > "$tmp/init.txt"
  echo "init $(evaluate "$tmp/init.txt")" >> "$tmp/rows"
  "$bin" synthesize -q -e "$exemplar" -m tiled_copy --set upscale="$u" --seed "$s" -o "$tmp/copy" > /dev/null
  echo "copy $(evaluate "$tmp/copy/output.txt")" >> "$tmp/rows"
done

awk -v n="$n" '
  function median(arr, m,   i, j, t) {  # sorts arr[1..m] in place
    for (i = 2; i <= m; i++) { t = arr[i]; for (j = i - 1; j >= 1 && arr[j] > t; j--) arr[j + 1] = arr[j]; arr[j + 1] = t }
    return m % 2 ? arr[(m + 1) / 2] : (arr[m / 2] + arr[m / 2 + 1]) / 2
  }
  { cols = NF - 1; for (c = 2; c <= NF; c++) { k = $1 SUBSEP c; cnt[k]++; val[k, cnt[k]] = $c } }
  END {
    printf "%-10s %12s %12s %14s\n", "", "init median", "copy median", "copy <= init/2"
    for (c = 2; c <= cols + 1; c++) {
      delete a; delete b
      for (i = 1; i <= cnt["init" SUBSEP c]; i++) a[i] = val["init" SUBSEP c, i]
      for (i = 1; i <= cnt["copy" SUBSEP c]; i++) b[i] = val["copy" SUBSEP c, i]
      mi = median(a, cnt["init" SUBSEP c]); mc = median(b, cnt["copy" SUBSEP c])
      ok = 0; for (i = 1; i <= cnt["copy" SUBSEP c]; i++) if (b[i] <= mi / 2) ok++
      printf "%-10s %12.4f %12.4f %13.0f%%\n", (c == 2 ? "all" : "class " (c - 3)), mi, mc, 100 * ok / cnt["copy" SUBSEP c]
    }
    printf "(%d seeds; pcf_mse of ppsynth eval, four-quadrant protocol)\n", n
  }' "$tmp/rows"
