#!/usr/bin/env python3
"""The issue's study benchmark: a 50-point study of the 4.32 m rest roll
(150.5x15.8 core, Ilomäki's rotogravure example) must finish in under 10
minutes on 2 cores.

    /usr/bin/python3 bench/study_benchmark.py [--supports clamped|chucks] [--model solid|harmonic] [--jobs N] [--mesh coarse] [--out bench/results/study_50.json]

The study: rest paper thickness 5 to 50 mm (10 values) x Li 150 to 350 mm
(5 values), the study defaults otherwise (coarse mesh, 12 modes), plots
included. With --supports chucks (the issue's scene) each end has an elastic
steel chuck inserted 400 mm whose expanding element (100 mm wide) is centred
at Li; with --supports clamped, rigid clamps 100 mm long centred at Li. Prints the wall time, the CPU time (user + system of the study process and
its children: a check on a machine shared with other work), the time per point
and a markdown row for bench/results/log.md.
"""
import argparse
import csv
import json
import os
import pathlib
import platform
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
BINARY = ROOT / "build" / "coremodal"
LIMIT_S = 600  # the target: under 10 minutes

BASE = """name = "bench-study-4320-{supports}"
model = "{model}"

[core]
inner_diameter = "150.5 mm"
wall = "15.8 mm"
length = "4.32 m"
material = "paperboard_core"

[rest_paper]
thickness = "10 mm"
material = "rest_paper"
"""

CLAMPED = """
[supports]
type = "clamped"

[supports.left]            # the right end mirrors it
length = "100 mm"
center = "250 mm"
"""

CHUCKS = """
[supports]
type = "chucks"

[supports.left]            # the right end mirrors it
inserted_length = "400 mm"

[[supports.left.expanding]]
center = "250 mm"
width = "100 mm"
"""

STUDY = """
[study]
parameters = [
  {{ key = "rest_paper.thickness", from = "5 mm", to = "50 mm", steps = 10 }},
  {{ key = "{li_key}", from = "150 mm", to = "350 mm", steps = 5 }},
]
{mesh}"""


def case_text(supports, mesh, model):
    li_key = "supports.left.center" if supports == "clamped" else "supports.left.expanding.1.center"
    mesh_line = f'mesh = "{mesh}"\n' if mesh else ""
    return (BASE.format(supports=supports, model=model) + (CLAMPED if supports == "clamped" else CHUCKS) +
            STUDY.format(li_key=li_key, mesh=mesh_line))


def machine():
    cpu = "unknown"
    for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    mem_kb = int(re.search(r"MemTotal:\s+(\d+)", pathlib.Path("/proc/meminfo").read_text()).group(1))
    return f"{cpu}, {os.cpu_count()} cores, {mem_kb / 2**20:.0f} GiB, {platform.platform()}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--supports", choices=["clamped", "chucks"], default="clamped")
    parser.add_argument("--jobs", type=int, default=0, help="coremodal study --jobs (default: the study's, the cores)")
    parser.add_argument("--model", choices=["solid", "harmonic"], default="solid",
                        help="model level of every point (harmonic: the scene is axisymmetric)")
    parser.add_argument("--mesh", default="", help="[study] mesh level (default: the study default, coarse)")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "bench" / "results" / "study_50.json")
    args = parser.parse_args()

    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as tmp:
        case = pathlib.Path(tmp) / "bench-study.toml"
        case.write_text(case_text(args.supports, args.mesh, args.model))
        out = pathlib.Path(tmp) / "study"
        load_before = os.getloadavg()
        start = time.monotonic()
        command = [str(BINARY), "study", str(case), "--output", str(out)]
        if args.jobs:
            command += ["--jobs", str(args.jobs)]
        run = subprocess.run(command, env=env, capture_output=True, text=True)
        wall = time.monotonic() - start
        load_after = os.getloadavg()
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = usage.ru_utime + usage.ru_stime  # the study and its python plots: less disturbed by other load
        if run.returncode != 0:
            sys.stderr.write(run.stdout + run.stderr)
            sys.exit(f"the study failed with status {run.returncode}")
        meta = json.loads((out / "study.json").read_text())
        with (out / "study.csv").open(newline="") as f:
            rows = list(csv.DictReader(f))
        times = {r["point"]: float(r["time_s"]) for r in rows}
        f1 = {r["point"]: float(r["f1_hz"]) for r in rows if r["f1_hz"]}
        dofs = [int(r["n_dofs"]) for r in rows if r["n_dofs"]]
    result = {
        "machine": machine(),
        "supports": args.supports,
        "model": args.model,
        "jobs": args.jobs or "default (cores)",
        "points": meta["n_points"],
        "failed": meta["n_failed"],
        "wall_s": wall,
        "study_time_s": meta["time_s"],
        "cpu_s": cpu,
        "point_time_median_s": statistics.median(times.values()),
        "point_time_max_s": max(times.values()),
        "f1_range_hz": [min(f1.values()), max(f1.values())],
        "dofs_range": [min(dofs), max(dofs)],
        "load_average_before_after": [load_before, load_after],
        "under_limit": wall < LIMIT_S,
        "options": meta["options"],
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    print(f"\n| {args.supports} ({args.model}) | {args.jobs or 'cores'} | {meta['n_points']} | {meta['options']['mesh']} | {meta['options']['modes']} | "
          f"{min(dofs):,}-{max(dofs):,} | {wall:.0f} s ({wall / 60:.1f} min) | {result['point_time_median_s']:.1f} s | "
          f"{result['point_time_max_s']:.1f} s | {'yes' if result['under_limit'] else 'NO'} |")


if __name__ == "__main__":
    main()
