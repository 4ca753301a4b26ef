"""The error-against-time picture of ``coremodal converge``, on a converge.json
written here in the layout the program writes (see src/output/converge_report.cpp)."""

from __future__ import annotations

import json
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal import converge_plot


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return struct.unpack(">II", header[16:24])


def level(k: int) -> dict:
    return {"k": k, "h": 1 / k, "mesh": f"{k}/{k}/{8 * k}/{10 * k}", "n_dofs": 1000 * k**3, "runs": 3,
            "timing_s": {"mesh": 0.01, "assemble": 0.1 * k, "factor_and_solve": k**3, "classify": 0.01,
                         "total": 1.2 * k**3},
            "peak_memory_mb": 100 * k**2, "complete": True, "repeat_spread": 0.0}


def mode(role: str, f0: float, c: float, p: float, type_: str, n: int) -> dict:
    values = []
    for i, k in enumerate(range(1, 5)):
        f = f0 + c * (1 / k) ** p
        values.append({"level": i, "frequency_hz": f, "relative_error": abs(f - f0) / f0})
    return {"id": f"{type_} n={n} m=0", "type": type_, "n": n, "m": 0, "occurrence": 1, "role": role,
            "values": values,
            "richardson": {"extrapolated": True, "order": p, "f0_hz": f0, "error_estimate_hz": c / 4**p,
                           "relative_error_estimate": c / 4**p / f0, "asymptotic": True, "note": ""}}


@pytest.fixture()
def study() -> dict:
    return {
        "program": "coremodal test", "case": "synthetic", "source_file": "synthetic.toml", "n_modes": 20,
        "repeats": 3, "repeat_limit_s": 30, "total_time_s": 120.0,
        "models": [{"model": "solid", "ladder": "unit 1/1/8/10",
                    "levels": [level(k) for k in range(1, 5)],
                    "modes": [mode("f1", 32.1, 0.5, 4, "bending", 1),
                              mode("", 85.0, 1.0, 4, "bending", 1),
                              mode("ovalling", 435.0, 90.0, 3, "ovalling", 2)]}],
        "checks": [{"name": "default", "mesh": "3/2/32/81", "n_dofs": 181152,
                    "timing_s": {"total": 84.0}, "peak_memory_mb": 3510,
                    "modes": [{"id": "bending n=1 m=0", "frequency_hz": 32.11, "relative_error": 3e-4,
                               "role": "f1"}]}],
        "notes": [],
    }


def test_curves_follow_the_roles_and_the_levels(study: dict) -> None:
    curves = converge_plot.error_curves(study)
    assert [(c["model"], c["role"], c["against"]) for c in curves] == [("solid", "f1", "own"),
                                                                       ("solid", "ovalling", "own")]
    f1 = curves[0]
    assert f1["time_s"] == [1.2, 9.6, pytest.approx(32.4), 76.8]
    assert f1["dofs"] == [1000, 8000, 27000, 64000]
    assert f1["finest"] == [False, False, False, True]
    assert f1["error"][1] == pytest.approx(0.5 / 16 / 32.1)
    assert converge_plot.check_points(study) == [
        {"name": "default", "role": "f1", "time_s": 84.0, "error": 3e-4}]


def beam_level(k: int) -> dict:
    return {"k": k, "h": 1 / k, "mesh": f"{4 * k}/{4 * k}", "n_dofs": 48 * k, "runs": 200,
            "timing_s": {"mesh": 1e-5 * k, "assemble": 0.0, "factor_and_solve": 2e-4 * k, "classify": 1e-5 * k,
                         "total": 2.2e-4 * k},
            "peak_memory_mb": 80, "complete": True, "repeat_spread": 0.0}


def converging_f1(mode_id: str, m: int, ks: list, f0: float, solid_f0: float, amplitude: float) -> dict:
    """A tracked f1 whose level k is f0 + amplitude / k^4 (order 4), with its
    Richardson entry and its error against the solid's f0."""
    values = []
    for i, k in enumerate(ks):
        f = f0 + amplitude * (1 / k) ** 4
        values.append({"level": i, "frequency_hz": f, "relative_error": abs(f - f0) / f0,
                       "error_vs_solid": abs(f - solid_f0) / solid_f0})
    estimate = amplitude / ks[-1] ** 4
    return {"id": mode_id, "type": "bending", "n": 1, "m": m, "occurrence": 1, "role": "f1", "values": values,
            "richardson": {"extrapolated": True, "order": 4.0, "f0_hz": f0, "error_estimate_hz": estimate,
                           "relative_error_estimate": estimate / f0, "asymptotic": True, "note": ""}}


@pytest.fixture()
def two_levels(study: dict) -> dict:
    """The study with a beam model level: five levels k = 1, 2, 4, 8, 16, f1
    converging to 32.3 Hz against the solid's 32.1 Hz (model error +0.62 %)."""
    ks = [1, 2, 4, 8, 16]
    f0, solid_f0 = 32.3, 32.1
    beam_f1 = converging_f1("bending n=1 m=2", 2, ks, f0, solid_f0, 0.8)
    study["models"].append({"model": "beam", "ladder": "unit 4 elements", "refined_dimensions": 1,
                            "levels": [beam_level(k) for k in ks], "modes": [beam_f1],
                            "not_in_model": [{"role": "ovalling", "reason": "rigid cross-sections"}]})
    study["model_errors"] = [{"model": "beam", "role": "f1", "id": "bending n=1 m=2", "solid_id": "bending n=1 m=0",
                              "f0_hz": f0, "solid_f0_hz": solid_f0, "model_error": (f0 - solid_f0) / solid_f0,
                              "known_to": 1e-6}]
    return study


