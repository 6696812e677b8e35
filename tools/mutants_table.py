#!/usr/bin/env python3
"""Tallies cargo-mutants' outcomes per file into docs/tests.md's table.

    python3 tools/mutants_table.py FIRST_PASS AGAIN[,AGAIN...] [FIRST_PASS AGAIN ...]

FIRST_PASS is a --output folder of `tools/mutants.sh GROUP`; AGAIN the folder of a later run
of the same group that tried its missed mutants again once tests were added (`--iterate`, or
`-F` naming them). Lines move as code and tests are added, so mutants are matched by file,
function and change, without line and column. A first-pass miss counts as caught if tried
again and caught, as equivalent if .cargo/mutants.toml now excludes it, and as missed
otherwise. Prints one Markdown row per file.
"""
import collections
import json
import re
import subprocess
import sys


def outcomes(folder):
    with open(f"{folder}/mutants.out/outcomes.json") as f:
        for o in json.load(f)["outcomes"]:
            scenario = o["scenario"]
            if isinstance(scenario, dict) and "Mutant" in scenario:
                yield scenario["Mutant"]["name"], o["summary"]


def unplaced(name):
    return re.sub(r":\d+:\d+:", ":", name)


def listed(files, *extra):
    args = ["cargo", "mutants", "--list", *extra] + [a for f in files for a in ("--file", f)]
    names = subprocess.run(args, capture_output=True, text=True, check=True).stdout.split("\n")
    return collections.Counter(n for n in names if n)


def unplaced_counts(names):
    return collections.Counter(unplaced(n) for n in names.elements())


first_passes = [list(outcomes(first)) for first in sys.argv[1::2]]
files = sorted({name.split(":")[0] for run in first_passes for name, _ in run})
every, kept = listed(files, "--no-config"), listed(files)
# A mutant whose line has not moved is equivalent if its own name is excluded; one whose line
# moved is matched by file, function and change (two alike in one function are told apart
# only by their place, so their own names decide wherever they still exist).
excluded = every - kept
equivalent = unplaced_counts(excluded)
rows = collections.defaultdict(collections.Counter)
for run, again in zip(first_passes, sys.argv[2::2]):
    retried = collections.defaultdict(list)
    for folder in again.split(","):  # a later folder's outcome is used first
        for name, summary in outcomes(folder):
            retried[unplaced(name)].append(summary)
    for name, summary in run:
        if summary == "MissedMutant":
            if name in every:
                is_equivalent = name in excluded
            else:
                is_equivalent = equivalent[unplaced(name)] > 0
                equivalent[unplaced(name)] -= is_equivalent
            if is_equivalent:
                summary = "equivalent"
            elif retried[unplaced(name)]:
                summary = retried[unplaced(name)].pop()
        rows[name.split(":")[0]][summary] += 1

print("| file | mutants | caught | timed out (caught) | missed | equivalent | unviable | score |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for file in files:
    r = rows[file]
    total = sum(r.values())
    caught, timeout, unviable = r["CaughtMutant"], r["Timeout"], r["Unviable"]
    missed = r["MissedMutant"]
    print(f"| `{file}` | {total} | {caught} | {timeout} | {missed} | {r['equivalent']} | {unviable} | "
          f"{100 * (caught + timeout) / (caught + timeout + missed):.1f} % |")
