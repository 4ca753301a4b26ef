"""`coremodal schema --winder`, `--fit` and `--selection`: the JSON Schemas
of the three input files the case schema does not describe, a two-drum winder
file ([winder], src/winder/winder_scene.cpp), a fit's measurements file
(parameters, [[measurement]], src/analyses/fit/measurements.cpp) and a
core-selection file ([selection], src/selection/selection_scene.cpp). Every
shipped file of each kind validates against its own schema (case 11, the fit
files of cases/validation, case 18; the other files against the case schema),
and broken copies do not.

Needs COREMODAL_BIN (the program) and the jsonschema package; skipped
without either.
"""

from __future__ import annotations

import copy
import json
import os
import subprocess
import tomllib
from pathlib import Path

import pytest

jsonschema = pytest.importorskip(
    "jsonschema", reason="the jsonschema package is missing: apt-get install python3-jsonschema")

REPO = Path(__file__).resolve().parents[2]


def load(path: Path) -> dict:
    with path.open("rb") as f:
        return tomllib.load(f)


def kind_of(document: dict) -> str:
    if "selection" in document:
        return "selection"
    if "winder" in document:
        return "winder"
    if "measurement" in document:
        return "fit"
    return "case"


INPUTS = sorted((REPO / "cases").glob("*.toml")) + sorted((REPO / "cases" / "validation").glob("*.toml"))


def schema_of(kind: str) -> dict:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    flag = {"case": [], "winder": ["--winder"], "fit": ["--fit"], "selection": ["--selection"]}[kind]
    done = subprocess.run([binary, "schema", *flag], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    schema = json.loads(done.stdout)
    jsonschema.Draft7Validator.check_schema(schema)
    return schema


@pytest.fixture(scope="module")
def validators() -> dict:
    return {kind: jsonschema.Draft7Validator(schema_of(kind)) for kind in ("case", "winder", "fit", "selection")}


def errors(validator, document: dict) -> list[str]:
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator.iter_errors(document)]


def test_there_are_files_of_every_kind() -> None:
    kinds = [kind_of(load(p)) for p in INPUTS]
    assert kinds.count("winder") >= 1 and kinds.count("fit") >= 2 and kinds.count("case") >= 10
    assert kinds.count("selection") >= 1


@pytest.mark.parametrize("path", INPUTS, ids=lambda p: str(p.relative_to(REPO)))
def test_every_shipped_input_validates_against_the_schema_of_its_kind(validators, path: Path) -> None:
    document = load(path)
    assert errors(validators[kind_of(document)], document) == []


WINDER = REPO / "cases" / "11-two-drum-winder.toml"
FIT = REPO / "cases" / "validation" / "ilomaki-table1.toml"
SELECTION = REPO / "cases" / "18-core-selection.toml"


def changed(path: Path, change) -> dict:
    document = copy.deepcopy(load(path))
    change(document)
    return document


BROKEN = [
    ("winder", WINDER, lambda d: d["winder"]["drums"].update(outer_diamter="850 mm"), "outer_diamter"),
    ("winder", WINDER, lambda d: d["winder"]["drums"].update(outer_diameter="850 kg"), "outer_diameter"),
    ("winder", WINDER, lambda d: d["winder"]["drums"].update(outer_diameter=-0.85), "outer_diameter"),
    ("winder", WINDER, lambda d: d["winder"]["rolls"].update(count=0), "count"),
    ("winder", WINDER, lambda d: d["winder"]["rolls"].update(model="flexible"), "flexible"),
    ("winder", WINDER, lambda d: d["winder"]["sweep"].update(response_drum="middle"), "middle"),
    ("winder", WINDER, lambda d: d.update(core={"length": "1 m"}), "core"),
    ("winder", WINDER, lambda d: d.pop("winder"), "'winder' is a required property"),
    ("fit", FIT, lambda d: d.update(parameter=d.pop("parameters")), "parameter"),
    ("fit", FIT, lambda d: d.update(parameters=[]), "parameters"),
    ("fit", FIT, lambda d: d["measurement"][0].update(frequency="39.06 mm"), "frequency"),
    ("fit", FIT, lambda d: d["measurement"][0].update(mode="first bending"), "mode"),
    ("fit", FIT, lambda d: d["measurement"][0].pop("case"), "'case' is a required property"),
    ("fit", FIT, lambda d: d["measurement"][0].update(model="solid"), "solid"),
    ("fit", FIT, lambda d: d["parameters"].append({"key": "core.length", "minimum": "1 m"}), "minimum"),
    ("selection", SELECTION, lambda d: d["selection"].update(paper_densty="750 kg/m^3"), "paper_densty"),
    ("selection", SELECTION, lambda d: d["selection"].pop("paper_density"), "'paper_density' is a required"),
    ("selection", SELECTION, lambda d: d["selection"]["core"][0].update(outer_diameter="102 kg"), "outer_diameter"),
    ("selection", SELECTION, lambda d: d["selection"]["core"][0].update(density=-700), "density"),
    ("selection", SELECTION, lambda d: d["selection"]["core"][2].update(durability="x.csv"), "valid under"),
    ("selection", SELECTION, lambda d: d["selection"]["core"][2].pop("s_log"), "valid under"),
    ("selection", SELECTION, lambda d: d["selection"]["core"][2].update(b0=45000), "b0"),
    ("selection", SELECTION, lambda d: d["selection"]["stand"][0].update(winder="center"), "center"),
    ("selection", SELECTION, lambda d: d["selection"]["stand"][0].update(chuck_factor=1.2), "chuck_factor"),
    ("selection", SELECTION, lambda d: d["selection"]["stand"][1].update(cores=[]), "cores"),
    ("selection", SELECTION, lambda d: d["selection"]["reel"][0].update(widht="1.6 m"), "widht"),
    ("selection", SELECTION, lambda d: d["selection"].update(core=[]), "core"),
]


@pytest.mark.parametrize("kind, path, change, expected", BROKEN)
def test_broken_inputs_are_rejected(validators, kind: str, path: Path, change, expected: str) -> None:
    found = errors(validators[kind], changed(path, change))
    assert found, f"{kind}: accepted"
    assert any(expected in e for e in found) or expected in json.dumps(found), found


def test_a_winder_file_is_not_a_case_file_and_a_fit_file_neither(validators) -> None:
    # The reason for separate schemas: each kind fails the others'.
    assert errors(validators["case"], load(WINDER))
    assert errors(validators["case"], load(FIT))
    assert errors(validators["winder"], load(FIT))
    assert errors(validators["case"], load(SELECTION))
    assert errors(validators["selection"], load(WINDER))
    assert errors(validators["selection"], load(FIT))
