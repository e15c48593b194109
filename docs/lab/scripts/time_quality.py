#!/usr/bin/python3
"""The time / quality curve of finished runs (docs/performance.md).

Every run of the Gabor method writes a snapshot of its points at the end of each stage
(snapshots/stageNN.txt) and the seconds of each stage (loss.csv). This script evaluates each
snapshot against the run's exemplar (`ppsynth eval`: the paper's quadrant protocol for a
u = 2 output) and pairs it with the run's time up to that stage's end, so a run gives one
point per stage: the quality a user would have had, had the run stopped there. Runs of the
same configuration (a sweep's group as `ppsynth gather` labels it, else the config name and
preset; seeds pooled) form one curve:
the median over seeds of the time and of each metric at each stage, with the quartiles.

    docs/lab/scripts/time_quality.py RUN_DIR... [-o curve.png] [--json curve.json] [--force]
    docs/lab/scripts/time_quality.py sweeps/lines_seeds/runs/* sweeps/candidates2/runs/* -o docs/results/time_quality/lines.png

Prints a Markdown table. Writes nothing but the plot and --json (each to a temporary file,
renamed; an existing file is replaced only with --force).
"""
import argparse
import csv
import functools
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BIN = os.environ.get("PPSYNTH_BIN", os.path.join(HERE, "..", "..", "..", "build", "ppsynth"))
METRICS = ("pcf_mse", "wasserstein", "chamfer")


def fail(message):
    sys.exit(f"time_quality: {message}")


def ppsynth(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"ppsynth {' '.join(args)} failed:\n{r.stderr}")
    return r.stdout


@functools.lru_cache(maxsize=None)
def sweep_group_labels(sweep):
    """{run dir relative to the sweep: group label} from a sweep's manifest.json (read once per
    sweep); empty for a directory that is not a sweep."""
    manifest = os.path.join(sweep, "manifest.json")
    if not os.path.exists(manifest):
        return {}
    with open(manifest) as f:
        rows = json.load(f).get("rows", [])
    return {row["dir"]: row["group_label"] for row in rows if row.get("dir") and row.get("group_label")}


def label(run_dir, config):
    """The configuration a run belongs to, seeds pooled: a sweep's run takes its group's label
    from the sweep's manifest.json (as `ppsynth gather` shows it: name, preset and grid point);
    another run its config's name and preset."""
    sweep = os.path.dirname(os.path.dirname(os.path.abspath(run_dir)))
    group = sweep_group_labels(sweep).get(os.path.relpath(os.path.abspath(run_dir), sweep))
    if group:
        return group
    text = config.get("name") or "run"
    if config.get("preset"):
        text += f" (preset {config['preset']})"
    return text


def stage_seconds(run_dir):
    """Seconds of each stage, in stage order (loss.csv: the last row of a stage holds its time)."""
    path = os.path.join(run_dir, "loss.csv")
    if not os.path.exists(path):
        fail(f"{run_dir} has no loss.csv (not a finished Gabor run?)")
    last = {}
    with open(path) as f:
        for line_no, rec in enumerate(csv.DictReader(f), start=2):
            try:
                last[int(rec["stage_index"])] = float(rec["seconds"])
            except (KeyError, ValueError):
                fail(f"{path}:{line_no}: malformed row")
    return [last[k] for k in sorted(last)]


def run_points(run_dir):
    with open(os.path.join(run_dir, "config.json")) as f:
        config = json.load(f)
    with open(os.path.join(run_dir, "run.json")) as f:
        run = json.load(f)
    seconds = stage_seconds(run_dir)
    snaps = sorted(p for p in os.listdir(os.path.join(run_dir, "snapshots")) if p.startswith("stage") and p.endswith(".txt"))
    if len(snaps) != len(seconds):
        fail(f"{run_dir}: {len(snaps)} stage snapshots but {len(seconds)} stages in loss.csv")
    # The set-up (targets of every stage) is in the wall time but in no stage: spread it evenly
    # is wrong, so charge it to the start, as the user waits for it before the first iteration.
    setup = max(0.0, run.get("synthesis_seconds", sum(seconds)) - sum(seconds))
    points, t = [], setup
    for snap, s in zip(snaps, seconds):
        t += s
        ev = json.loads(ppsynth("eval", "--exemplar", os.path.join(run_dir, "exemplar.txt"),
                                "--output", os.path.join(run_dir, "snapshots", snap), "--json", "--no-curves", "-q"))
        points.append({"seconds": t, **{m: ev["all"][m] for m in METRICS}})
    return label(run_dir, config), config.get("seed"), points


