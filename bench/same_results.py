#!/usr/bin/env python3
"""Do two coremodal programs give the same frequencies on every shipped case?

    /usr/bin/python3 bench/same_results.py OLD_BINARY NEW_BINARY [--mesh coarse] [--model solid] [--cases GLOB ...]

Runs each case file of cases/ and cases/hard/ (not the [study] and [winder] cases) with both
programs (`run CASE --no-plots -q -o DIR`), reads the modes' frequencies from both
(summary.json at full precision, else modes.csv; a
spinning scene: campbell.csv; a forced response: response.csv and peaks.csv), and
prints one row per case: the number of values, the largest relative
difference over those that are not rigid modes, and OK when it is at most
--tolerance (default 1e-10). Exits 1 if any case differs or fails in one
program and not the other. A refactoring that must keep every result (issue
12) records this table in its note.
"""
import argparse
import csv
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run(binary, case, out, mesh, model=None):
    args = [binary, "run", case, "--no-plots", "-q", "-o", out]
    if mesh:
        args += ["--mesh", mesh]
    if model:
        args += ["--model", model]
    start = time.time()
    p = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
    return p.returncode, p.stderr.strip().splitlines()[-1:] , time.time() - start


def rows(folder, name):
    with open(os.path.join(folder, name), newline="") as f:
        return list(csv.DictReader(f))


def frequencies(folder):
    """The numbers a run wrote, each with its kind ("rigid" ones are not compared):
    the modes (modes.csv); a spinning scene's modes at its speeds (campbell.csv);
    a forced response's amplitudes and its peaks (response.csv, peaks.csv)."""
    if os.path.exists(os.path.join(folder, "modes.csv")):
        # summary.json's at full precision: modes.csv prints 10 digits, where a last-digit flip is 1e-10
        modes = json.load(open(os.path.join(folder, "summary.json"))).get("modes") or []
        if modes and all("frequency_hz" in m for m in modes):
            return [(float(m["frequency_hz"]), m.get("type", "")) for m in modes]
        return [(float(r["frequency_hz"]), r["type"]) for r in rows(folder, "modes.csv")]
    if os.path.exists(os.path.join(folder, "campbell.csv")):
        return [(float(r["frequency_hz"]), "rigid" if float(r["frequency_hz"]) == 0 else "")
                for r in rows(folder, "campbell.csv")]
    values = [(float(r["amplitude_mm"]), "") for r in rows(folder, "response.csv")]
    for r in rows(folder, "peaks.csv"):
        values += [(float(r["web_speed_m_s"]), ""), (float(r["amplitude_mm"]), "")]
    return values


def compare(old, new):
    if len(old) != len(new):
        return None
    worst = 0.0
    for (fa, ta), (fb, tb) in zip(old, new):
        if ta == "rigid" and tb == "rigid":
            continue  # ~1e-5 Hz values, round-off of zero
        worst = max(worst, abs(fa - fb) / max(abs(fa), 1e-300))
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--mesh", default=None, help="mesh level for both (default: each case's own)")
    ap.add_argument("--model", default=None, help="model level for both (default: each case's own)")
    ap.add_argument("--tolerance", type=float, default=1e-10)
    ap.add_argument("--cases", nargs="*", default=None, help="case files (default: cases/*.toml and cases/hard/*.toml)")
    a = ap.parse_args()
    cases = a.cases or sorted(glob.glob(os.path.join(ROOT, "cases", "*.toml")) +
                              glob.glob(os.path.join(ROOT, "cases", "hard", "*.toml")))
    bad = 0
    print(f"| case | values | max relative difference | |\n|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for i, case in enumerate(cases):
            name = os.path.relpath(case, ROOT)
            text = open(case).read()
            if re.search(r"^\[(study|winder)\]", text, re.M):  # not `coremodal run` cases (a table, not a comment)
                continue
            outs = [os.path.join(tmp, f"{i}-old"), os.path.join(tmp, f"{i}-new")]
            results = [run(b, case, o, a.mesh, a.model) for b, o in zip((a.old, a.new), outs)]
            codes = [r[0] for r in results]
            if codes[0] != 0 or codes[1] != 0:
                same = codes[0] == codes[1]
                bad += 0 if same else 1
                print(f"| {name} | - | exit {codes[0]} / {codes[1]} | {'same failure' if same else 'DIFFERS'} |")
                continue
            old, new = frequencies(outs[0]), frequencies(outs[1])
            worst = compare(old, new)
            ok = worst is not None and worst <= a.tolerance
            bad += 0 if ok else 1
            shown = "different mode counts" if worst is None else f"{worst:.1e}"
            print(f"| {name} | {len(new)} | {shown} | {'OK' if ok else 'DIFFERS'} |", flush=True)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
