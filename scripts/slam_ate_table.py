#!/usr/bin/env python3
"""The SLAM's accuracy per setting and world, from bench folders run with SLAM on.

    scripts/slam_ate_table.py exact=out/graph_none tb3=out/graph_tb3 harsh=out/graph_harsh

Each argument is LABEL=DIR, DIR a `roomscout bench` folder (its results.jsonl). Prints a
Markdown table: per setting and world the runs, the ATE of the poses used online and after the
final optimisation (mean and worst over the runs), the runs that diverged, the mean final
exploration rate and the runs that reached 98 %, the SLAM's update time per scan (median of the
runs' medians and p95s), loop closures and wall time per episode.
"""
import json
import os
import statistics
import sys


def load(path):
    if os.path.isdir(path):
        path = os.path.join(path, "results.jsonl")
    records = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                records.append(json.loads(line))
            except json.JSONDecodeError as e:
                sys.exit(f"{path}:{n}: not JSON: {e}")
    return records


def main():
    if len(sys.argv) < 2 or any("=" not in a for a in sys.argv[1:]):
        sys.exit(__doc__)
    print("| setting | world | runs | ATE online mean / worst (m) | ATE final mean / worst (m) "
          "| diverged | rate mean | >= 98 % | update median / p95 (ms) | loop closures | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for arg in sys.argv[1:]:
        label, path = arg.split("=", 1)
        by_world = {}
        for r in load(path):
            if not r.get("slam"):
                sys.exit(f"{path}: a record without a 'slam' block (run with slam.mode set)")
            by_world.setdefault(r["world"], []).append(r)
        for world, runs in by_world.items():
            s = [r["slam"] for r in runs]
            online = [x["ate_rmse_m"] for x in s]
            final = [x.get("ate_final_rmse_m", x["ate_rmse_m"]) for x in s]
            rates = [r["exploration_rate"] for r in runs]
            upd = [r["update_ms"]["slam"] for r in runs]
            print(f"| {label} | {world} | {len(runs)} "
                  f"| {statistics.mean(online):.3f} / {max(online):.3f} "
                  f"| {statistics.mean(final):.3f} / {max(final):.3f} "
                  f"| {sum(1 for x in s if x['diverged'])} "
                  f"| {statistics.mean(rates):.3f} | {sum(1 for v in rates if v >= 0.98)} "
                  f"| {statistics.median(u['median'] for u in upd):.2f} / "
                  f"{statistics.median(u['p95'] for u in upd):.1f} "
                  f"| {statistics.mean(x.get('loop_closures', 0) for x in s):.0f} "
                  f"| {statistics.mean(r['wall_time_s'] for r in runs):.0f} |")


if __name__ == "__main__":
    main()
