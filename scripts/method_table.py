#!/usr/bin/env python3
"""Compares methods (or variants of one method) over bench results, paired by world and seed.

usage: scripts/method_table.py [--reference NAME] [--versus NAME] [--worlds W,...]
                               [--seeds [WORLD=]A-B]... SOURCE...

SOURCE is a bench folder (its results.jsonl), a CSV this script wrote with --csv, or
LABEL=FOLDER: with a label, every record of that folder is shown under LABEL instead of its
method, so that runs of one method under different --config files (scripts/semantic_ablation.py)
can be compared.

--csv FILE writes the episodes the tables are made of, one row each (world, method, seed,
setting, start mode, final rate, whether it timed out or the SLAM diverged, T98, L98, numbers
written exactly): the same command on that file prints the same tables, and a test reruns some
of its episodes to check that the binary still gives them.

Per world, a Markdown table with one row per method:
- success: episodes whose final exploration rate is >= 98 %, of all its episodes;
- ended: episodes the method ended by itself, before the time limit;
- T98, L98: means over the paired episodes, the seeds on which every row reached 98 %;
- L98 / REF: the mean over those seeds of L98 / the reference row's L98 on the same seed;
- beats VERSUS: of the seeds both reached 98 % on, the share where the row's L98 is shorter.
Only noise-free records (options.noise.profile and slam.mode none or absent) fill these
tables. With one --setting NOISE[+SLAM] (e.g. tb3, tb3+graph), the per-world tables are of that
setting's runs instead. With --noisy-table, one table of the --setting runs alone: successes,
ends and mean L98 per world. With --compact, one table: per world the paired mean L98 and its
ratio, then successes and ends over all worlds; each --setting adds a column of the same
methods under that noise profile and SLAM mode: episodes that reached 98 % (and did not
diverge) of all, episodes the method ended by itself, and the mean over the (world, seed)
episodes that succeeded in both of the L98 under noise over the noise-free L98. --wins adds,
per world, the method with the shortest paired mean L98 and on how many seeds it was shorter
than each other method.
"""
import argparse
import csv
import io
import json
import os
import statistics
import sys
from collections import defaultdict
from pathlib import Path


ORDER = ["rrt", "improved_rrt", "mmpf", "topo", "nearest_frontier", "semantic_paper",
         "semantic_sampling_only", "semantic_score_only", "semantic"]


CSV_FIELDS = ["world", "method", "seed", "setting", "start_mode", "exploration_rate", "timed_out",
              "diverged", "t98_s", "l98_m"]


def number(text):
    return None if text == "" else float(text)


def csv_records(path):
    """The records of a CSV written by --csv, with the fields the tables read."""
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != CSV_FIELDS:
            sys.exit(f"method_table: {path}: expected the columns {','.join(CSV_FIELDS)}")
        for n, row in enumerate(reader, 2):
            try:
                noise, _, slam = row["setting"].partition("+")
                yield {
                    "world": row["world"], "method": row["method"], "seed": int(row["seed"]),
                    "start_mode": row["start_mode"],
                    "exploration_rate": float(row["exploration_rate"]),
                    "timed_out": row["timed_out"] == "true",
                    "t98_s": number(row["t98_s"]), "l98_m": number(row["l98_m"]),
                    "options": {"noise": {"profile": noise},
                                "slam": {"mode": slam or "none"}},
                    "slam": {"diverged": row["diverged"] == "true"} if slam else None,
                }
            except (KeyError, ValueError) as e:
                sys.exit(f"method_table: {path}:{n}: bad row ({e})")


def write_csv(path, episodes):
    """Writes the episodes (records) to `path` as CSV, atomically."""
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow(CSV_FIELDS)
    for r in sorted(episodes, key=lambda r: (r["world"], r["method"], r["seed"], setting_of(r))):
        def num(v):
            return "" if v is None else repr(float(v))
        writer.writerow([r["world"], r["method"], r["seed"], setting_of(r),
                         r.get("start_mode", ""), num(r["exploration_rate"]),
                         str(bool(r["timed_out"])).lower(),
                         str(bool((r.get("slam") or {}).get("diverged", False))).lower(),
                         num(r["t98_s"]), num(r["l98_m"])])
    tmp = Path(str(path) + ".tmp")
    tmp.write_text(text.getvalue())
    os.replace(tmp, path)


