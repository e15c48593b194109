#!/usr/bin/python3
"""A gallery: every shipped exemplar beside a synthesis of it, on one self-contained HTML page.

    scripts/gallery.py -o gallery.html                  # every exemplar of configs/runs, --quick
    scripts/gallery.py -o gallery.html --preset fast    # the same at the fast preset (minutes each)
    scripts/gallery.py -o gallery.html --runs DIR...    # finished run directories (a sweep's runs/*)
    scripts/gallery.py -o page.html --pair LABEL EXEMPLAR OUTPUT ...   # point files (a model's draw, an output.txt)

Without --runs, it synthesizes each base config of configs/runs (one per shipped exemplar: the
configs whose parent, if any, is a method fragment) into a scratch directory, `--quick` unless
--preset is given (quick settings show the pipeline, not the method's quality). Each card shows
the exemplar beside the output (the run's exemplar_vs_output.png), the point counts, PCF MSE,
Wasserstein and Chamfer distance, the scorecard (novelty: is it a copy of the exemplar?;
fidelity: its L and g distances in spreads of independent realizations, within the band or
not; periodicity; close pairs; docs/explanation/scorecard.md) and the spatstat-style verdict
where the evaluation has them, and the settings it ran with. A multi-class exemplar and its
output are drawn once more class by class, each class on its own beside all together. Per
fidelity row, L(r) - r of exemplar and output with fidelity's band around the exemplar's (where
the evaluation has the curves). A --pair card evaluates OUTPUT against EXEMPLAR with `ppsynth
eval` and draws both (docs/lab/scorecard/real_data_page.sh: the six real sets). Pictures are
embedded, so the page is one file to open or send.

The page is written whole or not at all; an existing file is replaced only with --force.
"""
import argparse
import base64
import datetime
import html
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BIN = os.environ.get("PPSYNTH_BIN", os.path.join(ROOT, "build", "ppsynth"))


def base_configs():
    """One config per shipped exemplar: no parent, or a method fragment of configs/methods."""
    runs = os.path.join(ROOT, "configs", "runs")
    out = []
    for name in sorted(os.listdir(runs)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(runs, name)) as f:
            c = json.load(f)
        parent = c.get("parent", "")
        if parent and not parent.startswith("../methods/"):
            continue  # a variant of another run config
        if c.get("method", {}).get("type", "gabor") != "gabor":
            continue  # a baseline run, not the method
        if c.get("output") or c.get("upscale", 2) != 2:
            continue  # a large output: another page (docs/howto/large_outputs.md)
        out.append(os.path.join(runs, name))
    return out


def synthesize(configs, work, preset, threads):
    dirs = []
    for i, cfg in enumerate(configs, 1):
        d = os.path.join(work, os.path.splitext(os.path.basename(cfg))[0])
        cmd = [BIN, "synthesize", cfg, "-o", d, "-q"] + (["--preset", preset] if preset else ["--quick"])
        print(f"[{i}/{len(configs)}] {' '.join(os.path.relpath(c, ROOT) if c.startswith(ROOT) else c for c in cmd[1:])}",
              flush=True)
        env = dict(os.environ, PPSYNTH_THREADS=str(threads)) if threads else None
        p = subprocess.run(cmd, capture_output=True, text=True, env=env)
        if p.returncode != 0:
            sys.exit(f"gallery: {cfg}: ppsynth synthesize failed (exit {p.returncode}):\n{p.stderr.strip()}")
        dirs.append(d)
    return dirs


def read_json(path):
    with open(path) as f:
        return json.load(f)


def measure(a, key):
    """A measure of metrics.json's "all" as the card shows it. Null where it was not computed
    exactly: Wasserstein past the exact assignment's size has a subsample estimate beside it
    (core/metrics/evaluation.cpp), said as one; anything else null is "n/a"."""
    v = a.get(key)
    if isinstance(v, (int, float)):
        return f"{v:.3g}"
    estimate = a.get(key + "_estimate")
    if isinstance(estimate, (int, float)):
        sample = a.get(key + "_sample")
        of = f", subsamples of {sample[0]} and {sample[1]} points" if isinstance(sample, list) and len(sample) == 2 else ""
        return f"&asymp; {estimate:.3g} (estimate{of})"
    return "n/a"


