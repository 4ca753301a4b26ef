"""One scheme for every command's JSON (docs/reference/results.md, "summary.json"):
every shipped case in cases/ is run with its own command and what it writes
is validated against the published JSON Schema,
docs/schemas/summary.schema.json (draft 2020-12); so are `beam --json`,
`converge` and a study. Broken summaries (a key of schema_version 1, a safe
speed row without its m/min, no timing) must fail it.

Cheap settings keep this fast; they change how finely the case is solved,
not which keys its summary has: the beam model level for the solid cases
(the solid and harmonic levels write the same keys: a coarse solid run of
case 01 checks that), the variants of CHEAP_EDITS (a short roll-diameter
sweep for the winder, case 09's contact as a uniform layer), a three-level
beam ladder for converge.

Set COREMODAL_SCHEMA_ALL_LEVELS=1 to run every shipped case at its own
model level and mesh instead (minutes; what a release is checked with).

Needs COREMODAL_BIN (the program) and the jsonschema package (Debian
python3-jsonschema); skipped without either.
"""

from __future__ import annotations

import copy
import json
import os
import re
import subprocess
import tomllib
from pathlib import Path

import pytest

jsonschema = pytest.importorskip(
    "jsonschema", reason="the jsonschema package is missing: apt-get install python3-jsonschema")

REPO = Path(__file__).resolve().parents[2]
SCHEMA = REPO / "docs" / "schemas" / "summary.schema.json"
ALL_LEVELS = os.environ.get("COREMODAL_SCHEMA_ALL_LEVELS") == "1"
TIMEOUT_S = 3600 if ALL_LEVELS else 300


def binary() -> str:
    path = os.environ.get("COREMODAL_BIN")
    if not path:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    return path


@pytest.fixture(scope="module")
def validator():
    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def errors(validator, document: dict) -> list[str]:
    return [f"{'/'.join(map(str, e.absolute_path)) or '(top)'}: {e.message}" for e in validator.iter_errors(document)]


