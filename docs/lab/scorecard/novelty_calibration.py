#!/usr/bin/env python3
"""Calibration of eval's novelty line (core/metrics/novelty.hpp; docs/explanation/scorecard.md).

  docs/lab/scorecard/novelty_calibration.py DIR DRAWS FIRST K TOLERANCE [PROCESS ...]

For each process and draw d = FIRST..FIRST+DRAWS-1, `ppsynth eval` (the scorecard only) of
  same   an independent realization of the exemplar's process on 2 x 2 exemplar windows
  csr    uniform points of that count per class      (spatstat processes only)
  ssi    a Poisson-disk pattern of that count          (spatstat processes only)
  tiled  the tiled_copy method's output (seed d): must be flagged
against the draw's exemplar, at neighbourhoods of K points and TOLERANCE mean NN distances.
PROCESS: strauss hardcore matern thomas lgcp multitype (spatstat.random, drawn by
docs/lab/verdict/verdict_simulate.R into DIR/sim), uniform and poisson_disk (`ppsynth
generate`, 100 exemplar points against 400 on [0, 2]^2), poisson_disk_large (2000 against
8000: more exemplar neighbourhoods to match by chance). Default: all.

Writes DIR/k{K}_t{TOLERANCE}.tsv (process, kind, draw, scored, matched, share, closest, copy)
and prints, per process and kind, the draws flagged a copy, the draws with any matched point,
the largest share and the smallest best-match distance seen. A share at TOLERANCE bounds the
share at every smaller tolerance, so one run at the largest tolerance considered bounds them all.
"""
import json
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.path.join(ROOT, "build", "ppsynth")
SPATSTAT = ["strauss", "hardcore", "matern", "thomas", "lgcp", "multitype"]
GENERATED = {"uniform": ("uniform", 100), "poisson_disk": ("poisson_disk", 100), "poisson_disk_large": ("poisson_disk", 2000)}


def run(args):
    return subprocess.run([BIN] + args, check=True, capture_output=True, text=True).stdout


def scorecard(exemplar, output, k, tol, zoom):
    args = ["eval", "-q", "--exemplar", exemplar, "--output", output, "--json", "--no-curves", "--no-verdict",
            "--no-second-order", "--novelty-k", str(k), "--novelty-tolerance", str(tol)]
    if zoom:
        args += ["--zoom", zoom]
    return json.loads(run(args))["scorecard"]["novelty"]


def cases(dirpath, process, draw):
    """(kind, exemplar, output, zoom) of one draw; files made on first use."""
    if process in SPATSTAT:
        sim = os.path.join(dirpath, "sim", process)
        ex = os.path.join(sim, "d%03d_exemplar.txt" % draw)
        if not os.path.exists(ex):
            subprocess.run(["Rscript", os.path.join(ROOT, "docs/lab/verdict/verdict_simulate.R"), os.path.join(dirpath, "sim"),
                            "1", "2", str(draw), process], check=True, capture_output=True)
        out = [(kind, ex, os.path.join(sim, "d%03d_%s.txt" % (draw, kind)), "1") for kind in ("same", "csr", "ssi")]
    else:
        gen, n = GENERATED[process]
        base = os.path.join(dirpath, "gen", process)
        os.makedirs(base, exist_ok=True)
        ex = os.path.join(base, "d%03d_exemplar.txt" % draw)
        same = os.path.join(base, "d%03d_same.txt" % draw)
        if not os.path.exists(same):
            run(["generate", gen, "-n", str(n), "--seed", str(2 * draw), "-o", ex, "--force", "-q"])
            run(["generate", gen, "-n", str(4 * n), "--seed", str(2 * draw + 1), "--domain", "0", "0", "2", "2",
                 "-o", same, "--force", "-q"])
        out = [("same", ex, same, "1")]
    tiled = os.path.join(dirpath, "tiled", "%s_d%03d" % (process, draw))
    if not os.path.exists(os.path.join(tiled, "output.txt")):
        run(["synthesize", "-q", "-e", ex, "-m", "tiled_copy", "--seed", str(draw), "-o", tiled, "--force"])
    return out + [("tiled", ex, os.path.join(tiled, "output.txt"), None)]


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    dirpath, draws, first, k, tol = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5])
    processes = sys.argv[6:] or SPATSTAT + list(GENERATED)
    os.makedirs(dirpath, exist_ok=True)
    table = os.path.join(dirpath, "k%d_t%g.tsv" % (k, tol))
    summary = {}
    with open(table, "w") as f:
        for process in processes:
            for draw in range(first, first + draws):
                for kind, ex, out, zoom in cases(dirpath, process, draw):
                    n = scorecard(ex, out, k, tol, zoom)
                    f.write("\t".join(str(x) for x in (process, kind, draw, n["scored"], n["matched"], n["share"],
                                                        n["closest"], n["copy"])) + "\n")
                    s = summary.setdefault((process, kind), {"draws": 0, "copy": 0, "any": 0, "share": 0.0, "closest": None})
                    s["draws"] += 1
                    s["copy"] += bool(n["copy"])
                    s["any"] += n["matched"] > 0
                    s["share"] = max(s["share"], n["share"] or 0.0)
                    if n["closest"] is not None:
                        s["closest"] = n["closest"] if s["closest"] is None else min(s["closest"], n["closest"])
    print("k %d, tolerance %g mean NN distances, copy from share %s (%s)" % (k, tol, n["copy_share"], table))
    print("| process | output | draws | flagged a copy | draws with a matched point | largest share | closest match |")
    print("|---|---|---|---|---|---|---|")
    for (process, kind), s in summary.items():
        print("| %s | %s | %d | %d | %d | %.4f | %s |" % (process, kind, s["draws"], s["copy"], s["any"], s["share"],
                                                        "-" if s["closest"] is None else "%.3g" % s["closest"]))


if __name__ == "__main__":
    main()
