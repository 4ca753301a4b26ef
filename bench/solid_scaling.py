#!/usr/bin/env python3
"""Time and memory of the solid model of case 03 (4.32 m rest roll) at
several mesh sizes: DOFs, mesh, assembly, factor-and-solve and total time
(median of repeated runs) and peak memory, from each run's summary.json.

    /usr/bin/python3 bench/solid_scaling.py [--sizes A,B,C] [--repeats 3] [--out bench/results/solid_scaling.json]
        [--ranks 2] [--options '-mat_mumps_icntl_22 1']

Prints a markdown table to paste into bench/results/log.md. Runs serially, one
case at a time, so that timings are not disturbed by each other.
"""
import argparse
import json
import os
import pathlib
import platform
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BINARY = ROOT / "build" / "coremodal"
CASE = ROOT / "cases" / "03-rest-roll-150x15.8-4320.toml"

# (elements through the core wall, through the rest paper, around, along)
SIZES = {
    "A": (2, 1, 16, 40),     # ~29 k DOFs
    "B": (3, 2, 24, 60),     # ~100 k
    "C": (3, 2, 32, 81),     # ~180 k (the default level)
    "D": (4, 3, 48, 120),    # ~540 k
    "E": (4, 3, 64, 160),    # ~960 k
}


def case_with_mesh(wall, paper, around, along):
    """Case 03 asking for 20 modes, its [mesh] table replaced by explicit counts."""
    text = CASE.read_text()
    text = re.sub(r"(?ms)^\[mesh\].*?(?=^\[|\Z)", "", text)
    text = re.sub(r"(?m)^modes\s*=.*$", "modes = 20   # the issue's benchmark: first 20 modes", text)
    return text + (f"\n[mesh]\nthrough_wall = {wall}\nthrough_rest_paper = {paper}\n"
                   f"around = {around}\nalong = {along}\n")


def run_once(case_path, out_dir, ranks, options):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    launcher = [] if ranks == 1 else ["mpirun", "-n", str(ranks)]
    subprocess.run(launcher + [str(BINARY), "run", str(case_path), "--output", str(out_dir), "--quiet"] + options,
                   check=True, env=env)
    return json.loads((out_dir / "summary.json").read_text())


def machine():
    cpu = "unknown"
    for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    mem_kb = int(re.search(r"MemTotal:\s+(\d+)", pathlib.Path("/proc/meminfo").read_text()).group(1))
    return f"{cpu}, {os.cpu_count()} cores, {mem_kb / 2**20:.0f} GiB, {platform.platform()}"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", default="A,B,C,D")
    p.add_argument("--repeats", type=int, default=3, help="runs per size (median reported)")
    p.add_argument("--max-repeat-dofs", type=int, default=300_000,
                   help="larger models run once (a single run is minutes long)")
    p.add_argument("--out", default=str(ROOT / "bench" / "results" / "solid_scaling.json"))
    p.add_argument("--ranks", type=int, default=1, help="run under mpirun -n RANKS")
    p.add_argument("--options", default="",
                   help="PETSc options for every run, e.g. '-mat_mumps_icntl_22 1' (MUMPS's factor out of core)")
    args = p.parse_args()
    if not BINARY.exists():
        sys.exit(f"{BINARY} not found: build first (bash scripts/build.sh)")

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for name in args.sizes.split(","):
            case = tmp / f"case_{name}.toml"
            case.write_text(case_with_mesh(*SIZES[name]))
            runs = []
            for k in range(args.repeats):
                s = run_once(case, tmp / f"out_{name}_{k}", args.ranks, args.options.split())
                runs.append(s)
                print(f"size {name}: {s['model']['n_dofs']} DOFs, run {k + 1}: {s['timing_s']['total']:.1f} s",
                      file=sys.stderr, flush=True)
                if s["model"]["n_dofs"] > args.max_repeat_dofs:
                    break
            med = {key: statistics.median(r["timing_s"][key] for r in runs)
                   for key in ("mesh", "assemble", "factor_and_solve", "total")}
            rows.append({
                "size": name, "mesh": SIZES[name], "n_dofs": runs[0]["model"]["n_dofs"],
                "n_modes": len(runs[0]["modes"]), "runs": len(runs), "median_s": med,
                "peak_memory_mb": max(r["peak_memory_mb"] for r in runs),
                "f1_hz": runs[0]["beam"]["fe_first_bending_hz"],
            })
    result = {"machine": machine(), "case": str(CASE.relative_to(ROOT)), "ranks": args.ranks,
              "options": args.options, "rows": rows}
    out = pathlib.Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n")

    print(f"Machine: {result['machine']}; {args.ranks} MPI rank(s); options: {args.options or '(none)'}\n")
    print("| size | wall/paper/around/along | DOFs | runs | mesh [s] | assemble [s] | factor+solve [s] | total [s] | peak memory [MiB] | f1 [Hz] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        m = r["median_s"]
        print(f"| {r['size']} | {'/'.join(map(str, r['mesh']))} | {r['n_dofs']:,} | {r['runs']} | {m['mesh']:.2f} | "
              f"{m['assemble']:.2f} | {m['factor_and_solve']:.1f} | {m['total']:.1f} | {r['peak_memory_mb']:.0f} | "
              f"{r['f1_hz']:.4f} |")


if __name__ == "__main__":
    main()