# Class colours of the per-class panels, in class order as the run's own picture (matplotlib's
# tab10; later classes cycle).
COLOURS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf")


def read_points(path):
    """A plain point file as ppsynth writes it ("# domain x0 y0 x1 y1", "# class_labels ..." or
    "# classes 0=a 1=b", the columns' header "# x y [class] [attributes ...]", then the rows, the
    class an index into the labels; without the header the third column is the class):
    (domain, [(x, y, class)], labels); None when the file is not in that form (the card then
    shows no per-class panels)."""
    domain, points, labels, column = None, [], [], 2
    try:
        with open(path) as f:
            for line in f:
                t = line.split()
                if not t:
                    continue
                if t[0] == "#":
                    if len(t) == 6 and t[1] == "domain":
                        domain = tuple(float(v) for v in t[2:])
                    if len(t) > 2 and t[1] == "class_labels":
                        labels = t[2:]
                    if len(t) > 2 and t[1] == "classes":
                        labels = [c.split("=", 1)[-1] for c in t[2:]]
                    if len(t) >= 3 and t[1:3] == ["x", "y"]:  # a mark column is not a class
                        column = t.index("class") - 1 if "class" in t else None
                    continue
                c = int(float(t[column])) if column is not None and len(t) > column else 0
                points.append((float(t[0]), float(t[1]), c))
    except (OSError, ValueError):
        return None
    return (domain, points, labels) if domain and domain[2] > domain[0] and domain[3] > domain[1] else None


def panel(domain, points, classes, title, height=150):
    """One SVG panel: `points` of `classes` (all of them: coloured by class) in `domain`."""
    x0, y0, x1, y1 = domain
    w = height * (x1 - x0) / (y1 - y0)
    shown = [p for p in points if p[2] in classes]
    r = max(0.8, min(3.0, 0.35 * height / max(1.0, len(shown)) ** 0.5))
    dots = "".join(f'<circle cx="{(x - x0) / (x1 - x0) * w:.1f}" cy="{(1 - (y - y0) / (y1 - y0)) * height:.1f}" r="{r:.2f}" '
                   f'fill="{COLOURS[c % len(COLOURS)]}"/>' for x, y, c in shown)
    return (f'<div class="panel"><svg width="{w:.0f}" height="{height}" viewBox="0 0 {w:.1f} {height}">'
            f'<rect width="100%" height="100%" fill="#fff" stroke="#999"/>{dots}</svg>'
            f'<div class="ptitle">{html.escape(title)} ({len(shown)})</div></div>')


def class_panels(run_dir):
    """Exemplar and output, all classes and each class on its own, for a multi-class run; ""
    for one class or files not in the plain form."""
    ex, out = read_points(os.path.join(run_dir, "exemplar.txt")), read_points(os.path.join(run_dir, "output.txt"))
    if not ex or not out:
        return ""
    classes = sorted({p[2] for p in ex[1]} | {p[2] for p in out[1]})
    if len(classes) < 2:
        return ""
    labels = ex[2] or out[2]
    rows = []
    for name, (domain, points, _) in (("exemplar", ex), ("output", out)):
        cells = [panel(domain, points, set(classes), f"{name}, all classes")]
        cells += [panel(domain, points, {c}, f"class {labels[c] if c < len(labels) else c}") for c in classes]
        rows.append(f'<div class="classes">{"".join(cells)}</div>')
    return "".join(rows)


