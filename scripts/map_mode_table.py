#!/usr/bin/env python3
"""Table of T98, L98 and success per world and method for two bench runs side by side.

Usage: scripts/map_mode_table.py FIXED/results.jsonl GROWING/results.jsonl [--names fixed,growing]

Made for comparing `episode.map_mode: fixed` with `growing` (docs/explorer.md) but takes any
two runs of the same episodes. T98 and L98 are means over the episodes that reached 98 %;
success counts episodes whose final rate is at least 98 %; the ratio is B's mean over A's.
"""
import argparse
import json
import statistics
from collections import defaultdict

ORDER = ["rrt", "improved_rrt", "mmpf", "topo", "semantic", "nearest_frontier", "semantic_sampling_only",
         "semantic_score_only"]


def load(path):
    groups = defaultdict(list)
    seen = set()
    with open(path) as f:
        for line in f:
            try:
                r = json.loads(line)
            except json.JSONDecodeError:
                continue
            key = (r["world"], r["method"], r["seed"])
            if key in seen:
                continue
            seen.add(key)
            groups[(r["world"], r["method"])].append(r)
    return groups


def summary(records):
    reached = [r for r in records if r["t98_s"] is not None]
    mean = lambda k: statistics.mean(r[k] for r in reached) if reached else float("nan")
    ok = sum(r["exploration_rate"] >= 0.98 for r in records)
    return mean("t98_s"), mean("l98_m"), f"{ok}/{len(records)}", min(r["exploration_rate"] for r in records)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--names", default="fixed,growing")
    args = p.parse_args()
    na, nb = args.names.split(",")
    a, b = load(args.a), load(args.b)
    print(f"| world | method | T98 {na} [s] | T98 {nb} [s] | L98 {na} [m] | L98 {nb} [m] | L98 {nb}/{na} "
          f"| success {na} | success {nb} | lowest final rate {nb} |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    worlds = sorted({w for w, _ in a} | {w for w, _ in b}, key=lambda w: ["small_house", "medium_house",
                                                                        "large_office"].index(w)
                    if w in ("small_house", "medium_house", "large_office") else 9)
    for w in worlds:
        methods = sorted({m for ww, m in a if ww == w} | {m for ww, m in b if ww == w},
                         key=lambda m: ORDER.index(m) if m in ORDER else 99)
        for m in methods:
            if (w, m) not in a or (w, m) not in b:
                continue
            ta, la, sa, _ = summary(a[(w, m)])
            tb, lb, sb, low = summary(b[(w, m)])
            print(f"| {w} | {m} | {ta:.0f} | {tb:.0f} | {la:.1f} | {lb:.1f} | {lb / la:.3f} | {sa} | {sb} | "
                  f"{100 * low:.1f} % |")


if __name__ == "__main__":
    main()
