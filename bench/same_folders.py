#!/usr/bin/env python3
"""Do two sets of results folders (bench/levels_result_set.sh) say the same?

    python3 bench/same_folders.py BEFORE AFTER

For every folder of BEFORE, its namesake in AFTER: every .json (keys of
timing, memory and the program skipped) and .csv compared number by number
to 1e-9 relative, strings exactly; report.md line by line (its timing and
peak-memory lines differ from run to run: read them). Exits 1 on any
difference."""
import json, sys, os, csv, math
SKIP = {"timing_s", "seconds", "solve_seconds", "peak_memory_mb", "program", "wall_s", "elapsed_s", "version", "created", "date", "output", "results"}
def walk(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in set(a) | set(b):
            if k in SKIP or k.endswith("_s") or "time" in k or "memory" in k: continue
            if k not in a or k not in b: out.append(f"{path}/{k}: only in {'after' if k in b else 'before'}"); continue
            walk(a[k], b[k], f"{path}/{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b): out.append(f"{path}: length {len(a)} vs {len(b)}"); return
        for i, (x, y) in enumerate(zip(a, b)): walk(x, y, f"{path}[{i}]", out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if a != b and abs(a - b) > 1e-9 * max(abs(a), abs(b)) + 1e-300: out.append(f"{path}: {a} vs {b}")
    elif a != b:
        out.append(f"{path}: {str(a)[:80]!r} vs {str(b)[:80]!r}")
bad = 0
A, B = sys.argv[1], sys.argv[2]
for name in sorted(os.listdir(A)):
    da, db = os.path.join(A, name), os.path.join(B, name)
    if not os.path.isdir(da): continue
    if not os.path.isdir(db): print(f"{name}: missing after"); bad += 1; continue
    out = []; n = 0
    for f in sorted(os.listdir(da)):
        if f.endswith(".json"):
            n += 1; walk(json.load(open(os.path.join(da, f))), json.load(open(os.path.join(db, f))), f, out)
        elif f.endswith(".csv"):
            n += 1
            ra = list(csv.reader(open(os.path.join(da, f)))); rb = list(csv.reader(open(os.path.join(db, f))))
            if len(ra) != len(rb): out.append(f"{f}: rows {len(ra)} vs {len(rb)}"); continue
            for i,(x,y) in enumerate(zip(ra,rb)):
                for j,(u,v) in enumerate(zip(x,y)):
                    if u == v: continue
                    try:
                        fu, fv = float(u), float(v)
                        if abs(fu-fv) <= 1e-9*max(abs(fu),abs(fv)): continue
                    except ValueError: pass
                    out.append(f"{f}[{i}][{j}]: {u} vs {v}")
        elif f.endswith(".md"):
            n += 1
            if open(os.path.join(da, f)).read() != open(os.path.join(db, f)).read():
                la = open(os.path.join(da, f)).read().splitlines(); lb = open(os.path.join(db, f)).read().splitlines()
                diff = [(x, y) for x, y in zip(la, lb) if x != y]
                out.append(f"{f}: {len(diff)} lines differ, first: {diff[0] if diff else 'length'}")
    print(f"{name}: {n} files, {'OK' if not out else str(len(out)) + ' differences'}")
    for o in out[:8]: print("   ", o)
    bad += bool(out)
sys.exit(1 if bad else 0)
