#!/usr/bin/env python3
"""coremodal's solid level against CalculiX (Debian calculix-ccx) on the same
hex20 mesh (issue 19, bench/results/log.md "Against CalculiX").

For each case: build/coremodal_calculix_deck writes coremodal's own mesh of
the case as a CalculiX deck (C3D20 cells, cylindrically orthotropic
materials, rigid clamps, the case's modes); then `coremodal run` and `ccx`
run alternately, --repeats times each, every process timed whole (wall
clock and peak resident memory of the child, os.wait4). Prints the medians,
their ratio and the largest relative frequency difference (CalculiX prints 7
significant digits, so agreement shows as ~1e-7 at best).

    /usr/bin/python3 bench/calculix_compare.py [--repeats 3] [--threads 2] [--ranks 2] [--mesh coarse]
        [--precisions double,single] CASE.toml...

--precisions runs coremodal once per -factor_precision value in each round
(eigensolve/single_factor.hpp), then ccx: alternating in one sitting; each
row's last column is its largest relative frequency difference to the first
value's run.

--mesh replaces the case's [mesh] by a level (coarse, default, fine); the
default keeps the case's own. ccx runs with OMP_NUM_THREADS = --threads
(its SPOOLES solver's threads); coremodal as a user runs it, in one process
or under `mpirun -n RANKS` (then its memory is the sum over the ranks, from
its summary.json).
"""
import argparse
import json
import os
import pathlib
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORE = ROOT / "build" / "coremodal"
DECK = ROOT / "build" / "coremodal_calculix_deck"


def timed(cmd, cwd, env=None):
    """(wall seconds, peak RSS in GiB, CPU seconds user + system) of one child process; raises on failure.
    The CPU time is what compares on a shared machine, where the wall clock
    depends on the others' load."""
    start = time.perf_counter()
    with open(pathlib.Path(cwd) / "log.txt", "ab") as log:
        p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(map(str, cmd))} failed (see {cwd}/log.txt)")
    return wall, usage.ru_maxrss / 2**20, usage.ru_utime + usage.ru_stime


def case_at_mesh(case, mesh, folder):
    """The case, its [mesh] table replaced by `level = mesh` (or as it is)."""
    text = pathlib.Path(case).read_text()
    if mesh:
        text = re.sub(r"(?ms)^\[mesh\].*?(?=^\[|\Z)", "", text)
        text = text.replace("[analysis]", f'[mesh]\nlevel = "{mesh}"\n\n[analysis]', 1)
    path = pathlib.Path(folder) / pathlib.Path(case).name
    path.write_text(text)
    return path


def ccx_frequencies(dat):
    """The CYCLES/TIME column of CalculiX's eigenvalue table."""
    text = pathlib.Path(dat).read_text()
    table = text.split("E I G E N V A L U E   O U T P U T")[1].split("P A R T I C I P A T I O N")[0]
    return [float(m.group(1)) for m in re.finditer(r"^\s+\d+\s+\S+\s+\S+\s+(\S+)\s+\S+\s*$", table, re.M)]


def coremodal_frequencies(folder):
    summary = json.loads((pathlib.Path(folder) / "summary.json").read_text())
    return [m["frequency_hz"] for m in summary["modes"]], summary


