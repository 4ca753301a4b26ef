#!/usr/bin/env python3
"""The error laws behind the a-priori mesh rule (scene/mesh_rule.hpp,
docs/validation/accuracy-by-level.md, "The mesh from the band").

Around: the solid's lowest mode of each label (ovalling n, m = 0) against the
harmonic level's (the same r-z section, exact around) on free steel rings and
tubes, at several counts around. Along and through: the harmonic level at
several counts against its own finest (both levels share the section's mesh,
so these errors are the solid's too).

    python3 bench/mesh_rule_errors.py [BINARY] [--only around|along|through]
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BINARY = next((a for a in sys.argv[1:] if not a.startswith("--") and a not in ("around", "along", "through")),
              os.path.join(HERE, "..", "build", "coremodal"))
ONLY = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
STEEL = '{ E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }'


def case(d_in_mm, wall_mm, length_mm, band_hz, wall, around, along, supports="free"):
    return f'''name = "m"
[core]
inner_diameter = "{d_in_mm} mm"
wall = "{wall_mm} mm"
length = "{length_mm} mm"
material = {STEEL}
[supports]
type = "{supports}"
[analysis]
band = ["1 Hz", "{band_hz} Hz"]
[mesh]
through_wall = {wall}
around = {around}
along = {along}
'''


def lowest_per_label(text, model):
    """{(type, n, m): lowest frequency} of a run of `text` at `model`."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "m.toml")
        with open(path, "w") as f:
            f.write(text)
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        subprocess.run([BINARY, "run", path, "-o", os.path.join(d, "out"), "--model", model, "--no-plots", "-q",
                        "--keep-going"], check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        out = {}
        with open(os.path.join(d, "out", "modes.csv")) as f:
            for row in csv.DictReader(f):
                key = (row["type"], int(row["n"]), int(row["m"]))
                hz = float(row["frequency_hz"])
                if key not in out or hz < out[key]:
                    out[key] = hz
        return out


def around():
    print("## around: solid against the harmonic level, ovalling n (m = 0), 2 through the wall")
    print("| tube | R/t | around | n | elements per wave N/n | c = N/(2 pi sqrt(R/t)) | error |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for d_in, wall, length, band in [(980, 20, 50, 1000), (76, 3, 50, 30000), (76, 15, 50, 60000)]:
        r = (d_in + wall) / 2e3
        slenderness = 2 * math.pi * math.sqrt(r / (wall / 1e3))
        exact = lowest_per_label(case(d_in, wall, length, band, 2, 32, 2), "harmonic")
        for n_around in (16, 24, 32, 48, 64):
            solid = lowest_per_label(case(d_in, wall, length, band, 2, n_around, 2), "solid")
            for n in (2, 3, 4, 6):
                key = ("ovalling", n, 0)
                if key in exact and key in solid:
                    e = solid[key] / exact[key] - 1
                    print(f"| {d_in} x {wall} mm | {r / (wall / 1e3):.1f} | {n_around} | {n} | {n_around / n:.1f} | "
                          f"{n_around / slenderness:.2f} | {100 * e:+.3f} % |")
            sys.stdout.flush()


def along():
    print("## along: the harmonic level, 76 x 15 mm steel tube 1.5 m free, 2 through the wall, against 192 along")
    print("| label | along | elements per axial half-wave N/(m+1) | error |")
    print("|---|---:|---:|---:|")
    text = lambda n_along: case(76, 15, 1500, 4000, 2, 16, n_along)
    ref = lowest_per_label(text(192), "harmonic")
    for n_along in (6, 8, 12, 16, 24, 32):
        h = lowest_per_label(text(n_along), "harmonic")
        for key in sorted(ref):
            if key[0] in ("bending", "torsion", "axial", "ovalling") and key in h:
                e = h[key] / ref[key] - 1
                print(f"| {key[0]} n={key[1]} m={key[2]} | {n_along} | {n_along / (key[2] + 1):.1f} | {100 * e:+.4f} % |")
        sys.stdout.flush()


def through():
    print("## through: the harmonic level, against 8 through the wall")
    print("| tube | label | through | error |")
    print("|---|---|---:|---:|")
    for d_in, wall, length, band, along in [(76, 15, 1500, 4000, 48), (980, 20, 50, 1000, 2), (76, 3, 50, 30000, 2)]:
        ref = lowest_per_label(case(d_in, wall, length, band, 8, 16, along), "harmonic")
        for n_wall in (1, 2, 3, 4):
            h = lowest_per_label(case(d_in, wall, length, band, n_wall, 16, along), "harmonic")
            for key in sorted(ref):
                if key in h and key[0] != "rigid":
                    e = h[key] / ref[key] - 1
                    print(f"| {d_in} x {wall} mm | {key[0]} n={key[1]} m={key[2]} | {n_wall} | {100 * e:+.4f} % |")
        sys.stdout.flush()


for name, step in (("around", around), ("along", along), ("through", through)):
    if ONLY in (None, name):
        step()