def test_two_model_levels_give_a_curve_each_and_the_beam_one_against_the_solid(two_levels: dict) -> None:
    curves = converge_plot.error_curves(two_levels)
    assert [(c["model"], c["role"], c["against"]) for c in curves] == [
        ("solid", "f1", "own"), ("solid", "ovalling", "own"), ("beam", "f1", "own"), ("beam", "f1", "solid")]
    own, vs_solid = curves[2], curves[3]
    assert own["dofs"] == [48, 96, 192, 384, 768]
    assert own["time_s"] == pytest.approx([2.2e-4, 4.4e-4, 8.8e-4, 1.76e-3, 3.52e-3])
    assert own["finest"] == [False, False, False, False, True]
    assert own["error"][-1] < 1e-5  # converging to its own f0 ...
    assert vs_solid["finest"] == [False] * 5
    assert vs_solid["error"][-1] == pytest.approx(0.2 / 32.1, rel=1e-4)  # ... and levelling off at the model error
    assert converge_plot.model_errors(two_levels)[0]["model_error"] == pytest.approx(0.2 / 32.1)


@pytest.fixture()
def three_levels(two_levels: dict) -> dict:
    """Two levels plus the harmonic: the solid's ladder k = 1 ... 6 on the r-z
    section (DOFs ~ k^2), f1 converging to 32.0995 Hz, just below the solid's
    32.1 Hz (exact in theta: what is left is the solid's discretization around)."""
    ks = list(range(1, 7))
    f0, solid_f0 = 32.0995, 32.1
    harmonic_f1 = converging_f1("bending n=1 m=0", 0, ks, f0, solid_f0, 0.4)
    levels = [dict(level(k), n_dofs=60 * k * k, runs=3,
                   timing_s={"mesh": 1e-3, "assemble": 0.01 * k, "factor_and_solve": 0.02 * k * k, "classify": 0.01,
                             "total": 0.04 * k * k}) for k in ks]
    two_levels["models"].append({"model": "harmonic", "ladder": "r–z section only; exact in theta",
                                 "refined_dimensions": 2, "levels": levels, "modes": [harmonic_f1],
                                 "not_in_model": []})
    two_levels["model_errors"].append({"model": "harmonic", "role": "f1", "id": "bending n=1 m=0",
                                       "solid_id": "bending n=1 m=0", "f0_hz": f0, "solid_f0_hz": solid_f0,
                                       "model_error": (f0 - solid_f0) / solid_f0, "known_to": 1e-5})
    return two_levels


def test_three_model_levels_give_the_harmonic_its_own_curves(three_levels: dict) -> None:
    curves = converge_plot.error_curves(three_levels)
    assert [(c["model"], c["role"], c["against"]) for c in curves][-2:] == [("harmonic", "f1", "own"),
                                                                           ("harmonic", "f1", "solid")]
    own, vs_solid = curves[-2], curves[-1]
    assert own["dofs"] == [60, 240, 540, 960, 1500, 2160]
    assert own["finest"] == [False] * 5 + [True]
    assert vs_solid["error"][-1] == pytest.approx(abs(32.0995 + 0.4 / 6**4 - 32.1) / 32.1)
    assert converge_plot.error_meaning("harmonic") == "the solid's discretization around"
    assert converge_plot.error_meaning("beam") == "model error"
    assert [e["model"] for e in converge_plot.model_errors(three_levels)] == ["beam", "harmonic"]


def test_draws_three_model_levels(three_levels: dict, tmp_path: Path) -> None:
    out = converge_plot.draw_error_vs_time(three_levels, tmp_path / "three.png", size_px=(900, 600))
    assert png_size(out) == (900, 600)


def test_draws_two_model_levels(two_levels: dict, tmp_path: Path) -> None:
    out = converge_plot.draw_error_vs_time(two_levels, tmp_path / "two.png", size_px=(900, 600))
    assert png_size(out) == (900, 600)


def test_draws_a_png_of_the_asked_size(study: dict, tmp_path: Path) -> None:
    out = converge_plot.draw_error_vs_time(study, tmp_path / "e.png", size_px=(800, 500))
    assert out == tmp_path / "e.png"
    assert png_size(out) == (800, 500)


def test_a_study_without_extrapolated_modes_still_draws(study: dict, tmp_path: Path) -> None:
    for m in study["models"][0]["modes"]:
        for v in m["values"]:
            del v["relative_error"]
    assert converge_plot.error_curves(study) == []
    assert png_size(converge_plot.draw_error_vs_time(study, tmp_path / "empty.png")) == (1000, 700)


def run_cli(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "coremodal", *args], capture_output=True, text=True,
                          env=env, timeout=300)


def test_command_line_writes_error_vs_time_beside_the_json(study: dict, tmp_path: Path,
                                                           cli_env: dict[str, str]) -> None:
    (tmp_path / "converge.json").write_text(json.dumps(study))
    run = run_cli(cli_env, "converge-plot", str(tmp_path))
    assert run.returncode == 0, run.stderr
    assert png_size(tmp_path / "error_vs_time.png") == (1000, 700)
    assert "error_vs_time.png" in run.stdout


def test_command_line_names_a_missing_or_bad_study(tmp_path: Path, cli_env: dict[str, str]) -> None:
    run = run_cli(cli_env, "converge-plot", str(tmp_path))
    assert run.returncode == 1
    assert "converge.json" in run.stderr
    (tmp_path / "converge.json").write_text('{"case": "x"}')
    run = run_cli(cli_env, "converge-plot", str(tmp_path))
    assert run.returncode == 1
    assert "no 'models' list" in run.stderr
