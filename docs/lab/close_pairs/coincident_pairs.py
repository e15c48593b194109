#!/usr/bin/python3
"""coincident_pairs.py [--fraction F] RUN_DIR... : where a run's coincident pairs come from.

For each run directory of `ppsynth synthesize` (with snapshots), counts the pairs of points of
the same class closer than F (default 0.1) x the exemplar's closest pair of any classes, and
the pairs of different classes as close, in the initialization, after every stage
(snapshots/stageNN.txt) and in the output. Distances are in the output's unit square; the
exemplar's are divided by the run's `upscale`. Prints one Markdown row per run: per-stage
same-class counts by class, then the output's totals.

Lab tool of docs/lab/close_pairs (fig06 panel c, sixteenth session)."""
import glob, json, os, sys

import numpy as np


def load(path):
    """x, y, class of a ppsynth points file (comment lines start with '#')."""
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return np.array([[float(r[0]), float(r[1]), float(r[2]) if len(r) > 2 else 0.0] for r in rows])


def close_pairs(pts, threshold):
    """{(a, b): number of pairs of classes a <= b closer than threshold} (in the plane)."""
    cls = pts[:, 2].astype(int)
    d = np.sqrt(((pts[:, None, :2] - pts[None, :, :2]) ** 2).sum(-1))
    i, j = np.triu_indices(len(pts), 1)
    close = d[i, j] < threshold
    out = {}
    for a, b in zip(cls[i][close], cls[j][close]):
        key = (min(a, b), max(a, b))
        out[key] = out.get(key, 0) + 1
    return out


def split(counts):
    same = sum(n for (a, b), n in counts.items() if a == b)
    return same, sum(counts.values()) - same


def main(argv):
    fraction = 0.1
    if argv[:1] == ['--fraction']:
        fraction, argv = float(argv[1]), argv[2:]
    print(f'| run | seed | threshold | init same / cross | same-class pairs by class after each stage | output same / cross |')
    print('| --- | ---: | ---: | --- | --- | --- |')
    for run in argv:
        config = json.load(open(os.path.join(run, 'config.json')))
        ex = load(os.path.join(run, 'exemplar.txt'))
        d = np.sqrt(((ex[:, None, :2] - ex[None, :, :2]) ** 2).sum(-1))
        np.fill_diagonal(d, np.inf)
        threshold = fraction * d.min() / float(config.get('upscale', 1))
        classes = sorted(set(ex[:, 2].astype(int)))
        stages = []
        for f in sorted(glob.glob(os.path.join(run, 'snapshots', 'stage*.txt'))):
            c = close_pairs(load(f), threshold)
            stages.append(os.path.basename(f)[5:7] + ': ' + ','.join(str(c.get((k, k), 0)) for k in classes))
        init = split(close_pairs(load(os.path.join(run, 'init.txt')), threshold))
        out = split(close_pairs(load(os.path.join(run, 'output.txt')), threshold))
        print(f'| {os.path.basename(os.path.normpath(run))} | {config.get("seed")} | {threshold:.5f} | {init[0]} / {init[1]} | '
              f'{"; ".join(stages)} | {out[0]} / {out[1]} |')


if __name__ == '__main__':
    main(sys.argv[1:])
