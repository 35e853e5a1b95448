#!/usr/bin/env python3
"""Compares methods (or variants of one method) over bench results, paired by world and seed.

usage: scripts/method_table.py [--reference NAME] [--versus NAME] [--worlds W,...]
                               [--seeds [WORLD=]A-B]... SOURCE...

SOURCE is a bench folder (its results.jsonl) or LABEL=FOLDER: with a label, every record of
that folder is shown under LABEL instead of its method, so that runs of one method under
different --config files (scripts/semantic_ablation.py) can be compared.

Per world, a Markdown table with one row per method:
- success: episodes whose final exploration rate is >= 98 %, of all its episodes;
- ended: episodes the method ended by itself, before the time limit;
- T98, L98: means over the paired episodes, the seeds on which every row reached 98 %;
- L98 / REF: the mean over those seeds of L98 / the reference row's L98 on the same seed;
- beats VERSUS: of the seeds both reached 98 % on, the share where the row's L98 is shorter.
Only noise-free records are read (options.noise.profile none or absent).
"""
import argparse
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path


ORDER = ["rrt", "improved_rrt", "mmpf", "topo", "nearest_frontier", "semantic_paper",
         "semantic_sampling_only", "semantic_score_only", "semantic"]


def records(source):
    label, _, folder = source.rpartition("=")
    path = Path(folder)
    if path.is_dir():
        path = path / "results.jsonl"
    if not path.is_file():
        sys.exit(f"method_table: no results file: {path}")
    with path.open() as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                r = json.loads(line)
            except json.JSONDecodeError:
                print(f"method_table: {path}:{n}: not a JSON record, skipped", file=sys.stderr)
                continue
            noise = r.get("options", {}).get("noise", {}).get("profile", "none")
            if noise != "none":
                continue
            yield (label or r["method"]), r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sources", nargs="+")
    ap.add_argument("--reference", default="rrt", help="row the L98 ratio is taken to (default rrt)")
    ap.add_argument("--versus", default="semantic", help="row the 'beats' share compares with")
    ap.add_argument("--worlds", help="comma-separated worlds, in this order (default: all)")
    ap.add_argument("--compact", action="store_true",
                    help="one table: a column per world with the paired L98 and its ratio")
    ap.add_argument("--seeds", action="append", default=[],
                    help="only seeds A-B, of every world or (WORLD=A-B) of one; repeatable")
    args = ap.parse_args()
    ranges = {}
    for spec in args.seeds:
        world, _, span = spec.rpartition("=")
        first, _, last = span.partition("-")
        try:
            ranges[world] = (int(first), int(last or first))
        except ValueError:
            sys.exit(f"method_table: --seeds: expected [WORLD=]A-B, got '{spec}'")

    def wanted(r):
        first, last = ranges.get(r["world"], ranges.get("", (1, 10**9)))
        return first <= r["seed"] <= last

    # (world, row) -> seed -> record; the first record of a key wins, as in `report`.
    runs = defaultdict(dict)
    rows = []
    for source in args.sources:
        for row, r in records(source):
            if not wanted(r):
                continue
            runs[(r["world"], row)].setdefault(r["seed"], r)
            if row not in rows:
                rows.append(row)
    worlds = args.worlds.split(",") if args.worlds else sorted({w for w, _ in runs})
    rows.sort(key=lambda row: ORDER.index(row) if row in ORDER else len(ORDER))
    if args.compact:
        compact(args, runs, rows, worlds)
        return
    print(f"T98 and L98: means over the paired seeds, those on which every row of the world's table "
          f"reached 98 %. L98 / {args.reference}: the mean over those seeds of the row's L98 over "
          f"{args.reference}'s on the same seed. Beats {args.versus}: of the seeds both reached 98 % "
          f"on, those where the row's L98 is shorter. Success: final rate >= 98 %. Ended: the method "
          f"declared the end before the time limit.")

    for world in worlds:
        present = [row for row in rows if (world, row) in runs]
        if not present:
            continue
        seeds = set.intersection(*(set(runs[(world, row)]) for row in present))
        paired = sorted(s for s in seeds
                        if all(runs[(world, row)][s]["l98_m"] is not None for row in present))
        ref = args.reference if args.reference in present else present[0]
        versus = args.versus if args.versus in present else None
        print(f"\n**{world}**, paired seeds: {len(paired)} "
              f"({', '.join(map(str, paired)) or 'none'})" + (f"; ratio to {ref}" if ref != args.reference else ""))
        print()
        head = f"| method | success | ended | T98 (s) | L98 (m) | L98 / {ref} |" + (f" beats {versus} |" if versus else "")
        print(head)
        print("|" + "---|" * (head.count("|") - 1))
        for row in present:
            eps = runs[(world, row)]
            ok = sum(1 for r in eps.values() if r["exploration_rate"] >= 0.98)
            ended = sum(1 for r in eps.values() if not r["timed_out"])
            cells = [row, f"{ok}/{len(eps)}", f"{ended}/{len(eps)}"]
            if paired:
                cells.append(f"{statistics.mean(eps[s]['t98_s'] for s in paired):.0f}")
                cells.append(f"{statistics.mean(eps[s]['l98_m'] for s in paired):.1f}")
                refs = runs[(world, ref)]
                cells.append(f"{statistics.mean(eps[s]['l98_m'] / refs[s]['l98_m'] for s in paired):.3f}")
            else:
                cells += ["–", "–", "–"]
            if versus:
                if row == versus:
                    cells.append("–")
                else:
                    other = runs[(world, versus)]
                    both = [s for s in eps if s in other and eps[s]["l98_m"] is not None
                            and other[s]["l98_m"] is not None]
                    wins = sum(1 for s in both if eps[s]["l98_m"] < other[s]["l98_m"])
                    cells.append(f"{wins}/{len(both)}" if both else "–")
            print("| " + " | ".join(cells) + " |")


def paired_seeds(runs, world, present):
    seeds = set.intersection(*(set(runs[(world, row)]) for row in present))
    return sorted(s for s in seeds
                  if all(runs[(world, row)][s]["l98_m"] is not None for row in present))


def compact(args, runs, rows, worlds):
    """One table: per world the paired mean L98 and its mean ratio to the reference; success
    over all worlds."""
    print(f"Per world: L98 (m), the mean over the seeds on which every method reached 98 %, and "
          f"in brackets the mean over those seeds of L98 / {args.reference}'s L98 on the same "
          f"seed. Success: episodes whose final rate is >= 98 %, all worlds.")
    head = "| method | " + " | ".join(f"{w}" for w in worlds) + " | success |"
    print()
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for row in rows:
        cells = [row]
        ok = total = 0
        for world in worlds:
            present = [r for r in rows if (world, r) in runs]
            if row not in present:
                cells.append("–")
                continue
            eps = runs[(world, row)]
            ok += sum(1 for r in eps.values() if r["exploration_rate"] >= 0.98)
            total += len(eps)
            paired = paired_seeds(runs, world, present)
            ref = args.reference if args.reference in present else present[0]
            if not paired:
                cells.append("–")
                continue
            l98 = statistics.mean(eps[s]["l98_m"] for s in paired)
            ratio = statistics.mean(eps[s]["l98_m"] / runs[(world, ref)][s]["l98_m"] for s in paired)
            cells.append(f"{l98:.0f} ({ratio:.2f})")
        cells.append(f"{ok}/{total}")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
