#!/usr/bin/python3
"""The measurements of large outputs, as one table (docs/lab/large_outputs.md).

For each run directory (a finished `ppsynth synthesize`, large output or u = 2 run): points,
windows, wall time and peak memory (run.json), the PCF MSE, Wasserstein and Chamfer of random
exemplar-sized crops against the exemplar (`ppsynth eval --protocol crops`: median and
quartiles over the crops), border_fraction beside uniform points', and the 2-D power
spectrum's peak ratio with its heat map (`ppsynth spectrum`; tile periods and seams show as
peaks off the ring).

    docs/lab/scripts/large_outputs.py RUN_DIR... [--crops 20] [--spectra DIR] [--json FILE]
    docs/lab/scripts/large_outputs.py runs/lines_1k runs/lines_10k sweeps/lines_seeds/runs/* --spectra docs/lab/results_large_outputs

Run directories of sweeps are accepted as they are. Writes nothing but the spectra (into
--spectra, refusing to replace files it did not make unless --force).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BIN = os.environ.get("PPSYNTH_BIN", os.path.join(HERE, "..", "..", "..", "build", "ppsynth"))


def ppsynth(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"large_outputs: ppsynth {' '.join(args)} failed:\n{r.stderr}")
    return r.stdout


def row(run_dir, crops, spectra, force):
    with open(os.path.join(run_dir, "run.json")) as f:
        run = json.load(f)
    with open(os.path.join(run_dir, "config.json")) as f:
        config = json.load(f)
    output = os.path.join(run_dir, "output.txt")
    if not os.path.exists(output):
        sys.exit(f"large_outputs: {run_dir} has no output.txt (not finished?)")
    ev = json.loads(ppsynth("eval", "--exemplar", os.path.join(run_dir, "exemplar.txt"), "--output", output,
                            "--protocol", "crops", "--crops", str(crops), "--json", "--no-curves", "-q"))
    stats = run.get("method_stats", {})
    windows = stats.get("windows", {})
    name = config.get("name") or os.path.basename(run_dir.rstrip("/"))
    if config.get("preset"):
        name += f" (preset {config['preset']})"
    r = {
        "run": f"{name} seed {config.get('seed')}",
        "dir": run_dir,
        "points": ev["output"]["count"],
        "windows": f"{windows.get('nx', 1)} x {windows.get('ny', 1)}" if windows else "u = %d" % config.get("upscale", 2),
        "seconds": run.get("synthesis_seconds"),
        "threads": run.get("threads"),
        "peak_mib": run.get("peak_rss_mib"),
        "border": ev["output"]["border_fraction"],
        "border_uniform": ev["output"]["border_fraction_uniform"],
    }
    for m in ("pcf_mse", "wasserstein", "chamfer"):
        r[m] = ev["all"][m + "_quartiles"] if m + "_quartiles" in ev["all"] else [ev["all"][m]] * 3
    if spectra:
        os.makedirs(spectra, exist_ok=True)
        stem = os.path.join(spectra, "_".join(filter(None, [config.get("name") or "run", config.get("preset")]))
                            + f"_s{config.get('seed')}_spectrum")
        args = ["spectrum", output, "-o", stem + ".png", "--json", stem + ".json", "-q"]
        if force:
            args.append("--force")
        ppsynth(*args)
        with open(stem + ".json") as f:
            r["peak_ratio"] = json.load(f).get("peak_ratio")
    return r


def fmt_q(q):
    return f"{q[1]:.3g} ({q[0]:.3g}-{q[2]:.3g})"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--crops", type=int, default=20)
    ap.add_argument("--spectra", help="write each output's spectrum heat map and JSON here")
    ap.add_argument("--force", action="store_true", help="replace spectra files of an earlier call")
    ap.add_argument("--json", help="also write the rows as JSON")
    args = ap.parse_args()
    rows = [row(d, args.crops, args.spectra, args.force) for d in args.runs]
    print("| run | points | windows | wall time | threads | peak memory | crop PCF MSE, median (q1-q3) | crop Wasserstein | "
          "crop Chamfer | border_fraction (uniform) |" + (" spectrum peak ratio |" if args.spectra else ""))
    print("|---" * (10 + bool(args.spectra)) + "|")
    for r in rows:
        t = r["seconds"]
        print(f"| {r['run']} | {r['points']:,} | {r['windows']} | {t / 60:.1f} min | {r['threads']} | {r['peak_mib']:.0f} MiB | "
              f"{fmt_q(r['pcf_mse'])} | {fmt_q(r['wasserstein'])} | {fmt_q(r['chamfer'])} | "
              f"{r['border']:.3f} ({r['border_uniform']:.3f}) |" + (f" {r['peak_ratio']:.0f} |" if args.spectra else ""))
    groups = {}
    for r in rows:
        groups.setdefault(r["run"].rsplit(" seed ", 1)[0], []).append(r)
    if any(len(g) > 1 for g in groups.values()):
        print("\nOver seeds (median of the per-run crop medians, min-max):")
        for name, g in groups.items():
            v = [r["pcf_mse"][1] for r in g]
            print(f"  {name}: {len(g)} runs, crop PCF MSE {statistics.median(v):.3g} ({min(v):.3g}-{max(v):.3g})")
    if args.json:
        with tempfile.NamedTemporaryFile("w", dir=os.path.dirname(os.path.abspath(args.json)), delete=False) as f:
            json.dump(rows, f, indent=1)
        os.replace(f.name, args.json)


if __name__ == "__main__":
    main()
