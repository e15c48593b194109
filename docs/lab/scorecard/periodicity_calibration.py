#!/usr/bin/env python3
"""Calibration of eval's periodicity line (core/metrics/periodicity.hpp; docs/explanation/scorecard.md).

  /usr/bin/python3 docs/lab/scorecard/periodicity_calibration.py DIR DRAWS FIRST [PROCESS ...]

Runs in one process on the checkout's Python module (build/python: `cmake --build build
--target ppsynth_python ppsynth_python_files`; needs NumPy): the same evaluate() as `ppsynth
eval`, without a process start per pattern. For each process and draw d = FIRST..FIRST+DRAWS-1,
the scorecard's periodicity ratio of
  same   an independent realization of the exemplar's process on 2 x 2 exemplar windows
         (zoom 1): must not be flagged
  big    (generated processes) an independent realization on 5 x 5 exemplar windows
  csr    uniform points of that count per class        (spatstat processes only)
  ssi    a Poisson-disk pattern of that count            (spatstat processes only)
against the draw's exemplar, and for the first TILED draws of each process
  tiled  the tiled_copy method's output (seed d, 2 x 2 whole tiles): must be flagged
  cut    tiled_copy on a 2.6 x 2.3 rectangle (output.size: tiles cut at the edges), zoom 1
PROCESS: strauss hardcore matern thomas lgcp multitype (spatstat.random, drawn by
docs/lab/verdict/verdict_simulate.R into DIR/sim: link an earlier DIR/sim to reuse its draws),
uniform, poisson_disk, jittered_grid, jittered_small (4 x 4 cells, jitter 0.3: Bragg peaks on
the exemplar's harmonics 4 and 8), matern_cluster (`ppsynth generate`'s, 100 exemplar points on
the unit square unless said). Default: all.
TILED (environment, default 30): how many draws of each process get the tiled copies.

  /usr/bin/python3 docs/lab/scorecard/periodicity_calibration.py --summary TABLE ...

Writes DIR/periodicity.tsv (process, kind, draw, ratio, periodic) and prints per process and
kind the draws, the draws flagged, the ratio's median, 99th percentile and maximum (for the
copies: minimum), and the false-alarm rate at the default threshold and at lower ones, over
every kind that is not a copy, with exact (Clopper-Pearson) 95 % intervals; --summary prints
the same of tables written before, pooled.
"""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import ppsynth  # noqa: E402
import numpy as np  # noqa: E402
from scipy.stats import binomtest  # noqa: E402


def clopper_pearson(k, n):
    """Exact (Clopper-Pearson) 95 % interval of a binomial rate k / n; (0, 1) when n is 0."""
    if n == 0:
        return 0.0, 1.0
    ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="exact")
    return ci.low, ci.high

SPATSTAT = ["strauss", "hardcore", "matern", "thomas", "lgcp", "multitype"]
# name: (generator, exemplar points, generator parameters)
GENERATED = {"uniform": ("uniform", 100, {}), "poisson_disk": ("poisson_disk", 100, {}),
             "jittered_grid": ("jittered_grid", 100, {}), "jittered_small": ("jittered_grid", 16, {"jitter": 0.3}),
             "matern_cluster": ("matern_cluster", 100, {})}
COPIES = ("tiled", "cut")
THRESHOLDS = (1.5, 2.0, 2.5, 3.0)


def periodicity(exemplar, output, zoom):
    e = ppsynth.evaluate(exemplar, output, zoom=zoom, curves=False, verdict=False, second_order=False).to_dict()
    p = e["scorecard"]["periodicity"]
    return p["ratio"], p["periodic"]


def cases(dirpath, process, draw, tiled):
    """(kind, exemplar, output, zoom) of one draw (zoom 0: from the densities)."""
    if process in SPATSTAT:
        sim = os.path.join(dirpath, "sim", process)
        path = os.path.join(sim, "d%03d_exemplar.txt" % draw)
        if not os.path.exists(path):
            subprocess.run(["Rscript", os.path.join(ROOT, "docs/lab/verdict/verdict_simulate.R"), os.path.join(dirpath, "sim"),
                            "1", "2", str(draw), process], check=True, capture_output=True)
        ex = ppsynth.read(path)
        out = [(kind, ex, ppsynth.read(os.path.join(sim, "d%03d_%s.txt" % (draw, kind))), 1.0) for kind in ("same", "csr", "ssi")]
    else:
        gen, n, params = GENERATED[process]
        ex = ppsynth.generate(gen, n, seed=2 * draw, **params)
        out = [("same", ex, ppsynth.generate(gen, 4 * n, seed=2 * draw + 1, domain=(0, 0, 2, 2), **params), 1.0),
               ("big", ex, ppsynth.generate(gen, 25 * n, seed=2 * draw + 100001, domain=(0, 0, 5, 5), **params), 1.0)]
    if draw < tiled:
        whole = ppsynth.synthesize(ex, {"method": {"type": "tiled_copy"}}, seed=draw).output
        cut = ppsynth.synthesize(ex, {"method": {"type": "tiled_copy"}, "output": {"size": [2.6, 2.3]}}, seed=draw).output
        out += [("tiled", ex, whole, 0.0), ("cut", ex, cut, 1.0)]
    return out




def summarize(summary):
    print("| process | output | draws | flagged periodic | median ratio | 99th percentile | max (copies: min) |")
    print("|---|---|---|---|---|---|---|")
    nulls = []
    for (process, kind), rows in summary.items():
        ratios = [r for r, _ in rows]
        flagged = sum(bool(p) for _, p in rows)
        extreme = min(ratios) if kind in COPIES else max(ratios)
        print("| %s | %s | %d | %d | %.3g | %.3g | %.3g |" % (process, kind, len(rows), flagged, np.quantile(ratios, 0.5),
                                                        np.quantile(ratios, 0.99), extreme))
        if kind not in COPIES:
            nulls += ratios
    if nulls:
        print("\npatterns that are not copies: %d; largest ratio %.3g" % (len(nulls), max(nulls)))
        for t in THRESHOLDS:
            k = sum(r >= t for r in nulls)
            lo, hi = clopper_pearson(k, len(nulls))
            print("  from %.1f: %d flagged (%.2f %%, 95 %% interval %.2f-%.2f %%)" % (t, k, 100 * k / len(nulls), 100 * lo, 100 * hi))


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--summary":  # tables written before, pooled
        summary = {}
        for table in sys.argv[2:]:
            for line in open(table):
                process, kind, _, r, flagged = line.rstrip("\n").split("\t")
                summary.setdefault((process, kind), []).append((float(r), flagged == "True"))
        summarize(summary)
        return
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    dirpath, draws, first = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    processes = sys.argv[4:] or SPATSTAT + list(GENERATED)
    tiled = first + int(os.environ.get("TILED", "30"))
    os.makedirs(dirpath, exist_ok=True)
    table = os.path.join(dirpath, "periodicity.tsv")
    summary = {}
    with open(table, "w") as f:
        for process in processes:
            for draw in range(first, first + draws):
                for kind, ex, out, zoom in cases(dirpath, process, draw, tiled):
                    r, flagged = periodicity(ex, out, zoom)
                    f.write("%s\t%s\t%d\t%r\t%s\n" % (process, kind, draw, r, flagged))
                    summary.setdefault((process, kind), []).append((r, flagged))
    summarize(summary)


if __name__ == "__main__":
    main()
