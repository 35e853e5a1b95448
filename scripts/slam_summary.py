#!/usr/bin/env python3
"""Per world x method, how a method explores under noise and SLAM against itself without.

Reads two results.jsonl files (bench directories or files): the noise-free bench first, the
bench under noise and SLAM second. For each world x method it prints means over the seeds:
the final exploration rate of each, the length driven when the rate first reached a level both
settings reach (default 85 %; L85), the SLAM run's distance when it declared the end, its ATE
and map precision, and the number of diverged runs. A method that never reached the level in
some seed has that cell marked with the count that did.

    scripts/slam_summary.py ideal slam_tb3_icp [--level 0.85]
"""
import argparse
import json
import math
import os
import statistics
import sys

WORLDS = ["small_house", "medium_house", "large_office"]
METHODS = ["rrt", "improved_rrt", "mmpf", "topo", "semantic", "nearest_frontier"]


def load(path):
    if os.path.isdir(path):
        path = os.path.join(path, "results.jsonl")
    records = {}
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                r = json.loads(line)
            except json.JSONDecodeError as e:
                sys.exit(f"{path}:{n}: not JSON: {e}")
            records.setdefault((r["world"], r["method"]), []).append(r)
    return records


def length_at(record, level):
    """Length driven when the rate first reached `level`, or None."""
    columns = record.get("curve_columns", ["time_s", "length_m", "rate"])
    li, ri = columns.index("length_m"), columns.index("rate")
    for row in record.get("curve", []):
        if row[ri] >= level:
            return row[li]
    return None


def mean(values):
    return statistics.fmean(values) if values else math.nan


def cell(values, total):
    if not values:
        return "–"
    text = f"{mean(values):.1f}"
    return text if len(values) == total else f"{text} ({len(values)}/{total})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ideal")
    parser.add_argument("slam")
    parser.add_argument("--level", type=float, default=0.85)
    args = parser.parse_args()
    ideal, slam = load(args.ideal), load(args.slam)
    pct = f"{round(args.level * 100)}"
    print(f"| world | method | rate ideal | rate SLAM | L{pct} ideal (m) | L{pct} SLAM (m) | "
          f"L{pct} ratio | L_done SLAM (m) | ATE (m) | map precision | diverged |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    worlds = [w for w in WORLDS if any(k[0] == w for k in slam)] + sorted(
        {k[0] for k in slam} - set(WORLDS))
    for world in worlds:
        methods = [m for m in METHODS if (world, m) in slam] + sorted(
            {k[1] for k in slam if k[0] == world} - set(METHODS))
        for method in methods:
            a, b = ideal.get((world, method), []), slam[(world, method)]
            la = [x for x in (length_at(r, args.level) for r in a) if x is not None]
            lb = [x for x in (length_at(r, args.level) for r in b) if x is not None]
            ratio = (f"{mean(lb) / mean(la):.2f}" if la and lb and len(lb) == len(b) and len(la) == len(a)
                     else "–")
            done = [r["l_done_m"] for r in b if r.get("l_done_m") is not None]
            ate = [r["slam"]["ate_rmse_m"] for r in b if r.get("slam")]
            precision = [r["map_accuracy"]["occupied_precision"] for r in b if r.get("slam")]
            diverged = sum(1 for r in b if r.get("slam", {}).get("diverged"))
            print(f"| {world} | {method} | {mean([r['exploration_rate'] for r in a]):.3f} | "
                  f"{mean([r['exploration_rate'] for r in b]):.3f} | {cell(la, len(a))} | "
                  f"{cell(lb, len(b))} | {ratio} | {cell(done, len(b))} | {mean(ate):.2f} | "
                  f"{mean(precision):.2f} | {diverged}/{len(b)} |")


if __name__ == "__main__":
    main()
