#!/usr/bin/python3
"""A gallery: every shipped exemplar beside a synthesis of it, on one self-contained HTML page.

    scripts/gallery.py -o gallery.html                  # every exemplar of configs/runs, --quick
    scripts/gallery.py -o gallery.html --preset fast    # the same at the fast preset (minutes each)
    scripts/gallery.py -o gallery.html --runs DIR...    # finished run directories (a sweep's runs/*)

Without --runs, it synthesizes each base config of configs/runs (one per shipped exemplar: the
configs whose parent, if any, is a method fragment) into a scratch directory, `--quick` unless
--preset is given (quick settings show the pipeline, not the method's quality). Each card shows
the exemplar beside the output (the run's exemplar_vs_output.png), the point counts, PCF MSE,
Wasserstein and Chamfer distance, spatstat-style verdict where the evaluation has one, and the
settings it ran with. Pictures are embedded, so the page is one file to open or send.

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
    rows = []
    a = m.get("all", {})
    if a:
        counts = f"{m.get('exemplar', {}).get('count', '?')} &rarr; {m.get('output', {}).get('count', '?')} points"
        rows.append(("points", counts))
        for key, label in (("pcf_mse", "PCF MSE"), ("wasserstein", "Wasserstein"), ("chamfer", "Chamfer")):
            if key in a:
                rows.append((label, measure(a, key)))
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
    rows.append(("method", f"{html.escape(method)}, {settings}, seed {run.get('seed', '?')}"))
    threads = run.get("threads", "?")
    rows.append(("time", f"{run.get('total_seconds', 0):.1f} s, {threads} thread{'' if threads == 1 else 's'}, {run.get('processor', '?')}"))
    table = "".join(f"<tr><th>{html.escape(k)}</th><td>{v}</td></tr>" for k, v in rows)
    return (f'<figure><figcaption>{html.escape(name)}</figcaption>'
            f'<img alt="{html.escape(name)}: exemplar and output" src="data:image/png;base64,{picture}">'
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
th {{ text-align: left; color: #666; font-weight: normal; padding-right: 1em; }}
</style></head>
<body>
<h1>ppsynth gallery</h1>
<p class="lead">Each exemplar (left), the points the synthesis started from (middle), and the pattern
ppsynth synthesized from it (right, 2 x 2 the exemplar's area). {what}</p>
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
    ap.add_argument("--force", action="store_true", help="replace an existing page")
    args = ap.parse_args()
    check_out(args.out, args.force)
    if args.runs and (args.preset or args.work):
        sys.exit("gallery: --runs shows finished runs; --preset and --work go with new syntheses")
    if args.work and os.path.exists(args.work) and os.listdir(args.work):
        sys.exit(f"gallery: --work {args.work} is not empty")
    if not args.runs and not os.access(BIN, os.X_OK):
        sys.exit(f"gallery: {BIN} not found: build first (scripts/setup.sh) or set PPSYNTH_BIN")

    scratch = None
    if args.runs:
        dirs = args.runs
        what = "Finished runs."
    else:
        work = args.work or (scratch := tempfile.TemporaryDirectory(prefix="ppsynth-gallery-")).name
        dirs = synthesize(base_configs(), work, args.preset, args.threads)
        what = ("At the " + args.preset + " preset." if args.preset else
                "At quick settings (tiny grids, few iterations): they show every exemplar through the "
                "pipeline, not the method's quality; <code>--preset fast</code> or <code>--runs</code> for that.")
    def order(d):  # by exemplar name, then seed
        try:
            r = read_json(os.path.join(d, "run.json"))
            return (str(r.get("name", "")), int(r.get("seed", 0)))
        except (OSError, ValueError):
            return ("", 0)  # card() names what is wrong with it
    cards = "\n".join(card(d) for d in sorted(dirs, key=order))
    command = "scripts/gallery.py " + " ".join(sys.argv[1:])
    page = PAGE.format(what=what, when=datetime.date.today().isoformat(), command=html.escape(command), cards=cards)
    try:
        write_page(page, args.out)
    except OSError as e:
        sys.exit(f"gallery: cannot write {args.out}: {e.strerror or e}")
    if scratch:
        scratch.cleanup()
    print(f"gallery: {len(dirs)} exemplars -> {args.out}")


if __name__ == "__main__":
    main()
