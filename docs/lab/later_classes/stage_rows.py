#!/usr/bin/python3
"""stage_rows.py RUN_DIR EXEMPLAR W H: per snapshot (each stage's end, cropped to the output
[0,W]x[0,H]) the PCF MSE per row (all, class k, pair) and the verdict's p, from `ppsynth eval --zoom 1`."""
import json, subprocess, sys, os, glob, tempfile
d, ex, W, H = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
files = sorted(glob.glob(os.path.join(d, 'snapshots', 'stage*.txt')))
if os.path.exists(os.path.join(d, 'output.txt')): files.append(os.path.join(d, 'output.txt'))
for f in files:
    tmp = tempfile.mktemp(suffix='.txt')
    subprocess.run(['python3', '/tmp/l64/salvage.py', f, tmp, W, H], check=True)
    r = subprocess.run(['nice', '/tmp/l64/ppsynth', 'eval', '-q', '--exemplar', ex, '--output', tmp, '--zoom', '1', '--json', '--no-curves', '--no-scorecard'],
                       capture_output=True, text=True)
    os.unlink(tmp)
    if r.returncode: print(os.path.basename(f), 'eval failed', r.stderr[-300:]); continue
    m = json.loads(r.stdout)
    cells = ['all %.4f' % m['all']['pcf_mse']]
    cells += ['c%d %.4f' % (i, c['pcf_mse']) for i, c in enumerate(m['classes'])]
    cells += ['x%d%d %.4f' % (c['ci'], c['cj'], c['pcf_mse']) for c in m.get('cross', [])]
    ps = []
    for row in m['verdict']['rows']:
        n = 'all' if row['row'] == 'all' else ('c%d' % row['class'] if row['row'] == 'class' else 'x%d%d' % (row['ci'], row['cj']))
        ps.append('%s p=%s' % (n, 'NA' if row['p'] is None else '%.3f' % row['p']))
    print('%-12s %s | %s' % (os.path.basename(f), '  '.join(cells), '  '.join(ps)))