def records(source):
    label, _, folder = source.rpartition("=")
    path = Path(folder)
    if path.is_dir():
        path = path / "results.jsonl"
    if not path.is_file():
        sys.exit(f"method_table: no results file: {path}")
    if path.suffix == ".csv":
        for r in csv_records(path):
            yield (label or r["method"]), r
        return
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
            yield (label or r["method"]), r


def setting_of(r):
    """'none', or the record's noise profile and SLAM mode, e.g. 'tb3' or 'tb3+graph'."""
    options = r.get("options", {})
    noise = options.get("noise", {}).get("profile", "none")
    slam = options.get("slam", {}).get("mode", "none")
    return "none" if noise == "none" and slam == "none" else f"{noise}+{slam}".replace("+none", "")


def succeeded(r):
    return r["exploration_rate"] >= 0.98 and not (r.get("slam") or {}).get("diverged", False)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sources", nargs="+")
    ap.add_argument("--reference", default="rrt", help="row the L98 ratio is taken to (default rrt)")
    ap.add_argument("--versus", default="semantic", help="row the 'beats' share compares with")
    ap.add_argument("--worlds", help="comma-separated worlds, in this order (default: all)")
    ap.add_argument("--compact", action="store_true",
                    help="one table: a column per world with the paired L98 and its ratio")
    ap.add_argument("--setting", action="append", default=[],
                    help="with --compact: a column of the methods under NOISE[+SLAM]; repeatable")
    ap.add_argument("--noisy-table", action="store_true",
                    help="one table of the --setting runs alone: per method and setting, "
                         "successes and ends of all, and the mean L98 of the successes per world")
    ap.add_argument("--seeds", action="append", default=[],
                    help="only seeds A-B, of every world or (WORLD=A-B) of one; repeatable")
    ap.add_argument("--wins", action="store_true",
                    help="with --compact: per world, the shortest method and its paired wins")
    ap.add_argument("--csv", help="also write the episodes the tables are made of to this CSV")
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
    noisy = defaultdict(dict)  # (setting, world, row) -> seed -> record
    rows = []
    used = []  # the records the tables read, for --csv
    for source in args.sources:
        for row, r in records(source):
            if not wanted(r):
                continue
            used.append(r)
            if row not in rows:
                rows.append(row)
            setting = setting_of(r)
            if setting != "none":
                noisy[(setting, r["world"], row)].setdefault(r["seed"], r)
                continue
            runs[(r["world"], row)].setdefault(r["seed"], r)
    if args.setting and not args.compact and not args.noisy_table:
        # The per-world tables of one noisy setting instead of the noise-free runs.
        runs = defaultdict(dict, {(w, row): eps for (s, w, row), eps in noisy.items()
                                  if s == args.setting[0]})
    rows = [row for row in rows if any(key[1] == row for key in runs)]
    worlds = args.worlds.split(",") if args.worlds else sorted({w for w, _ in runs})
    rows.sort(key=lambda row: ORDER.index(row) if row in ORDER else len(ORDER))
    if args.csv:
        write_csv(args.csv, used)
    if args.compact:
        compact(args, runs, noisy, rows, worlds)
        if args.wins:
            print_wins(args, runs, rows, worlds)
        return
    if args.noisy_table:
        noisy_table(args, noisy, worlds)
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


def noisy_table(args, noisy, worlds):
    """Per method, for each --setting: episodes that succeeded and that ended by themselves, of
    all, and per world the mean L98 over the successful episodes."""
    print("Per setting: episodes that reached 98 % (SLAM not diverged), and that the method "
          "ended by itself before the time limit, of all; per world the mean L98 (m) of the "
          "successful episodes, with their number when not all succeeded.")
    methods = sorted({row for (_, _, row) in noisy},
                     key=lambda row: ORDER.index(row) if row in ORDER else len(ORDER))
    head = "| method |" + "".join(
        f" {s}: success | {s}: ended |" + "".join(f" {s}: L98 {w} |" for w in worlds)
        for s in args.setting)
    print()
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for row in methods:
        cells = [row]
        for setting in args.setting:
            eps = [r for w in worlds for r in noisy.get((setting, w, row), {}).values()]
            if not eps:
                cells += ["–", "–"] + ["–"] * len(worlds)
                continue
            cells.append(f"{sum(succeeded(r) for r in eps)}/{len(eps)}")
            cells.append(f"{sum(not r['timed_out'] for r in eps)}/{len(eps)}")
            for world in worlds:
                world_eps = list(noisy.get((setting, world, row), {}).values())
                ok = [r["l98_m"] for r in world_eps if succeeded(r) and r["l98_m"]]
                cell = f"{statistics.mean(ok):.0f}" if ok else "–"
                if ok and len(ok) < len(world_eps):
                    cell += f" ({len(ok)}/{len(world_eps)})"
                cells.append(cell)
        print("| " + " | ".join(cells) + " |")


