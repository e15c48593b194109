#!/usr/bin/python3
"""salvage.py SNAPSHOT OUT W H: the points of a canvas snapshot inside [0,W]x[0,H], as a point file."""
import sys
src, dst, W, H = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
out = []
for line in open(src):
    if line.startswith('#'):
        if line.startswith('# domain'):
            line = '# domain 0 0 %.17g %.17g\n' % (W, H)
        out.append(line); continue
    f = line.split()
    if len(f) >= 2 and 0 <= float(f[0]) <= W and 0 <= float(f[1]) <= H: out.append(line)
open(dst, 'w').writelines(out)
