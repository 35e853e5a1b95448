#!/usr/bin/env python3
"""Compares two bench result files episode by episode, without their timing fields.

Usage: scripts/compare_records.py A/results.jsonl B/results.jsonl [--ignore-option GROUP.NAME ...]

Timing fields (wall_time_s, recorded_at, host, version, the median and p95 of every update_ms
and map_stats entry) vary with the machine, not the inputs, and are left out, as
experiment::withoutTimingFields() does. Options named with --ignore-option (options added
since A was recorded) are left out of both. Prints one line per episode that differs, with
the first differing keys, and exits 1 if any does.
"""
import argparse
import json
import sys

TIMED = {"update_ms": ("median", "p95", "by_known_area"), "map_stats": ("update_median_ms", "update_p95_ms")}


def load(path):
    records = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            try:
                r = json.loads(line)
            except json.JSONDecodeError:
                continue  # a truncated last line
            records.setdefault((r["world"], r["method"], r["seed"]), r)
    return records


def strip(record, ignored_options):
    r = json.loads(json.dumps(record))
    for key in ("wall_time_s", "recorded_at", "host", "version"):
        r.pop(key, None)
    for group, quantiles in TIMED.items():
        for stats in r.get(group, {}).values():
            if isinstance(stats, dict):
                for q in quantiles:
                    stats.pop(q, None)
    for name in ignored_options:
        group, _, option = name.partition(".")
        r.get("options", {}).get(group, {}).pop(option, None)
    return r


def differences(a, b, path=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                yield f"{path}/{k} only in {'B' if k in b else 'A'}"
            else:
                yield from differences(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{path}/{i}")
    elif a != b:
        yield f"{path}: {json.dumps(a)[:60]} vs {json.dumps(b)[:60]}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--ignore-option", action="append", default=[])
    args = parser.parse_args()
    a, b = load(args.a), load(args.b)
    common = sorted(set(a) & set(b))
    differing = 0
    for key in common:
        diffs = list(differences(strip(a[key], args.ignore_option), strip(b[key], args.ignore_option)))
        if diffs:
            differing += 1
            print(f"{key[0]} {key[1]} seed {key[2]}: {len(diffs)} differences, e.g. " + "; ".join(diffs[:4]))
    only = sorted(set(a) ^ set(b))
    for key in only:
        print(f"{key[0]} {key[1]} seed {key[2]}: only in {'A' if key in a else 'B'}")
    print(f"{len(common)} episodes in both, {differing} differ, {len(only)} in one file only")
    return 1 if differing or only else 0


if __name__ == "__main__":
    sys.exit(main())