def l_panels(m):
    """Per fidelity row with an L distance, an SVG of L(r) - r of exemplar and output up to the
    row's r_max, and the band around the exemplar's: L within band x spread mean spacings of it
    (the fidelity line's test, a sup distance: the output's curve stays inside the grey). From
    the evaluation's second-order curves ("second_order", eval without --no-curves) and its
    fidelity rows; "" when either is missing."""
    rows = ((m.get("second_order") or {}).get("rows")) or []
    fid = ((m.get("scorecard") or {}).get("fidelity") or {}).get("rows") or []
    def key(r):
        return (r.get("row"), r.get("class"), r.get("ci"), r.get("cj"))
    curves = {key(r): r for r in rows if isinstance(r.get("r"), list)}
    cells = []
    for f in fid:
        c, l = curves.get(key(f)), f.get("l")
        if not c or not isinstance(l, dict) or not all(isinstance(v, (int, float)) for v in (f.get("r_max"), f.get("spacing"),
                                                                                           l.get("spread"), l.get("band"))):
            continue
        half = l["band"] * l["spread"] * f["spacing"]  # the band's half-width in L's units
        pts = [(r, e - r, o - r) for r, e, o in zip(c["r"], c["exemplar"]["l"], c["output"]["l"])
               if 0 < r <= f["r_max"] and isinstance(e, (int, float)) and isinstance(o, (int, float))]
        if len(pts) < 2:
            continue
        ys = [v for _, e, o in pts for v in (e - half, e + half, o)]
        lo, hi = min(ys), max(ys)
        hi, lo = hi + 0.05 * (hi - lo or 1), lo - 0.05 * (hi - lo or 1)
        w, h, r1 = 210, 120, pts[-1][0]
        def xy(r, y):
            return f"{r / r1 * w:.1f},{(hi - y) / (hi - lo) * h:.1f}"
        band = " ".join(xy(r, e + half) for r, e, _ in pts) + " " + " ".join(xy(r, e - half) for r, e, _ in reversed(pts))
        zero = f'<line x1="0" x2="{w}" y1="{hi / (hi - lo) * h:.1f}" y2="{hi / (hi - lo) * h:.1f}" stroke="#ccc"/>' if lo < 0 < hi else ""
        within = "within band" if l.get("within") else "out of band"
        title = f"{f.get('name', f.get('row'))}: L {l.get('spreads', float('nan')):.2f} spreads, {within}"
        cells.append(f'<div class="panel"><svg width="{w}" height="{h}" viewBox="0 0 {w} {h}">'
                     f'<rect width="100%" height="100%" fill="#fff" stroke="#999"/>{zero}'
                     f'<polygon points="{band}" fill="#ddd"/>'
                     f'<polyline points="{" ".join(xy(r, e) for r, e, _ in pts)}" fill="none" stroke="#000" stroke-width="1.5"/>'
                     f'<polyline points="{" ".join(xy(r, o) for r, _, o in pts)}" fill="none" stroke="#1f77b4" stroke-width="1.5"/>'
                     f'</svg><div class="ptitle">{html.escape(title)}</div></div>')
    legend = ('<div class="ptitle">L(r) - r up to each row\'s r_max (exemplar units): exemplar (black), output (blue), '
              'the band around the exemplar\'s (grey)</div>')
    return f'<div class="classes">{"".join(cells)}</div>{legend}' if cells else ""


def scorecard_rows(m):
    """The scorecard's lines as the card shows them (docs/explanation/scorecard.md)."""
    sc = m.get("scorecard") or {}
    rows = []
    nov = sc.get("novelty") or {}
    if isinstance(nov.get("share"), (int, float)):
        word = "<b>COPY</b> of the exemplar" if nov.get("copy") else "new"
        rows.append(("novelty", f"{word}: {nov['share']:.3f} of the neighbourhoods copied (a copy from {nov.get('copy_share', '?')})"))
    fid = sc.get("fidelity") or {}
    for r in fid.get("rows", []):
        parts = []
        for key, label in (("l", "L"), ("g", "g"), ("kmm", "k_mm")):
            d = r.get(key)
            if isinstance(d, dict) and isinstance(d.get("spreads"), (int, float)) and isinstance(d.get("band"), (int, float)):
                parts.append(f"{label} {d['spreads']:.2f} (band {d['band']:.2f})")
        if r.get("within") is None:
            word = "cannot judge"
        else:
            word = "within band" if r["within"] else "<b>out of band</b>"
        spreads = f"{', '.join(parts)} spreads; " if parts else ""
        reason = f" ({html.escape(r['reason'])})" if r.get("reason") and not parts else ""
        rows.append((f"fidelity, {r.get('name', r.get('row'))}", f"{spreads}{word}{reason}"))  # the table escapes names
    per = sc.get("periodicity") or {}
    if isinstance(per.get("ratio"), (int, float)):
        word = "<b>PERIODIC</b>" if per.get("periodic") else "no repeat"
        rows.append(("periodicity", f"{word} (ratio {per['ratio']:.3g}, periodic from {per.get('periodic_ratio', '?')})"))
    for r in (sc.get("close_pairs") or {}).get("rows", []):
        if r.get("row") != "all":
            continue
        if isinstance(r.get("share_below"), (int, float)):
            rows.append(("close pairs", f"{r.get('pairs_below', '?')} pairs closer than the exemplar's closest "
                                        f"({r['share_below']:.3f} of the points); normalized min distance "
                                        f"{r.get('output_normalized') or 0:.3f} (exemplar {r.get('exemplar_normalized') or 0:.3f})"))
    return rows


