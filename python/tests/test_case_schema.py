"""`coremodal schema`: the case file's JSON Schema (src/scene/case_json_schema.cpp).

Every shipped case in cases/ and cases/hard/ must validate against it, and a
few broken cases must not: an unknown key, a wrong type, a negative length,
a unit string of the wrong dimension or no unit at all.

cases/11-two-drum-winder.toml is left out: it is a [winder] file, read by its
own reader (src/winder/winder_scene.cpp, docs/how-to/winder.md), with its own schema,
`coremodal schema --winder` (test_winder_fit_schema.py); cases/18-core-selection.toml
is a [selection] file (src/selection/selection_scene.cpp, docs/how-to/durability.md),
which the case-file schema does not describe.

Needs COREMODAL_BIN (the program) and the jsonschema package (Debian
python3-jsonschema, installed by scripts/setup.sh); skipped without either.
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
WINDER_FILES = {"11-two-drum-winder.toml"}  # [winder] files: their own reader, not in the schema
SELECTION_FILES = {"18-core-selection.toml"}  # [selection] files: likewise
FIT_FILES = {"16-limits-measured-f1.toml"}  # `coremodal fit` measurements: the fit schema (test_winder_fit_schema.py)


def shipped_cases() -> list[Path]:
    cases = sorted((REPO / "cases").glob("*.toml")) + sorted((REPO / "cases" / "hard").glob("*.toml"))
    return [c for c in cases if c.name not in WINDER_FILES | SELECTION_FILES | FIT_FILES]


@pytest.fixture(scope="module")
def schema() -> dict:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    done = subprocess.run([binary, "schema"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def validator(schema: dict):
    jsonschema.Draft7Validator.check_schema(schema)
    return jsonschema.Draft7Validator(schema)


def load(path: Path) -> dict:
    with path.open("rb") as f:
        return tomllib.load(f)


def errors(validator, document: dict) -> list[str]:
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator.iter_errors(document)]


def test_the_schema_is_draft_07_with_a_description_for_every_key(schema: dict) -> None:
    assert schema["$schema"] == "http://json-schema.org/draft-07/schema#"
    tables = [schema] + list(schema["definitions"].values())
    for table in tables:
        assert table["additionalProperties"] is False
        for key, prop in table["properties"].items():
            assert prop.get("description"), key
            assert "Default:" in prop["description"], key


@pytest.mark.parametrize("case", shipped_cases(), ids=lambda p: str(p.relative_to(REPO)))
def test_every_shipped_case_validates(validator, case: Path) -> None:
    assert errors(validator, load(case)) == []


def test_the_test_sees_the_shipped_cases() -> None:
    assert len(shipped_cases()) >= 20


BASE = "cases/02-clamped-76x15.toml"
CHUCKS = "cases/08-news-chucks-76x15-2200.toml"
TRACTION = "cases/19-grooved-idler-traction.toml"  # [traction] alone: no [core] needed


def broken(path: str, change) -> dict:
    document = copy.deepcopy(load(REPO / path))
    change(document)
    return document


BROKEN = [
    ("an unknown key", BASE, lambda d: d["core"].update(outer_diamter="106 mm"), "outer_diamter"),
    ("an unknown table", BASE, lambda d: d.update(anlysis={"modes": 3}), "anlysis"),
    ("a wrong type", BASE, lambda d: d["analysis"].update(modes="12"), "'12' is not of type 'integer'"),
    # 12.0 would pass: JSON Schema counts a number with no fraction as an
    # integer, where the reader wants a TOML integer (docs/reference/case-files.md).
    ("a fraction for an integer", BASE, lambda d: d["analysis"].update(modes=12.5), "integer"),
    ("a negative length", BASE, lambda d: d["core"].update(length=-2.2), "length"),
    ("a negative length with a unit", BASE, lambda d: d["core"].update(length="-2.2 m"), "length"),
    ("a unit of the wrong dimension", BASE, lambda d: d["core"].update(length="2211 kg"), "length"),
    ("a bad unit string", BASE, lambda d: d["core"].update(inner_diameter="76 mmm"), "inner_diameter"),
    ("a unit in the wrong case", BASE, lambda d: d["core"].update(inner_diameter="76 MM"), "inner_diameter"),
    ("no unit on a length", BASE, lambda d: d["core"].update(inner_diameter="76"), "inner_diameter"),
    ("a missing required key", BASE, lambda d: d["core"].pop("length"), "'length' is a required property"),
    ("an unknown choice", BASE, lambda d: d["supports"].update(type="clampd"), "clampd"),
    ("an unknown library material", BASE, lambda d: d["core"].update(material="paperbord_core"), "material"),
    ("an unknown base material", BASE, lambda d: d["core"].update(material={"base": "steal"}), "material"),
    ("a chuck key on a clamp zone", BASE, lambda d: d["supports"]["left"].update(inserted_length="110 mm"),
     "inserted_length"),
    ("a clamp key on a chuck", CHUCKS, lambda d: d["supports"]["left"].update(start="0 mm"), "start"),
    ("a band of one frequency", BASE, lambda d: d["analysis"].update(band=["0 Hz"]), "band"),
    ("a wrap of zero", TRACTION, lambda d: d["traction"].update(wrap=0), "wrap"),
    ("an unknown [traction] key", TRACTION, lambda d: d["traction"].update(grove_depth="36 um"), "grove_depth"),
    ("a viscosity in the wrong unit", TRACTION, lambda d: d["traction"].update(air_viscosity="1.8e-5 Pa"),
     "air_viscosity"),
    ("neither [core] nor [traction]", TRACTION, lambda d: d.pop("traction"),
     "is not valid under any of the given schemas"),
]


@pytest.mark.parametrize("what, path, change, expected", BROKEN)
def test_broken_cases_are_rejected(validator, what: str, path: str, change, expected: str) -> None:
    found = errors(validator, broken(path, change))
    assert found, f"{what} was accepted"
    assert any(expected in e for e in found) or expected in json.dumps(found), found


def toml_text(document: dict, path: str = "") -> str:
    """Enough of a TOML writer for the cases: scalars, lists of scalars,
    tables, arrays of tables."""
    def value(v) -> str:
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, (int, float)):
            return repr(v)
        if isinstance(v, str):
            return json.dumps(v, ensure_ascii=False)
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }"
        raise TypeError(v)

    def is_tables(v) -> bool:
        return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)

    lines = [f"{k} = {value(v)}" for k, v in document.items() if not isinstance(v, dict) and not is_tables(v)]
    for k, v in document.items():
        name = f"{path}.{k}" if path else k
        if isinstance(v, dict):
            lines += ["", f"[{name}]", toml_text(v, name)]
        elif is_tables(v):
            for item in v:
                lines += ["", f"[[{name}]]", toml_text(item, name)]
    return "\n".join(lines)


@pytest.mark.parametrize("what, path, change, expected", BROKEN)
def test_the_reader_refuses_the_broken_cases_too(tmp_path: Path, what: str, path: str, change, expected: str) -> None:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set")
    original = tmp_path / "original.toml"
    original.write_text(toml_text(load(REPO / path)), encoding="utf-8")
    assert tomllib.loads(original.read_text(encoding="utf-8")) == load(REPO / path)  # the writer is faithful
    done = subprocess.run([binary, "check", str(original)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    case = tmp_path / "broken.toml"
    case.write_text(toml_text(broken(path, change)), encoding="utf-8")
    done = subprocess.run([binary, "check", str(case)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 1, f"{what}: the reader took it\n{done.stdout}"


@pytest.mark.parametrize("value", ["76 mm", "76mm", "7.6 cm", "3 in", 0.076, "76 µm", "76 um", "+76 mm", "7.6e1 mm"])
def test_lengths_the_reader_takes_are_accepted(validator, value: str | float) -> None:
    assert errors(validator, broken(BASE, lambda d: d["core"].update(inner_diameter=value))) == []


@pytest.mark.parametrize("value", ["920 kg/m^3", "920 kg/m3", "920 kg/m³", "0.92 g/cm^3", "920 kg / m^3"])
def test_density_spellings_the_reader_takes_are_accepted(validator, value: str) -> None:
    document = broken(BASE, lambda d: d["core"].update(material={"base": "paperboard_core", "density": value}))
    assert errors(validator, document) == []


def test_the_schema_file_option_writes_the_same_text(tmp_path: Path) -> None:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set")
    out = tmp_path / "case.schema.json"
    done = subprocess.run([binary, "schema", "--output", str(out)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    printed = subprocess.run([binary, "schema"], capture_output=True, text=True, timeout=60).stdout
    assert out.read_text(encoding="utf-8") == printed


def test_every_default_is_a_valid_value_of_its_key(schema: dict) -> None:
    resolver = jsonschema.RefResolver.from_schema(schema)
    checked = 0
    for table in [schema] + list(schema["definitions"].values()):
        for key, prop in table["properties"].items():
            if "default" in prop:
                jsonschema.Draft7Validator(prop, resolver=resolver).validate(prop["default"])
                checked += 1
    assert checked >= 20
