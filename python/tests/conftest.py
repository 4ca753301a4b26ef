"""Fixtures: a real modes.h5, made by running the coremodal program on
python/tests/data/tiny.toml (a free-free steel tube).

COREMODAL_BIN names the program (CMake's python_pytest test sets it). If it is
set the run must succeed, or every test that needs the file fails. If it is
not set, COREMODAL_TEST_H5 may name an existing modes.h5 to test against
instead (handy while developing); with neither, those tests are skipped.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

PYTHON_DIR = Path(__file__).resolve().parents[1]
DATA_DIR = Path(__file__).resolve().parent / "data"

# The tests import the package from this checkout, with or without PYTHONPATH.
if str(PYTHON_DIR) not in sys.path:
    sys.path.insert(0, str(PYTHON_DIR))

import coremodal  # noqa: E402

RUN_TIMEOUT_S = 600


def _run_program(binary: str, output: Path) -> Path:
    case = DATA_DIR / "tiny.toml"
    env = dict(os.environ)
    # Open MPI refuses to start as root without these (containers, CI).
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    command = [binary, "run", str(case), "--output", str(output), "--no-plots"]
    try:
        run = subprocess.run(command, capture_output=True, text=True, env=env,
                             timeout=RUN_TIMEOUT_S)
    except (OSError, subprocess.TimeoutExpired) as error:
        pytest.fail(f"cannot run {' '.join(command)}: {error}", pytrace=False)
    if run.returncode != 0:
        pytest.fail(
            f"{' '.join(command)} exited with status {run.returncode}\n"
            f"--- stdout\n{run.stdout}\n--- stderr\n{run.stderr}",
            pytrace=False,
        )
    modes_h5 = output / "modes.h5"
    if not modes_h5.is_file():
        pytest.fail(f"{' '.join(command)} succeeded but wrote no {modes_h5}", pytrace=False)
    return modes_h5


@pytest.fixture(scope="session")
def modes_h5(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Path of a modes.h5 of the tiny free-free tube (modes.xdmf beside it)."""
    binary = os.environ.get("COREMODAL_BIN")
    if binary:
        return _run_program(binary, tmp_path_factory.mktemp("tiny_run"))
    fallback = os.environ.get("COREMODAL_TEST_H5")
    if fallback:
        return Path(fallback)
    pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest), or set "
                "COREMODAL_BIN=build/coremodal to test on a real result file")


@pytest.fixture(scope="session")
def results(modes_h5: Path) -> coremodal.Results:
    return coremodal.load(modes_h5)


@pytest.fixture(scope="session")
def cli_env() -> dict[str, str]:
    """Environment for running ``python3 -m coremodal`` from this checkout."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(PYTHON_DIR)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    env.setdefault("MPLBACKEND", "Agg")
    return env
