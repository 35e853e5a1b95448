#!/usr/bin/env python3
"""How the cost of exploring grows with the building: wall seconds per 1000 m2 explored, and
the room and skeleton update times against the area the map knew.

Usage: scripts/growth_table.py OUT_DIR --worlds small_house,large_office,w.yaml
           [--methods semantic,mmpf] [--repeats 3] [--seed 1] [--binary build/roomscout]
           [--config FILE]

Runs `roomscout explore` once per (world, method, repeat), one at a time (a timing table wants
a quiet machine), into OUT_DIR/<world>/<method>/<repeat>, and reuses a run whose metrics.json
is there already. Prints a Markdown table: per world and method, the reachable area, the
median over repeats of the episode's wall time and of that per 1000 m2, then the median and
p95 update time of the rooms and of the skeleton, over every update and over the updates in
the largest known-area bin (metrics.json: update_ms.<map>.by_known_area; bins double from
250 m2), from the first repeat.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys


def run(binary, world, method, seed, out, config):
    metrics = os.path.join(out, "metrics.json")
    if os.path.exists(metrics):
        with open(metrics) as f:
            return json.load(f)
    cmd = [binary, "explore", "--world", world, "--method", method, "--seed", str(seed),
           "--out", out]
    if config:
        cmd += ["--config", config]
    print("running:", " ".join(cmd), file=sys.stderr, flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(metrics) as f:
        return json.load(f)


def updates(metrics, name):
    u = metrics["update_ms"].get(name)
    if not u:
        return "-", "-"
    whole = "%.1f / %.1f" % (u["median"], u["p95"])
    bins = u.get("by_known_area") or []
    if not bins:
        return whole, "-"
    top = bins[-1]  # [known_max_m2, count, median, p95]
    return whole, "%.1f / %.1f (<= %g m2, %d)" % (top[2], top[3], top[0], top[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--worlds", required=True)
    parser.add_argument("--methods", default="semantic,mmpf")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--binary", default="build/roomscout")
    parser.add_argument("--config")
    args = parser.parse_args()

    print("| world | reachable m2 | method | explored | wall s | wall s per 1000 m2 | "
          "rooms ms, median / p95 | rooms, largest area bin | skeleton ms, median / p95 | "
          "skeleton, largest area bin |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for world in args.worlds.split(","):
        name = os.path.splitext(os.path.basename(world))[0]
        for method in args.methods.split(","):
            runs = [run(args.binary, world, method, args.seed,
                        os.path.join(args.out, name, method, str(r)), args.config)
                    for r in range(args.repeats)]
            area = runs[0]["reachable_area_m2"]
            wall = statistics.median(m["wall_time_s"] for m in runs)
            rooms, rooms_top = updates(runs[0], "semantic")
            skel, skel_top = updates(runs[0], "topological")
            print("| %s | %.0f | %s | %.1f %% | %.1f | %.1f | %s | %s | %s | %s |" % (
                name, area, method, 100 * runs[0]["exploration_rate"], wall,
                1000 * wall / area, rooms, rooms_top, skel, skel_top))


if __name__ == "__main__":
    main()
