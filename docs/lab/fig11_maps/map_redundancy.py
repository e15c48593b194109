#!/usr/bin/python3
"""map_redundancy.py POINTS [--u 2] [--sigmas S1,S2,...] [--res R1,R2,...] [--k 20] [--f 1.5] [--width 7]

How much of each Gabor frequency map (method.md section 2: h = (1/k) sum over the k nearest
points of exp(-|p - g|^2 / (2 sigma^2)) cos(2 pi nu . (p - g)), nu on {-f u, 0, f u}^2) is a
linear filter of the spatial map (gamma = 0) of the same points, a filter as wide as the
network's first convolution (7 x 7). If a frequency map is (nearly) such a filter of the
spatial map, the first convolution over the ten maps equals one over the spatial map alone
with other random filters, and the Fig. 11 ablation (spatial maps only against Gabor maps)
compares two random networks on the same information.

Prints per sigma: the distinct maps (cos is even: nu and -nu give the same map, nu = 0 the
spatial map), and for each frequency map the R^2 of its least-squares fit by the WIDTH x WIDTH
shifts of the spatial map plus a constant, over the grid's interior.
POINTS: a plain file of x y per line in the unit square (`ppsynth convert --to plain`)."""
import argparse
import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument('points')
ap.add_argument('--u', type=float, default=2)
ap.add_argument('--sigmas', default='0.15906,0.12643,0.09380,0.06118', help='exemplar units (lines at the fast preset)')
ap.add_argument('--res', default='100,124,168,256', help='output grid positions per axis, per sigma')
ap.add_argument('--k', type=int, default=20)
ap.add_argument('--f', type=float, default=1.5)
ap.add_argument('--width', type=int, default=7)
a = ap.parse_args()

pts = np.array([[float(v) for v in l.split()[:2]] for l in open(a.points) if l.strip() and not l.startswith('#')])
sigmas = [float(s) / a.u for s in a.sigmas.split(',')]
ress = [int(r) for r in a.res.split(',')]
f = a.f * a.u
freqs = [(fx, fy) for fx in (-f, 0, f) for fy in (-f, 0, f)]


def maps(res, sigma):
    b = 1.0 / (res + 1)
    c = np.linspace(b, 1 - b, res)
    gx, gy = np.meshgrid(c, c)  # x along columns, y along rows
    g = np.stack([gx.ravel(), gy.ravel()], 1)
    d = pts[None, :, :] - g[:, None, :]                          # positions x points x 2
    k = min(a.k, len(pts))
    near = np.argsort((d ** 2).sum(2), axis=1)[:, :k]
    dk = np.take_along_axis(d, near[:, :, None], axis=1)          # positions x k x 2
    env = np.exp(-(dk ** 2).sum(2) / (2 * sigma ** 2))
    spatial = env.sum(1) / k
    out = {}
    for nu in freqs:
        out[nu] = (env * np.cos(2 * np.pi * (dk @ np.array(nu)))).sum(1) / k
    return spatial.reshape(res, res), {nu: m.reshape(res, res) for nu, m in out.items()}


def fit_r2(target, source, w):
    h = w // 2
    rows, cols = target.shape
    inner = (slice(h, rows - h), slice(h, cols - h))
    cols_ = [source[h + dy:rows - h + dy, h + dx:cols - h + dx].ravel() for dy in range(-h, h + 1) for dx in range(-h, h + 1)]
    A = np.stack(cols_ + [np.ones_like(cols_[0])], 1)
    y = target[inner].ravel()
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    res = y - A @ coef
    return 1 - (res ** 2).sum() / ((y - y.mean()) ** 2).sum()


print('points: %d, u %g, k %d, f %g per output unit, fit %d x %d' % (len(pts), a.u, a.k, f, a.width, a.width))
print('| sigma (output units) | grid | sigma x f x 2 pi | distinct maps | R^2 of each frequency map from the spatial map: (f,0) (0,f) (f,f) (f,-f) | R^2 from the spatial map at 1 x 1 (a scale) |')
print('| --- | --- | --- | --- | --- | --- |')
for sigma, res in zip(sigmas, ress):
    s, fm = maps(res, sigma)
    distinct = [s] + [fm[nu] for nu in freqs if not any(np.allclose(fm[nu], m) for m in [s])]
    uniq = [s]
    for nu in freqs:
        if not any(np.allclose(fm[nu], m, atol=1e-12) for m in uniq): uniq.append(fm[nu])
    show = [(f, 0), (0, f), (f, f), (f, -f)]
    r2 = [fit_r2(fm[nu], s, a.width) for nu in show]
    r1 = [fit_r2(fm[nu], s, 1) for nu in show]
    print('| %.4f | %d | %.2f | %d of 10 | %s | %s |' % (sigma, res, 2 * np.pi * sigma * f, len(uniq),
          ' '.join('%.4f' % v for v in r2), ' '.join('%.3f' % v for v in r1)))