def paired_seeds(runs, world, present):
    seeds = set.intersection(*(set(runs[(world, row)]) for row in present))
    return sorted(s for s in seeds
                  if all(runs[(world, row)][s]["l98_m"] is not None for row in present))


def compact(args, runs, noisy, rows, worlds):
    """One table: per world the paired mean L98 and its mean ratio to the reference; success
    over all worlds; per --setting, success, ended and the paired L98 ratio to noise-free."""
    print(f"Per world: L98 (m), the mean over the seeds on which every method reached 98 %, and "
          f"in brackets the mean over those seeds of L98 / {args.reference}'s L98 on the same "
          f"seed. Success: episodes whose final rate is >= 98 %, all worlds. Ended: episodes the "
          f"method ended by itself before the time limit, all worlds." +
          (" Per setting: episodes that succeeded (reached 98 %, SLAM not diverged) and that "
           "ended by themselves, of all; in brackets the mean, over the episodes that succeeded "
           "with and without noise, of L98 under noise / L98 noise-free." if args.setting else ""))
    head = ("| method | " + " | ".join(f"{w}" for w in worlds) + " | success | ended |" +
            "".join(f" {s} |" for s in args.setting))
    print()
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for row in rows:
        cells = [row]
        ok = ended = total = 0
        for world in worlds:
            present = [r for r in rows if (world, r) in runs]
            if row not in present:
                cells.append("–")
                continue
            eps = runs[(world, row)]
            ok += sum(1 for r in eps.values() if r["exploration_rate"] >= 0.98)
            ended += sum(1 for r in eps.values() if not r["timed_out"])
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
        cells.append(f"{ended}/{total}")
        for setting in args.setting:
            ok = ended = total = 0
            ratios = []
            for world in worlds:
                eps = noisy.get((setting, world, row), {})
                clean = runs.get((world, row), {})
                for seed, r in eps.items():
                    total += 1
                    ok += succeeded(r)
                    ended += not r["timed_out"]
                    base = clean.get(seed)
                    if succeeded(r) and base and base["l98_m"] and r["l98_m"]:
                        ratios.append(r["l98_m"] / base["l98_m"])
            ratio = f" ({statistics.mean(ratios):.2f}×)" if ratios else ""
            cells.append(f"{ok}/{total}, ended {ended}{ratio}" if total else "–")
        print("| " + " | ".join(cells) + " |")


def print_wins(args, runs, rows, worlds):
    """Per world: the row with the shortest paired mean L98, and against each other row, on how
    many of the seeds both reached 98 % on its L98 was the shorter."""
    print()
    for world in worlds:
        present = [r for r in rows if (world, r) in runs]
        paired = paired_seeds(runs, world, present)
        if not paired:
            continue
        means = {row: statistics.mean(runs[(world, row)][s]["l98_m"] for s in paired)
                 for row in present}
        best = min(present, key=lambda row: means[row])
        mine = runs[(world, best)]
        counts = []
        for other in sorted((r for r in present if r != best), key=lambda r: means[r]):
            theirs = runs[(world, other)]
            both = [s for s in mine if s in theirs and mine[s]["l98_m"] is not None
                    and theirs[s]["l98_m"] is not None]
            won = sum(1 for s in both if mine[s]["l98_m"] < theirs[s]["l98_m"])
            counts.append(f"`{other}` ({means[other]:.0f} m) on {won} of {len(both)}")
        print(f"- {world}: `{best}` is shortest ({means[best]:.0f} m over {len(paired)} paired "
              f"seeds); shorter than " + ", ".join(counts) + " seeds")


if __name__ == "__main__":
    main()
