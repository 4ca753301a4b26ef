#!/usr/bin/env python3
"""What bounds the solid level's one factorization (issue 19): MUMPS's LDL^T
of case 03's K - sigma M (181,152 unknowns) under each ordering Debian's
MUMPS and METIS offer, with the MUMPS controls that could speed it up, timed
in one sitting (median of repeats; alternating variants).

    /usr/bin/python3 bench/factor_study/factor_study.py [--repeats 3] [--out bench/results/factor_study.json]

Builds factor_study.c into build/ (installs Debian's libmetis-dev when
missing), writes case 03's K and M with PETSc's -mat_view, then runs every
variant. Prints a markdown table for bench/results/log.md.
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
CASE = ROOT / "cases" / "03-rest-roll-150x15.8-4320.toml"
DRIVER = ROOT / "build" / "factor_study"

# (label, driver options, timed): orderings are compared by their flops
# (analysis only, deterministic); the numeric step is timed where the
# question is speed at PORD's flops.
VARIANTS = [
    ("PORD on 3-unknown nodes (coremodal's)", ["-ordering", "pord"], True),
    ("PORD on unknowns", ["-ordering", "pord", "-compress", "0"], False),
    ("METIS nested dissection (given as the pivot order)", ["-ordering", "metis", "-compress", "0"], True),
    ("AMD", ["-ordering", "amd"], False),
    ("AMF", ["-ordering", "amf"], False),
    ("QAMD", ["-ordering", "qamd"], False),
    ("PORD, no threshold pivoting (CNTL(1) = 0)", ["-ordering", "pord", "-cntl1", "0"], True),
    ("PORD, block low-rank (BLR, eps 1e-12)", ["-ordering", "pord", "-blr", "1e-12"], True),
    ("PORD, K alone as SPD (MUMPS SYM = 1, sigma = 0)", ["-ordering", "pord", "-sym", "1", "-sigma", "0"], True),
]


def build_driver():
    if not pathlib.Path("/usr/include/metis.h").exists():
        subprocess.run(["apt-get", "install", "-y", "libmetis-dev"], check=True, stdout=subprocess.DEVNULL)
    DRIVER.parent.mkdir(exist_ok=True)
    subprocess.run(["mpicc", "-O2", str(HERE / "factor_study.c"), "-o", str(DRIVER), "-I/usr/include/petsc",
                    "-lpetsc_real", "-ldmumps", "-lmumps_common", "-lpord", "-lmetis"], check=True)


def write_matrices(folder):
    """Case 03's K and M (the first two matrices the run assembles) and the
    squared circular frequency of its 12th mode, an interior shift."""
    binary = folder / "matrices.bin"
    subprocess.run([str(ROOT / "build" / "coremodal"), "run", str(CASE), "--model", "solid", "--no-plots", "-q",
                    "-o", str(folder / "run"), "--", "-mat_view", f"binary:{binary}::append"], check=True)
    rows = (folder / "run" / "modes.csv").read_text().splitlines()[1:]
    f12 = float(rows[11].split(",")[1])
    return binary, (2 * 3.141592653589793 * f12) ** 2


def run(binary, sigma, options, analysis_only):
    args = [str(DRIVER), "-f", str(binary), "-sigma", str(sigma)] + options
    if analysis_only:
        args.append("-analysis_only")
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--out", default=str(ROOT / "bench" / "results" / "factor_study.json"))
    args = parser.parse_args()
    build_driver()
    with tempfile.TemporaryDirectory() as tmp:
        binary, sigma = write_matrices(pathlib.Path(tmp))
        results = {label: [] for label, _, _ in VARIANTS}
        for repeat in range(args.repeats):
            for label, options, timed in VARIANTS:
                if not timed and repeat > 0:
                    continue
                r = run(binary, sigma, options, analysis_only=not timed)
                results[label].append(r)
                print(f"[{repeat + 1}/{args.repeats}] {label}: {r['flops']:.3e} flop, numeric {r['numeric_s']:.2f} s",
                      file=sys.stderr, flush=True)
    rows = []
    print("| variant | flop | factor entries | largest front | analysis s | numeric s (median) | GFlop/s | negative pivots |")
    print("|---|---|---|---|---|---|---|---|")
    for label, _, timed in VARIANTS:
        runs = results[label]
        numeric = statistics.median(r["numeric_s"] for r in runs) if timed else None
        first = runs[0]
        rows.append({"variant": label, "runs": runs, "numeric_median_s": numeric})
        rate = f"{first['flops'] / numeric / 1e9:.1f}" if numeric else "—"
        print(f"| {label} | {first['flops']:.3e} | {first['factor_entries']:,} | {first['largest_front']:,} | "
              f"{first['analysis_s'] + first['ordering_s']:.2f} | {f'{numeric:.2f}' if numeric else '—'} | {rate} | "
              f"{first['negative_pivots'] if timed else '—'} |")
    cpu = next((l.split(":", 1)[1].strip() for l in pathlib.Path("/proc/cpuinfo").read_text().splitlines()
                if l.startswith("model name")), "unknown")
    pathlib.Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    pathlib.Path(args.out).write_text(json.dumps({"machine": {"cpu": cpu, "cores": os.cpu_count()},
                                                 "sigma": sigma, "variants": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
