#!/usr/bin/python3
"""The same outputs under two evaluation protocols (issue 20, docs/large_outputs.md "Tiles").

The paper compares the exemplar with the four quadrants of a u = 2 output: windows aligned
with the output's own frame. An output that treats its frame as the exemplar treats its own
(keeps off it, or parks on it) is rewarded there for that, whatever its inside is like.
`ppsynth eval --protocol crops` compares the exemplar with 20 exemplar-sized crops at random
places instead (seeded): the pattern, not its framing. This script evaluates every run's
output both ways against the run's own exemplar and prints, per configuration (a sweep's
group label, as `ppsynth gather` shows it; seeds pooled), the median and quartiles of each
metric, and with --baseline the ratio of each median to the baseline group's with a 90 %
bootstrap interval (resampling the seeds of both groups; 2,000 draws, fixed seed).

    scripts/protocols.py RUN_DIR... [--baseline LABEL] [--json out.json] [--force]
    scripts/protocols.py sweeps/lines_seeds/runs/* sweeps/tiles_default/runs/* --baseline lines

Prints a Markdown table; writes nothing but --json (to a temporary file, renamed; an existing
file is replaced only with --force).
"""
import argparse
import json
import os
import random
import statistics

from run_groups import fail, label, ppsynth, quartiles, write_atomic

METRICS = ("pcf_mse", "wasserstein", "chamfer")
PROTOCOLS = ("quadrants", "crops")


def evaluate(run_dir):
    out = os.path.join(run_dir, "output.txt")
    exemplar = os.path.join(run_dir, "exemplar.txt")
    for path in (out, exemplar, os.path.join(run_dir, "config.json")):
        if not os.path.exists(path):
            fail(f"{run_dir} has no {os.path.basename(path)} (not a finished run?)")
    with open(os.path.join(run_dir, "config.json")) as f:
        config = json.load(f)
    row = {"run": run_dir, "seed": config.get("seed")}
    for protocol in PROTOCOLS:
        ev = json.loads(ppsynth("eval", "--exemplar", exemplar, "--output", out, "--protocol", protocol, "--json", "--no-curves", "-q"))
        for m in METRICS:
            row[f"{protocol}/{m}"] = ev["all"][m]
        row["border_fraction"] = ev["output"]["border_fraction"]
    return label(run_dir, config), row


def ratio_interval(a, b, draws=2000, seed=1):
    """Median of a over median of b, and the 5 % and 95 % points of its bootstrap."""
    rng = random.Random(seed)
    ratios = sorted(statistics.median(rng.choices(a, k=len(a))) / statistics.median(rng.choices(b, k=len(b)))
                    for _ in range(draws))
    return statistics.median(a) / statistics.median(b), ratios[int(0.05 * draws)], ratios[int(0.95 * draws) - 1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--baseline", help="group label the ratios are taken against")
    ap.add_argument("--json", help="also write every run's values and the groups' summaries as JSON")
    ap.add_argument("--force", action="store_true", help="replace the JSON of an earlier call")
    args = ap.parse_args()
    groups = {}
    for d in args.runs:
        name, row = evaluate(d)
        groups.setdefault(name, []).append(row)
    if args.baseline and args.baseline not in groups:
        fail(f"--baseline '{args.baseline}' is none of the groups: {', '.join(groups)}")
    keys = [f"{p}/{m}" for p in PROTOCOLS for m in METRICS] + ["border_fraction"]
    summary = {}
    for name, rows in groups.items():
        summary[name] = {"runs": len(rows), "seeds": sorted(r["seed"] for r in rows)}
        for k in keys:
            summary[name][k] = quartiles([r[k] for r in rows])
            if args.baseline and name != args.baseline and k != "border_fraction":
                summary[name][k + " ratio"] = ratio_interval([r[k] for r in rows], [r[k] for r in groups[args.baseline]])
    titles = {"pcf_mse": "PCF MSE", "wasserstein": "Wasserstein", "chamfer": "Chamfer"}
    head = ["config", "seeds"] + [f"{p}: {titles[m]}" for p in PROTOCOLS for m in METRICS] + ["border_fraction"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for name, s in summary.items():
        cells = [name, ",".join(str(x) for x in s["seeds"])]
        for k in keys:
            q = s[k]
            cell = f"{q[1]:.3g} ({q[0]:.3g}-{q[2]:.3g})"
            if k + " ratio" in s:
                r = s[k + " ratio"]
                cell += f" **{r[0]:.2f} x** ({r[1]:.2f}-{r[2]:.2f})"
            cells.append(cell)
        print("| " + " | ".join(cells) + " |")
    if args.json:
        def dump(tmp):
            with open(tmp, "w") as f:
                json.dump({"groups": summary, "runs": groups, "baseline": args.baseline}, f, indent=1)
        write_atomic(args.json, args.force, dump)


if __name__ == "__main__":
    main()