def quartiles(v):
    if len(v) == 1:
        return v[0], v[0], v[0]
    q = statistics.quantiles(v, n=4, method="inclusive")
    return q[0], statistics.median(v), q[2]


def write_atomic(path, force, write):
    if os.path.exists(path) and not force:
        fail(f"{path} exists; pass --force to replace it")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(path)), suffix=os.path.splitext(path)[1])
    os.close(fd)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


TITLES = {"pcf_mse": "PCF MSE", "wasserstein": "Wasserstein", "chamfer": "Chamfer"}


def plot(curves, path, force):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(METRICS), figsize=(4.6 * len(METRICS), 4.6))
    for name, stages in curves.items():
        xs = [s["seconds"][1] for s in stages]
        # Sweep labels name their grid keys in full; the last part of each key is enough here.
        short = re.sub(r"\b(?:[a-z_]+\.)+([a-z_]+)=", r"\1=", name)
        for ax, m in zip(axes, METRICS):
            med = [s[m][1] for s in stages]
            err = [[s[m][1] - s[m][0] for s in stages], [s[m][2] - s[m][1] for s in stages]]
            ax.errorbar(xs, med, yerr=err, marker="o", capsize=3, label=f"{short} (n={stages[0]['n']})")
    for ax, m in zip(axes, METRICS):
        ax.set_xscale("log")
        ax.set_xlabel("seconds to the stage's end")
        ax.set_title(f"{TITLES.get(m, m)} (lower is better)")
        ax.grid(alpha=0.3)
    fig.suptitle("Quality after each stage against the time to it: median over seeds, bars q1-q3", fontsize=11)
    handles, labels = axes[0].get_legend_handles_labels()
    rows = (len(labels) + 1) // 2
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.06 * rows + 0.02, 1, 0.95))  # the legend's rows below the plots
    write_atomic(path, force, lambda tmp: fig.savefig(tmp, dpi=110))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("-o", "--out", help="plot (PNG, SVG or PDF)")
    ap.add_argument("--json", help="also write the curves as JSON")
    ap.add_argument("--force", action="store_true", help="replace the plot or JSON of an earlier call")
    args = ap.parse_args()
    per_run = {}
    for d in args.runs:
        name, seed, pts = run_points(d)
        per_run.setdefault(name, []).append(pts)
    curves = {}
    for name, runs in per_run.items():
        n_stages = min(len(r) for r in runs)
        if any(len(r) != n_stages for r in runs):
            fail(f"{name}: runs with different stage counts")
        curves[name] = [{"n": len(runs), "seconds": quartiles([r[i]["seconds"] for r in runs]),
                         **{m: quartiles([r[i][m] for r in runs]) for m in METRICS}} for i in range(n_stages)]
    print("| config | runs | stage | seconds, median (q1-q3) | PCF MSE | Wasserstein | Chamfer |")
    print("|---|---|---|---|---|---|---|")
    fmt = lambda q: f"{q[1]:.3g} ({q[0]:.3g}-{q[2]:.3g})"
    for name, stages in curves.items():
        for i, s in enumerate(stages):
            print(f"| {name} | {s['n']} | {i + 1} | {fmt(s['seconds'])} | {fmt(s['pcf_mse'])} | {fmt(s['wasserstein'])} | {fmt(s['chamfer'])} |")
    if args.out:
        plot(curves, args.out, args.force)
    if args.json:
        def dump(tmp):
            with open(tmp, "w") as f:
                json.dump(curves, f, indent=1)
        write_atomic(args.json, args.force, dump)


if __name__ == "__main__":
    main()