def card(run_dir):
    for need in ("run.json", "exemplar_vs_output.png"):
        if not os.path.exists(os.path.join(run_dir, need)):
            sys.exit(f"gallery: {run_dir}: not a finished run directory of ppsynth (no {need})")
    run = read_json(os.path.join(run_dir, "run.json"))
    metrics_path = os.path.join(run_dir, "metrics.json")
    m = read_json(metrics_path) if os.path.exists(metrics_path) else {}
    with open(os.path.join(run_dir, "exemplar_vs_output.png"), "rb") as f:
        picture = base64.b64encode(f.read()).decode()
    name = run.get("name") or os.path.basename(os.path.normpath(run_dir))
    config_path = os.path.join(run_dir, "config.json")
    method = (read_json(config_path).get("method") or {}).get("type", "?") if os.path.exists(config_path) else "?"
    preset = (run.get("preset") or {}).get("name") if isinstance(run.get("preset"), dict) else run.get("preset")
    defaults = "the paper's settings" if method == "gabor" else "its defaults"
    settings = "quick settings" if run.get("quick") else (f"preset {preset}" if preset else defaults)
    rows = measure_rows(m)
    rows.append(("method", f"{html.escape(method)}, {settings}, seed {run.get('seed', '?')}"))
    threads = run.get("threads", "?")
    rows.append(("time", f"{run.get('total_seconds', 0):.1f} s, {threads} thread{'' if threads == 1 else 's'}, {run.get('processor', '?')}"))
    table = "".join(f"<tr><th>{html.escape(k)}</th><td>{v}</td></tr>" for k, v in rows)
    return (f'<figure><figcaption>{html.escape(name)}</figcaption>'
            f'<img alt="{html.escape(name)}: exemplar and output" src="data:image/png;base64,{picture}">'
            f"{class_panels(run_dir)}{l_panels(m)}<table>{table}</table></figure>")


def measure_rows(m):
    """An evaluation's rows as a card shows them: counts and distances, the scorecard, the verdict."""
    rows = []
    a = m.get("all", {})
    if a:
        counts = f"{m.get('exemplar', {}).get('count', '?')} &rarr; {m.get('output', {}).get('count', '?')} points"
        rows.append(("points", counts))
        for key, label in (("pcf_mse", "PCF MSE"), ("wasserstein", "Wasserstein"), ("chamfer", "Chamfer")):
            if key in a:
                rows.append((label, measure(a, key)))
    rows += scorecard_rows(m)
    # The verdict per row: all points, each class, each pair of classes (a multi-class pattern
    # can pass on all points and fail on a class: the segregation unmarked K cannot see).
    for r in m.get("verdict", {}).get("rows", []):
        row = {"all": "all points", "class": f"class {r.get('class')}", "pair": f"classes {r.get('ci')}-{r.get('cj')}"}
        label = row.get(r.get("row"), str(r.get("row")))
        outcome = r.get("outcome", "cannot judge" if r.get("p") is None else ("pass" if r.get("pass") else "fail"))
        if outcome == "fail" and r.get("p") is None:  # a class missing from the output, or extra in it
            rows.append((f"K test, {label}", "<b>fails</b>: " + html.escape(str(r.get("reason") or "no p"))))
        elif outcome == "cannot judge":
            rows.append((f"K test, {label}", "cannot judge: " + html.escape(str(r.get("reason") or "too few points"))))
        else:
            word = "same K-function" if r.get("pass") else "<b>K-function differs</b>"
            rows.append((f"K test, {label}", f"{word} (p = {r['p']:.3g})"))
    return rows