def run(args: list[str], cwd: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    done = subprocess.run([binary(), *args], cwd=cwd, capture_output=True, text=True, env=env, timeout=TIMEOUT_S)
    assert done.returncode == 0, f"coremodal {' '.join(args)}: exit {done.returncode}\n{done.stdout}\n{done.stderr}"
    return done


def command_of(case: dict) -> str:
    """The command a case file is made for: its tables say it."""
    if "selection" in case:
        return "select"
    if "traction" in case and "core" not in case:
        return "traction"
    if "limits" in case:
        return "limits"
    if "winder" in case:
        return "winder"
    if "study" in case:
        return "study"
    if "response" in case:
        return "response"
    if "rotation" in case:
        return "campbell"
    return "run"


#: `coremodal fit` measurements beside a case: no summary.json (fit.toml;
#: their schema is tested in test_winder_fit_schema.py).
FIT_FILES = {"16-limits-measured-f1.toml"}


def shipped_cases() -> list[Path]:
    """Every case file: the TOML cases and the durability data (CSV)."""
    cases = [c for c in (REPO / "cases").glob("*.toml") if c.name not in FIT_FILES]
    return sorted([*cases, *DURABILITY_DATA])


#: The simulator results `coremodal durability` reads (the selection's grade
#: files are read through cases/18-core-selection.toml).
DURABILITY_DATA = [REPO / "cases" / "18-core-durability-76x15.csv"]


def command_of_file(case: Path) -> str:
    if case in DURABILITY_DATA:
        return "durability"
    with case.open("rb") as f:
        return command_of(tomllib.load(f))


# Cheap variants, keys unchanged: the winder on 4 roll diameters instead of
# 57 (a second instead of a minute); case 14's response on 20 web speeds
# instead of 126; case 09's chucks not expanded as a
# uniform soft layer, which the beam level models, instead of the one-sided
# contact under gravity (the coupled harmonics: minutes).
CHEAP_EDITS = {
    "11-two-drum-winder": (r"(?m)^points\s*=\s*\d+", "points = 4"),
    "09-news-chucks-not-expanded-76x15-2200": (r"(?m)^expanded = false", 'expanded = false\ncontact = "uniform"'),
    "14-study-response-safe-speed": (r"(?m)^points\s*=\s*126", "points = 20"),  # web speeds per point
    # limits on 3 rest-roll diameters instead of 20 and without the band of
    # the uncertain inputs (its 10 solves per diameter), at the beam level
    "16-limits-rotogravure-150x15.8-4320": (r"(?m)^points\s*=\s*20.*$", "points = 3\nband = false"),
    "17-limits-news-76x15-2200": (r"(?m)^points\s*=\s*20.*$", "points = 3\nband = false"),
}


def cheap_copy(case: Path, tmp: Path) -> Path:
    """The case as shipped, or its cheap variant (CHEAP_EDITS)."""
    if ALL_LEVELS or case.stem not in CHEAP_EDITS:
        return case
    pattern, replacement = CHEAP_EDITS[case.stem]
    text, count = re.subn(pattern, replacement, case.read_text(encoding="utf-8"))
    assert count >= 1, f"{case.name}: the cheap variant no longer applies ({pattern})"
    copy_path = tmp / case.name
    copy_path.write_text(text, encoding="utf-8")
    return copy_path


def cheap_options(command: str) -> list[str]:
    if ALL_LEVELS or command in ("winder", "select", "traction", "durability"):  # no model level to choose
        return []
    if command == "study":
        return ["--model", "beam", "--jobs", "1"]
    return ["--model", "beam"]


def written_json(command: str, out: Path) -> dict:
    name = {"study": "study.json", "converge": "converge.json"}.get(command, "summary.json")
    return json.loads((out / name).read_text(encoding="utf-8"))


@pytest.mark.parametrize("case", shipped_cases(), ids=lambda p: p.stem)
def test_every_shipped_case_writes_a_summary_of_the_scheme(case: Path, tmp_path: Path, validator) -> None:
    command = command_of_file(case)
    out = tmp_path / "out"
    source = cheap_copy(case, tmp_path)
    run([command, str(source), "--output", str(out), "--no-plots", "-q", *cheap_options(command)], tmp_path)
    summary = written_json(command, out)
    assert errors(validator, summary) == []
    assert list(summary)[:4] == ["schema_version", "program", "command", "case"]
    assert summary["command"] == command
    assert summary["case"]["file"] == str(source)
    assert summary["timing_s"]["total"] >= 0
    same_numbers_in_python(out, command, summary)


def same_numbers_in_python(out: Path, command: str, summary: dict) -> None:
    """coremodal.load() opens the folder; its tables (to_pandas) hold the
    numbers summary.json holds (CSV cells carry 10 significant digits)."""
    import coremodal

    folder = coremodal.load(out)
    frame = folder.to_pandas()
    assert len(frame) > 0

    def same(table_values, json_values, rel: float = 1e-9) -> None:
        assert list(table_values) == pytest.approx(list(json_values), rel=rel, abs=1e-12)

    if command == "run":
        assert isinstance(folder, coremodal.Run)
        same(frame["frequency_hz"], [m["frequency_hz"] for m in summary["modes"]])
        return
    assert folder.command == command
    assert folder.summary == summary
    if command == "campbell":
        same(folder.read("critical_speeds.csv")["speed_rpm"], [c["speed_rpm"] for c in summary["critical_speeds"]])
    elif command == "response":
        same(folder.read("peaks.csv")["amplitude_mm"], [p["amplitude_mm"] for p in summary["peaks"]])
    elif command == "winder":
        same(folder.read("crossings.csv")["x_over_f_m_per_n"], [c["x_over_f_m_per_n"] for c in summary["crossings"]])
        assert len(set(frame["roll_diameter_m"])) == len(summary["points"])
    elif command == "study":
        assert max(frame["point"]) == summary["n_points"]
    elif command == "limits":
        same(frame["diameter_mm"], [p["diameter_mm"] for p in summary["points"]])
        same(frame["safe_m_s"], [p["safe_web_speed_m_s"] for p in summary["points"]])
    elif command == "select":
        assert len(set(folder.read("reels.csv")["reel"])) == len(summary["reels"])
        json_cores = {(s["name"], c["core"]): c for s in summary["stands"] for c in s["cores"]}
        assert len(frame) == len(json_cores) > 0
        # selection.csv carries 6 significant digits
        same(frame["max_roll_mass_kg"],
             [json_cores[(str(r["stand"]), str(r["core"]))]["max_roll_mass_kg"] for r in folder.table], rel=1e-5)
    elif command == "traction":
        same(frame["web_speed_m_s"], [p["web_speed_m_s"] for p in summary["points"]])
        same(frame["traction_N_m"], [p["traction_N_m"] for p in summary["points"]])
    elif command == "durability":
        assert len(frame) == summary["data"]["points"]
        allowed = folder.read("allowed_weights.csv")
        same(allowed["cycles"], summary["table_cycles"])


def test_a_solid_run_and_the_beam_formulas_follow_the_scheme(tmp_path: Path, validator) -> None:
    out = tmp_path / "solid"
    run(["run", str(REPO / "cases" / "01-iso-free-free-76x15.toml"), "--mesh", "coarse", "--output", str(out),
         "--no-plots", "-q"], tmp_path)
    summary = written_json("run", out)
    assert errors(validator, summary) == []
    assert summary["model"]["level"] == "solid"
    assert summary["speeds"] == {"not_given": summary["speeds"]["not_given"]}  # free-free: no stand
    beam = json.loads(run(["beam", str(REPO / "cases" / "03-rest-roll-150x15.8-4320.toml"), "--json"], tmp_path).stdout)
    assert errors(validator, beam) == []
    row = beam["speeds"]["safe_web_speed"][0]
    # I-5 by hand from the same f1 and Dp: v = safe pi Dp f1, and m/min = 60 m/s.
    assert row["v_safe_m_s"] == pytest.approx(row["safe"] * 3.141592653589793 * beam["speeds"]["dp_m"]
                                              * beam["speeds"]["f1_hz"], rel=1e-12)
    assert row["v_safe_m_min"] == pytest.approx(60 * row["v_safe_m_s"], rel=1e-12)


def test_a_converge_study_follows_the_scheme(tmp_path: Path, validator) -> None:
    out = tmp_path / "converge"
    run(["converge", str(REPO / "cases" / "01-iso-free-free-76x15.toml"), "--models", "beam", "--levels", "3",
         "--repeats", "1", "--output", str(out), "--no-plots", "-q"], tmp_path)
    assert errors(validator, written_json("converge", out)) == []


def test_the_schema_refuses_the_old_keys_and_broken_rows(tmp_path: Path, validator) -> None:
    out = tmp_path / "campbell"
    run(["campbell", str(REPO / "cases" / "12-rotation-tester-76x15.toml"), "--output", str(out), "--no-plots",
         "-q"], tmp_path)
    good = written_json("campbell", out)
    assert errors(validator, good) == []
    assert good["speeds"]["safe_web_speed"], "case 12 spins in a stand: its I-5 speeds are given"

    old = copy.deepcopy(good)
    old["version"] = old.pop("program")
    assert errors(validator, old)
    no_minutes = copy.deepcopy(good)
    del no_minutes["speeds"]["safe_web_speed"][0]["v_safe_m_min"]
    assert errors(validator, no_minutes)
    renamed = copy.deepcopy(good)
    renamed["speeds"]["safe_web_speed"][0]["factor"] = renamed["speeds"]["safe_web_speed"][0].pop("safe")
    assert errors(validator, renamed)
    untimed = copy.deepcopy(good)
    untimed["time_s"] = untimed.pop("timing_s")["total"]
    assert errors(validator, untimed)
    both = copy.deepcopy(good)
    both["speeds"]["not_given"] = "no bending mode"
    assert errors(validator, both)


def test_a_traction_summary_keeps_its_speeds_apart_from_the_i5_speeds(tmp_path: Path, validator) -> None:
    """`speeds` is a roll's I-5 speeds in every summary: traction's
    zero-traction and slip speeds are `traction_speeds`, and the old key fails."""
    out = tmp_path / "traction"
    run(["traction", str(REPO / "cases" / "19-grooved-idler-traction.toml"), "--output", str(out), "--no-plots",
         "-q"], tmp_path)
    good = written_json("traction", out)
    assert errors(validator, good) == []
    old = copy.deepcopy(good)
    old["speeds"] = old.pop("traction_speeds")
    assert errors(validator, old)
