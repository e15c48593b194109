"""docs/lab/border_criterion/edge_against_lines.py (a proposed border criterion): on a torus
output the edge is one line like any other, so a pattern with no border artifact puts the edge
among its random lines, a pile on the edge puts it at the top, and a thin seam at the bottom."""
import os
import subprocess
import sys

import numpy as np

from conftest import SOURCE_DIR

SCRIPT = os.path.join(SOURCE_DIR, "docs", "lab", "border_criterion", "edge_against_lines.py")


def write(path, points):
    with open(path, "w") as f:
        f.write("# ppsynth points\n# domain 0 0 1 1\n# x y\n")
        for x, y in points:
            f.write(f"{x!r} {y!r}\n")


def quantiles(*paths):
    p = subprocess.run([sys.executable, SCRIPT, *map(str, paths)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    rows = p.stdout.splitlines()[1:]
    return [[float(v) for v in row.rsplit("|", 1)[1].split()] for row in rows]


def test_a_pile_on_the_edge_tops_every_random_line_and_a_torus_pattern_does_not(tmp_path):
    rng = np.random.default_rng(5)
    # A jittered 20 x 20 lattice shifted off the edge: no line of the torus is special.
    g = (np.stack(np.meshgrid(np.arange(20), np.arange(20)), -1).reshape(-1, 2) + 0.37 + rng.uniform(-0.3, 0.3, (400, 2))) / 20
    clean = g % 1.0
    # The same with the points nearest the edge moved onto it (a published border's pile).
    piled = clean.copy()
    near = np.abs(((piled + 0.5) % 1.0) - 0.5) < 0.03
    piled[near] = np.where(piled[near] > 0.5, 0.9995, 0.0005)
    # And with the edge's strip emptied (a thin seam): those points moved 0.05 inward.
    thin = clean.copy()
    thin[near] = np.where(thin[near] > 0.5, thin[near] - 0.05, thin[near] + 0.05)
    for name, pts in (("clean", clean), ("piled", piled), ("thin", thin)):
        write(tmp_path / f"{name}.txt", pts)
    q_clean, q_piled, q_thin = quantiles(tmp_path / "clean.txt", tmp_path / "piled.txt", tmp_path / "thin.txt")
    assert all(0.05 <= q <= 0.95 for q in q_clean), q_clean
    # Within 0.5-2 %: the moved points stay inside 4 % either way, so that width keeps its count.
    assert all(q >= 0.99 for q in q_piled[:3]), q_piled
    # An empty strip ties with the random lines that are empty too; at 0.5 % some are.
    assert all(q <= 0.05 for q in q_thin[1:3]) and q_thin[0] <= 0.2, q_thin


def test_it_refuses_an_output_that_is_not_the_unit_square(tmp_path):
    (tmp_path / "rect.txt").write_text("# ppsynth points\n# domain 0 0 4 1\n# x y\n0.5 0.5\n")
    p = subprocess.run([sys.executable, SCRIPT, str(tmp_path / "rect.txt")], capture_output=True, text=True)
    assert p.returncode != 0 and "rect.txt" in p.stderr and "unit square" in p.stderr
