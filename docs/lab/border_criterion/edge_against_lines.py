#!/usr/bin/python3
"""Is the square's edge special in a u x u output? (a proposed border criterion)

The paper's u x u output is a torus: its edge is one line of it like any other. This compares
the density near the edge (the lines x = 0 and y = 0, both sides) with the density near
`--lines` random axis-parallel lines of the same output, at widths 0.5, 1, 2 and 4 % of the
side, each over what uniform points put there. The edge's quantile among the random lines is
near 1 where points pile on it, near 0 where the edge is a thin seam, and anywhere between
where the edge looks like any other line. Unlike a bound on the density itself, this holds
for lattice-like patterns, whose density near a line depends on where the line falls between
rows (Tree1: docs/lab/large_outputs.md, "The relax as the default").

    docs/lab/border_criterion/edge_against_lines.py RUN_DIR/output.txt [RUN_DIR/snapshots/stage04.txt ...]

Reads the ppsynth point format (`# domain 0 0 1 1` outputs only); the lines are drawn from
`--seed`, so the same files give the same table.
"""
import argparse
import sys

import numpy as np

WIDTHS = (0.005, 0.01, 0.02, 0.04)


def read_unit_square(path):
    domain = None
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith("# domain"):
                domain = [float(v) for v in line.split()[2:6]]
    if domain != [0.0, 0.0, 1.0, 1.0]:
        sys.exit(f"{path}: expected a u x u output on the unit square ('# domain 0 0 1 1'), got {domain}")
    points = np.loadtxt(path, comments="#", ndmin=2)
    if points.shape[0] == 0:
        sys.exit(f"{path}: no points")
    return points[:, :2]


def density_near(points, axis, at, width):
    """Share of points within `width` of the torus line `axis` = `at`, over uniform's (2 width)."""
    d = np.abs(((points[:, axis] - at + 0.5) % 1.0) - 0.5)
    return np.mean(d < width) / (2 * width)


def profile(points, at_x, at_y):
    return np.array([(density_near(points, 0, at_x, w) + density_near(points, 1, at_y, w)) / 2 for w in WIDTHS])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+")
    ap.add_argument("--lines", type=int, default=400, help="random lines per axis (400)")
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args()
    if a.lines < 20:
        sys.exit("--lines: at least 20")
    header = " ".join(f"{100 * w:g}%" for w in WIDTHS)
    print(f"file | edge density over uniform's ({header}) | random lines 5 / 50 / 95 % | edge's quantile")
    for path in a.files:
        points = read_unit_square(path)
        rng = np.random.default_rng(a.seed)
        edge = profile(points, 0.0, 0.0)
        lines = np.array([profile(points, *rng.random(2)) for _ in range(a.lines)])
        q = np.quantile(lines, [0.05, 0.5, 0.95], axis=0)
        rank = (lines <= edge).mean(axis=0)
        fmt = lambda v: " ".join(f"{x:.2f}" for x in v)
        print(f"{path} | {fmt(edge)} | {fmt(q[0])} / {fmt(q[1])} / {fmt(q[2])} | {fmt(rank)}")


if __name__ == "__main__":
    main()
