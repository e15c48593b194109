#!/usr/bin/env python3
"""The least time a finished run's network arithmetic needs on a CPU of a given conv throughput.

Usage: network_floor.py RUN_DIR GFLOPS WxH [WxH ...]
  RUN_DIR  a finished ppsynth run (run.json's stage records: iterations, sigma, class)
  GFLOPS   the CPU's float32 convolution throughput (`ppsynth doctor`: "convolution ... GFLOP/s")
  WxH      the output grid of each sigma, coarsest first (the plan bench_rectangle.sh prints)

Counts multiply-adds of the random-filter network as configured (config.json's feature_net:
channels, kernel 7, depth 3: conv C->ch and ch->ch at full resolution, then ch->ch at 1/4 and
1/16 of the positions), forward plus the input-gradient backward (the same multiply-adds again),
and a second pass on every stage after the first class and on the revisit (class_own, on by
default). The Gabor maps, the losses, k-NN and Adam are left out, so the run cannot be faster
than this at that throughput.
"""
import json
import sys


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    run_dir, gflops = argv[1], float(argv[2])
    grids = [tuple(int(v) for v in g.split("x")) for g in argv[3:]]
    run = json.load(open(f"{run_dir}/run.json"))
    config = json.load(open(f"{run_dir}/config.json"))
    net = config["method"]["feature_net"]
    ch, k, c_in = net.get("channels", 120), net.get("kernel_size", 7), 10
    weight = config["method"].get("map_terms", {}).get("class_own", {}).get("weight", 1)
    mac_per_position = k * k * (c_in * ch + ch * ch * (1 + 1 / 4 + 1 / 16))
    flop_per_position = 4 * mac_per_position  # forward + input gradient, 2 flops a multiply-add

    sigmas = sorted({s["sigma"] for s in run["method_stats"]["stages"]}, reverse=True)
    if len(sigmas) != len(grids):
        sys.exit(f"{len(sigmas)} sigmas in run.json, {len(grids)} grids given")
    total_flop, total_s = 0.0, 0.0
    print(f"{'stage':<34} {'its':>4} {'grid':>9} {'passes':>6} {'TFLOP':>7} {'floor s':>8} {'ran s':>8}")
    for s in run["method_stats"]["stages"]:
        w, h = grids[sigmas.index(s["sigma"])]
        passes = 2 if weight and (s["class"] > 0 or "revisit" in s["stage"]) else 1
        flop = s["iterations"] * passes * w * h * flop_per_position
        total_flop += flop
        total_s += s["seconds"]
        print(f"{s['stage']:<34} {s['iterations']:>4} {w:>4}x{h:<4} {passes:>6} {flop / 1e12:>7.1f} "
              f"{flop / gflops / 1e9:>8.0f} {s['seconds']:>8.0f}")
    floor = total_flop / gflops / 1e9
    print(f"network: {ch} filters, {mac_per_position * 4 / 1e6:.3f} MFLOP per position and pass")
    print(f"total {total_flop / 1e12:.1f} TFLOP; floor at {gflops:.0f} GFLOP/s: {floor:.0f} s "
          f"({floor / 60:.1f} min); the stages ran {total_s:.0f} s ({total_s / 60:.1f} min), "
          f"{total_s / floor:.2f} x the floor")


if __name__ == "__main__":
    main(sys.argv)
