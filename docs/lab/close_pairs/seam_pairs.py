#!/usr/bin/python3
"""seam_pairs.py RUN_DIR... : for each run's output on the unit torus (the paper's u x u square),
the normalized minimum distance rho measured in the plane and on the torus (table1's measure:
rho = (d_min / 2) / r_max, r_max = sqrt(1 / (2 sqrt(3) N))), whether the closest torus pair
crosses the square's edge (a seam pair), and how many torus pairs are closer than the plane's
closest. PPSYNTH_BIN picks the binary that converts output.txt to plain text."""
import math, os, subprocess, sys, tempfile

import numpy as np

BIN = os.environ.get('PPSYNTH_BIN', 'build/ppsynth')


def points(run):
    with tempfile.TemporaryDirectory() as t:
        plain = os.path.join(t, 'p.txt')
        subprocess.run([BIN, 'convert', '-q', os.path.join(run, 'output.txt'), plain, '--to', 'plain'], check=True)
        return np.array([[float(v) for v in l.split()[:2]] for l in open(plain) if l.strip() and not l.startswith('#')])


print('| run | points | rho, plane | rho, torus | closest torus pair | torus pairs below the plane\'s closest |')
print('| --- | ---: | ---: | ---: | --- | ---: |')
for run in sys.argv[1:]:
    p = points(run)
    n = len(p)
    r_max = math.sqrt(1 / (2 * math.sqrt(3) * n))
    diff = p[:, None, :] - p[None, :, :]
    plane = np.sqrt((diff ** 2).sum(2))
    wrapped = diff - np.round(diff)
    torus = np.sqrt((wrapped ** 2).sum(2))
    np.fill_diagonal(plane, np.inf)
    np.fill_diagonal(torus, np.inf)
    i, j = np.unravel_index(torus.argmin(), torus.shape)
    seam = not np.allclose(wrapped[i, j], diff[i, j])
    below = int((torus < plane.min()).sum() // 2)
    print('| %s | %d | %.3f | %.3f | %s | %d |' % (run.rstrip('/'), n, plane.min() / 2 / r_max, torus.min() / 2 / r_max,
                                                 'across the edge' if seam else 'inside', below))
