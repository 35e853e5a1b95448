#!/usr/bin/env python3
"""Checks and summarises a soak (scripts/soak.sh): every expected episode has exactly one
record and ended, done or at its time limit; prints per-method figures.

usage: soak_summary.py --methods M1,M2,... BENCH=WORLDS_DIR:SEEDS [...]
  BENCH       a bench folder (its results.jsonl)
  WORLDS_DIR  the folder of map_server YAML files the bench ran (one world per *.yaml)
  SEEDS       seeds 1..SEEDS of every (world, method)
Exits 1 when an episode is missing, recorded twice, or neither done nor timed out.
"""

import argparse
import collections
import json
import pathlib
import statistics
import sys


def read_records(path):
    records = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                records.append(json.loads(line))
            except json.JSONDecodeError as e:
                sys.exit(f"{path}:{n}: not a JSON record: {e}")
    return records


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--methods", required=True)
    ap.add_argument("benches", nargs="+", metavar="BENCH=WORLDS_DIR:SEEDS")
    args = ap.parse_args()
    methods = [m for m in args.methods.split(",") if m]

    problems = []
    rows = collections.defaultdict(list)  # (group, method) -> records
    for spec in args.benches:
        bench, rest = spec.split("=", 1)
        worlds_dir, seeds = rest.rsplit(":", 1)
        worlds = sorted(p.stem for p in pathlib.Path(worlds_dir).glob("*.yaml"))
        expected = {(w, m, s) for w in worlds for m in methods for s in range(1, int(seeds) + 1)}
        results = pathlib.Path(bench) / "results.jsonl"
        if not results.exists():
            problems.append(f"{results}: missing")
            continue
        seen = collections.Counter()
        group = pathlib.Path(bench).name
        for r in read_records(results):
            key = (r["world"], r["method"], r["seed"])
            if key not in expected:
                continue
            seen[key] += 1
            rows[(group, r["method"])].append(r)
            ended = r.get("t_done_s") is not None or r.get("timed_out")
            if not ended:
                problems.append(f"{group}: {key} neither done nor timed out")
        for key in sorted(expected - set(seen)):
            problems.append(f"{group}: {key} has no record")
        for key, n in seen.items():
            if n > 1:
                problems.append(f"{group}: {key} recorded {n} times")

    print("| plans | method | episodes | done | at time limit | rate < 98 % | median rate | "
          "min rate | median wall [s] | max wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for (group, method), rs in sorted(rows.items()):
        rates = [r["exploration_rate"] for r in rs]
        walls = [r["wall_time_s"] for r in rs]
        timed_out = sum(1 for r in rs if r["timed_out"])
        print(f"| {group} | {method} | {len(rs)} | {len(rs) - timed_out} | {timed_out} | "
              f"{sum(1 for x in rates if x < 0.98)} | {100 * statistics.median(rates):.1f} | "
              f"{100 * min(rates):.1f} | {statistics.median(walls):.1f} | {max(walls):.1f} |")
    for group in sorted({g for g, _ in rows}):
        worst = sorted((r for (g, _), rs in rows.items() if g == group for r in rs),
                       key=lambda r: r["exploration_rate"])[:5]
        print(f"\n{group}, lowest exploration rates:")
        for r in worst:
            state = "time limit" if r["timed_out"] else "done"
            print(f"  {r['world']} {r['method']} seed {r['seed']}: "
                  f"{100 * r['exploration_rate']:.1f} % ({state}, {r['sim_time_s']:.0f} s)")
    if problems:
        print(f"\n{len(problems)} problem(s):", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print("\nsoak: every episode recorded once and ended")
    return 0


if __name__ == "__main__":
    sys.exit(main())
