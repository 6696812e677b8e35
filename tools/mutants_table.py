#!/usr/bin/env python3
"""Tallies cargo-mutants' outcomes per file into docs/tests.md's table.

    python3 tools/mutants_table.py target/mutants-lesson target/mutants-lesson-all ...

Each argument is a --output folder of tools/mutants.sh; later folders (a group's --iterate
--all-tests pass) override earlier ones for the mutants they tried again. Equivalent mutants
are those `cargo mutants --list` names without .cargo/mutants.toml's exclusions but not with
them. Prints one Markdown row per file.
"""
import collections
import json
import subprocess
import sys

outcome = {}
for folder in sys.argv[1:]:
    with open(f"{folder}/mutants.out/outcomes.json") as f:
        for o in json.load(f)["outcomes"]:
            mutant = o["scenario"]
            if isinstance(mutant, dict) and "Mutant" in mutant:
                outcome[mutant["Mutant"]["name"]] = o["summary"]

files = sorted({name.split(":")[0] for name in outcome})


def listed(*extra):
    args = ["cargo", "mutants", "--list", *extra]
    for file in files:
        args += ["--file", file]
    return set(subprocess.run(args, capture_output=True, text=True, check=True).stdout.split("\n")) - {""}


kept = listed()
equivalent = listed("--no-config") - kept
rows = collections.defaultdict(collections.Counter)
for name, summary in outcome.items():
    if name in kept:
        rows[name.split(":")[0]][summary] += 1
for name in equivalent:
    rows[name.split(":")[0]]["equivalent"] += 1

print("| file | mutants | caught | timed out (caught) | missed | equivalent | unviable | score |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for file in files:
    r = rows[file]
    caught, timeout, missed = r["CaughtMutant"], r["Timeout"], r["MissedMutant"]
    viable = caught + timeout + missed
    score = f"{100 * (caught + timeout) / viable:.1f} %" if viable else "–"
    total = viable + r["equivalent"] + r["Unviable"]
    print(f"| `{file}` | {total} | {caught} | {timeout} | {missed} | {r['equivalent']} | {r['Unviable']} | {score} |")
untried = kept - set(outcome)
if untried:
    print(f"\n{len(untried)} mutants not tried:", *sorted(untried), sep="\n", file=sys.stderr)