def compare(case, args, work):
    path = case_at_mesh(case, args.mesh, work)
    out = subprocess.run([str(DECK), str(path), str(pathlib.Path(work) / "deck.inp")], check=True,
                         capture_output=True, text=True).stdout.strip()
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    variants = args.precisions.split(",") if args.precisions else [""]
    runs = {v: [] for v in variants}
    runs["ccx"] = []
    # --ranks N: coremodal under mpirun (MUMPS's distributed factor).
    launcher = [] if args.ranks == 1 else ["mpirun", "-n", str(args.ranks)]
    mpi_env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    for r in range(args.repeats):
        for v in variants:  # alternating: each precision, then ccx, in one sitting
            folder = pathlib.Path(work) / f"run{r}{v}"
            options = ["-factor_precision", v] if v else []
            # --model solid: under auto a body of revolution runs at the harmonic level.
            wall, gib, cpu = timed(launcher + [str(CORE), "run", str(path), "-o", str(folder), "--no-plots", "--model",
                                          "solid"] + options, work, mpi_env)
            if launcher:  # mpirun's peak is one rank's: the summary sums them
                gib = json.loads((folder / "summary.json").read_text())["peak_memory_mb"] / 1024
            runs[v].append((wall, gib, cpu))
        runs["ccx"].append(timed(["ccx", "-i", "deck"], work, env))
    theirs = ccx_frequencies(pathlib.Path(work) / "deck.dat")
    first, summary = coremodal_frequencies(pathlib.Path(work) / f"run0{variants[0]}")
    med = {k: (statistics.median(w for w, _, _ in v), max(m for _, m, _ in v), statistics.median(c for _, _, c in v))
           for k, v in runs.items()}
    rows = []
    for v in variants:
        ours, _ = coremodal_frequencies(pathlib.Path(work) / f"run0{v}")
        n = min(len(ours), len(theirs))
        rows.append({"variant": v or "default", "modes": n, "coremodal_s": med[v][0], "coremodal_gib": med[v][1],
                     "coremodal_cpu_s": med[v][2],
                     "max_rel_diff": max(abs(a - b) / b for a, b in zip(ours[:n], theirs[:n])),
                     # against the first variant (e.g. single against double): the precision's own effect
                     "vs_first": max(abs(a - b) / abs(b) for a, b in zip(ours, first) if b)})
    return {"case": pathlib.Path(case).stem, "mesh": args.mesh or "case's", "deck": out,
            "dofs": summary.get("model", {}).get("n_dofs") or summary.get("n_dofs"), "rows": rows,
            "ccx_s": med["ccx"][0], "ccx_gib": med["ccx"][1], "ccx_cpu_s": med["ccx"][2],
            "all_s": {k or "default": [round(w, 2) for w, _, _ in v] for k, v in runs.items()},
            "all_cpu_s": {k or "default": [round(c, 2) for _, _, c in v] for k, v in runs.items()}}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--mesh", default="")
    ap.add_argument("--ranks", type=int, default=1, help="coremodal under mpirun -n RANKS")
    ap.add_argument("--precisions", default="",
                    help="comma-separated -factor_precision values run alternately (e.g. double,single); "
                         "default: coremodal's own choice")
    args = ap.parse_args()
    for tool in (CORE, DECK):
        if not tool.exists():
            sys.exit(f"{tool} is missing: bash scripts/build.sh")
    if shutil.which("ccx") is None:
        sys.exit("ccx is missing: apt-get install calculix-ccx")
    print(f"machine: {platform.node()}, {os.cpu_count()} cores; load before: {os.getloadavg()[0]:.2f}; "
          f"coremodal on {args.ranks} MPI rank(s); OPENBLAS_CORETYPE={os.environ.get('OPENBLAS_CORETYPE', '(unset)')}")
    print("| case | mesh | DOFs | modes | factor | coremodal s | GiB | CalculiX s | GiB | CalculiX / coremodal | "
          "max rel. freq. diff to CalculiX | to the first factor |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for case in args.cases:
        with tempfile.TemporaryDirectory(prefix="ccx-") as work:
            r = compare(case, args, work)
        for row in r["rows"]:
            print(f"| {r['case']} | {r['mesh']} | {r['dofs']} | {row['modes']} | {row['variant']} | "
                  f"{row['coremodal_s']:.1f} | {row['coremodal_gib']:.2f} | {r['ccx_s']:.1f} | {r['ccx_gib']:.2f} | "
                  f"{r['ccx_s'] / row['coremodal_s']:.2f} | {row['max_rel_diff']:.1e} | {row['vs_first']:.1e} |",
                  flush=True)
        print(f"<!-- {r['case']}: wall {r['all_s']}; CPU {r['all_cpu_s']}; deck: {r['deck']} -->", flush=True)
    print(f"load after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