def pair_card(label, exemplar, output):
    """A card for an output that is a point file, not a run directory (a fitted model's draw, a
    finished run's output.txt): `ppsynth eval` of it against `exemplar` (its scorecard, verdict
    and curves), the two drawn side by side (and class by class), the L curves with their band."""
    for path in (exemplar, output):
        if not os.path.isfile(path):
            sys.exit(f"gallery: --pair {label}: no file {path}")
    p = subprocess.run([BIN, "eval", "-q", "--json", "--exemplar", exemplar, "--output", output], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"gallery: --pair {label}: ppsynth eval failed (exit {p.returncode}):\n{p.stderr.strip()}")
    m = json.loads(p.stdout)
    ex, out = read_points(exemplar), read_points(output)
    if not ex or not out:
        sys.exit(f"gallery: --pair {label}: {exemplar if not ex else output} is not a plain point file of ppsynth")
    classes = sorted({q[2] for q in ex[1]} | {q[2] for q in out[1]})
    labels = ex[2] or out[2]
    pictures = []
    for name, (domain, points, _) in (("exemplar", ex), ("output", out)):
        aspect = (domain[2] - domain[0]) / (domain[3] - domain[1])
        height = int(min(150 if name == "exemplar" else 220, 460 / aspect))  # the card's width
        cells = [panel(domain, points, set(classes), name, height=height)]
        if len(classes) > 1:
            cells += [panel(domain, points, {c}, f"{name}, class {labels[c] if c < len(labels) else c}", height=height // 2)
                      for c in classes]
        pictures.append(f'<div class="classes">{"".join(cells)}</div>')
    rows = measure_rows(m)
    rows.append(("files", f"{html.escape(exemplar)} &rarr; {html.escape(output)}"))
    table = "".join(f"<tr><th>{html.escape(k)}</th><td>{v}</td></tr>" for k, v in rows)
    return (f'<figure><figcaption>{html.escape(label)}</figcaption>{"".join(pictures)}{l_panels(m)}'
            f"<table>{table}</table></figure>")


PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>ppsynth gallery</title>
<style>
body {{ font: 15px/1.4 system-ui, sans-serif; margin: 2em; color: #222; background: #fafafa; }}
h1 {{ font-weight: 600; margin-bottom: 0.2em; }}
p.lead {{ color: #555; max-width: 60em; }}
main {{ display: grid; grid-template-columns: repeat(auto-fill, minmax(520px, 1fr)); gap: 1.5em; }}
figure {{ margin: 0; background: #fff; border: 1px solid #ddd; border-radius: 6px; padding: 1em; }}
figcaption {{ font-weight: 600; font-size: 1.1em; margin-bottom: 0.5em; }}
img {{ width: 100%; height: auto; image-rendering: auto; }}
table {{ border-collapse: collapse; margin-top: 0.5em; font-size: 0.92em; }}
th {{ text-align: left; color: #666; font-weight: normal; padding-right: 1em; vertical-align: top; }}
.classes {{ display: flex; flex-wrap: wrap; gap: 0.5em; margin-top: 0.5em; }}
.ptitle {{ font-size: 0.8em; color: #555; text-align: center; }}
</style></head>
<body>
<h1>ppsynth gallery</h1>
<p class="lead">{what}</p>
<main>
{cards}
</main>
<footer><p class="lead">Made {when} by <code>{command}</code>.</p></footer>
</body></html>
"""


def check_out(out, force):
    """Refuses, before any synthesis, a page that could not be written in the end."""
    if os.path.isdir(out):
        sys.exit(f"gallery: -o {out} is a directory; name the HTML file to write")
    if os.path.lexists(out) and not force:
        sys.exit(f"gallery: {out} exists; --force replaces it")
    folder = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(folder):
        sys.exit(f"gallery: -o {out}: no directory {folder} to write it in")
    if not os.access(folder, os.W_OK):
        sys.exit(f"gallery: -o {out}: the directory {folder} is not writable")


def write_page(page, out):
    """Writes `page` to `out` whole or not at all: the temporary file beside it is removed
    on every way out (a failed rename included)."""
    f = tempfile.NamedTemporaryFile("w", dir=os.path.dirname(os.path.abspath(out)), delete=False, suffix=".partial")
    try:
        with f:
            f.write(page)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(f.name, 0o666 & ~umask)  # as an ordinary new file, not the scratch file's 0600
        os.replace(f.name, out)
    except BaseException:
        if os.path.exists(f.name):
            os.unlink(f.name)
        raise


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--out", required=True, help="the HTML page to write")
    ap.add_argument("--runs", nargs="+", metavar="RUN_DIR", help="finished run directories instead of new syntheses")
    ap.add_argument("--preset", help="synthesize at this preset (e.g. fast) instead of --quick")
    ap.add_argument("--work", help="keep the syntheses in this new directory (default: a scratch directory, removed)")
    ap.add_argument("--threads", type=int, default=0, help="threads per synthesis (default: PPSYNTH_THREADS or every core)")
    ap.add_argument("--pair", nargs=3, action="append", metavar=("LABEL", "EXEMPLAR", "OUTPUT"),
                    help="a card for OUTPUT, a point file, evaluated against EXEMPLAR (repeatable; with or without --runs)")
    ap.add_argument("--force", action="store_true", help="replace an existing page")
    args = ap.parse_args()
    check_out(args.out, args.force)
    if (args.runs or args.pair) and (args.preset or args.work):
        sys.exit("gallery: --runs and --pair show finished outputs; --preset and --work go with new syntheses")
    if args.work and os.path.exists(args.work) and os.listdir(args.work):
        sys.exit(f"gallery: --work {args.work} is not empty")
    if not args.runs and not os.access(BIN, os.X_OK):
        sys.exit(f"gallery: {BIN} not found: build first (scripts/setup.sh) or set PPSYNTH_BIN")

    scratch = None
    # A finished run may have any output size (--size, rectangles); only the shipped configs are 2 x 2.
    runs = ("Each exemplar (left), the points the synthesis started from (middle), and the pattern ppsynth "
            "synthesized from it (right; " + ("each run at its own output size" if args.runs else "2 x 2 the exemplar's area")
            + "). ")
    pairs = ("A point file's card: the exemplar, the output (and each class on its own), per row L(r) - r of both with "
             "the fidelity band around the exemplar's, and <code>ppsynth eval</code>'s scorecard and verdict. ")
    if args.runs or args.pair:
        dirs = args.runs or []
        what = (runs + "Finished runs. " if dirs else "") + (pairs if args.pair else "")
    else:
        work = args.work or (scratch := tempfile.TemporaryDirectory(prefix="ppsynth-gallery-")).name
        dirs = synthesize(base_configs(), work, args.preset, args.threads)
        what = runs + ("At the " + args.preset + " preset." if args.preset else
                "At quick settings (tiny grids, few iterations): they show every exemplar through the "
                "pipeline, not the method's quality; <code>--preset fast</code> or <code>--runs</code> for that.")
    def order(d):  # by exemplar name, then seed
        try:
            r = read_json(os.path.join(d, "run.json"))
            return (str(r.get("name", "")), int(r.get("seed", 0)))
        except (OSError, ValueError):
            return ("", 0)  # card() names what is wrong with it
    cards = "\n".join([card(d) for d in sorted(dirs, key=order)] + [pair_card(*p) for p in args.pair or []])
    command = "scripts/gallery.py " + " ".join(sys.argv[1:])
    page = PAGE.format(what=what, when=datetime.date.today().isoformat(), command=html.escape(command), cards=cards)
    try:
        write_page(page, args.out)
    except OSError as e:
        sys.exit(f"gallery: cannot write {args.out}: {e.strerror or e}")
    if scratch:
        scratch.cleanup()
    print(f"gallery: {len(dirs) + len(args.pair or [])} cards -> {args.out}")


if __name__ == "__main__":
    main()
