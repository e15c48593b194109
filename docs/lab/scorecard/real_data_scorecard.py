#!/usr/bin/env python3
"""The scorecard first, the verdict beside it: one table over the six real sets (docs/explanation/verdict.md).

  /usr/bin/python3 docs/lab/scorecard/real_data_scorecard.py WORK EXEMPLARS FITTED "SEEDS" [RUNS ...]
  e.g. ... /tmp/rs /tmp/real/exemplars /tmp/fid/real/fitted "95 96 97 98 99" /tmp/s5/real /tmp/l64/runs
  SETS="redwood longleaf" in the environment judges those sets only.

Per set (cells redwood japanesepines swedishpines longleaf amacrine) and kind, over the seeds:
  fitted      FITTED/SET_dNNN.txt, draws 1..len(SEEDS) (docs/lab/verdict/spatstat_fitted.R)
  tiled_copy  `ppsynth synthesize -m tiled_copy --seed S` into WORK/SET_tiled_copy_sS (made when missing)
  pcf2017     the same with -m pcf2017 (its defaults; under a minute on these sets)
  gabor       RUNS/SET_sS/output.txt where it exists (for amacrine also RUNS/ama1x_own_sS: the lead's
              2.56 x 1 runs with class_own), seeds that have none left out
`ppsynth eval` at its defaults in one process (the Python module: build/python or PPSYNTH_PYTHON; a
fitted draw at zoom 1, as it is in exemplar units, the syntheses at the zoom of the densities):
the scorecard's fidelity (every row within band; the all-points row's L and g in spreads), its
copy flag, and the verdict (rows passing at 5 %; the all-points row's p). Prints a markdown table.
"""
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.environ.get("PPSYNTH_PYTHON", os.path.join(ROOT, "build", "python")))
import ppsynth  # noqa: E402

ALL_SETS = ("cells", "redwood", "japanesepines", "swedishpines", "longleaf", "amacrine")
SETS = tuple(s for s in ALL_SETS if s in os.environ.get("SETS", " ".join(ALL_SETS)).split())
BIN = os.environ.get("PPSYNTH_BIN", os.path.join(ROOT, "build", "ppsynth"))


def synthesized(work, name, method, seed):
    run = os.path.join(work, "%s_%s_s%d" % (name, method, seed))
    if not os.path.exists(os.path.join(run, "output.txt")):
        subprocess.run([BIN, "synthesize", "-q", "-e", os.path.join(EXEMPLARS, name + ".txt"), "-m", method, "--seed",
                        str(seed), "-o", run, "--force"], check=True, capture_output=True,
                       env=dict(os.environ, PPSYNTH_THREADS="1"))
    return os.path.join(run, "output.txt")


def outputs(work, fitted, name, seeds, runs):
    """(kind, [(seed, output file)]) of one set."""
    kinds = [("fitted", [(i + 1, os.path.join(fitted, "%s_d%03d.txt" % (name, i + 1))) for i in range(len(seeds))])]
    gabor = []
    for s in seeds:
        for folder in runs:
            for run in ("%s_s%d" % (name, s),) + (("ama1x_own_s%d" % s,) if name == "amacrine" else ()):
                path = os.path.join(folder, run, "output.txt")
                if os.path.exists(path) and s not in [g[0] for g in gabor]:
                    gabor.append((s, path))
    if gabor:
        kinds.append(("gabor (ppsynth)", gabor))
    kinds.append(("pcf2017", [(s, synthesized(work, name, "pcf2017", s)) for s in seeds]))
    kinds.append(("tiled_copy", [(s, synthesized(work, name, "tiled_copy", s)) for s in seeds]))
    return kinds


def main():
    global EXEMPLARS
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    work, EXEMPLARS, fitted, seeds, runs = sys.argv[1], sys.argv[2], sys.argv[3], [int(s) for s in sys.argv[4].split()], sys.argv[5:]
    os.makedirs(work, exist_ok=True)
    print("| data set | output | seeds | fidelity: every row within band | fidelity, all points: median L, g spreads "
          "(band) | flagged a copy | verdict: every row passes at 5 % | verdict p, all points (median) |")
    print("|---|---|---|---|---|---|---|---|")
    for name in SETS:
        ex = ppsynth.read(os.path.join(EXEMPLARS, name + ".txt"))
        for kind, files in outputs(work, fitted, name, seeds, runs):
            within = copies = passes = 0
            l, g, p, band = [], [], [], None
            for _, path in files:
                # A fitted model's draw is in exemplar units (zoom 1); the syntheses' zoom comes from the densities.
                zoom = 1.0 if kind == "fitted" else 0.0
                e = ppsynth.evaluate(ex, ppsynth.read(path), zoom=zoom, curves=False, second_order=False).to_dict()
                sc = e["scorecard"]
                within += sc["fidelity"]["within"] is True
                row = sc["fidelity"]["rows"][0]
                l.append((row.get("l") or {}).get("spreads"))
                g.append((row.get("g") or {}).get("spreads"))
                band = (row.get("l") or {}).get("band", band)
                copies += bool(sc["novelty"].get("copy"))
                rows = e["verdict"]["rows"]
                passes += all(r.get("outcome") == "pass" for r in rows)
                p.append(rows[0].get("p"))
            med = lambda v: np.median([x for x in v if x is not None]) if any(x is not None for x in v) else float("nan")  # noqa: E731
            n = len(files)
            print("| %s | %s | %s | %d / %d | %.2f, %.2f (%.2f) | %d / %d | %d / %d | %.3f |" % (
                name, kind, ",".join(str(s) for s, _ in files), within, n, med(l), med(g), band or float("nan"), copies, n,
                passes, n, med(p)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
