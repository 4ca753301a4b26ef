"""Installing: `pip install ./python` (pyproject.toml, no network) gives an
importable package and, in a venv as README.md says, the coremodal-plot
command; and `cmake --install` gives a program that runs outside
the source tree and draws its pictures with the installed package."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import coremodal

PYTHON_DIR = Path(__file__).resolve().parents[1]
SOURCE_DIR = PYTHON_DIR.parent
DATA_DIR = Path(__file__).resolve().parent / "data"
INSTALL_TIMEOUT_S = 600


def test_the_package_version_is_the_programs() -> None:
    cmake = (SOURCE_DIR / "CMakeLists.txt").read_text()
    program = re.search(r"project\(coremodal VERSION ([0-9.]+)", cmake).group(1)
    pyproject = (PYTHON_DIR / "pyproject.toml").read_text()
    assert re.search(r'^version = "([0-9.]+)"', pyproject, re.M).group(1) == program
    assert coremodal.__version__ == program


def test_pip_installs_the_package_without_network(tmp_path: Path, modes_h5: Path) -> None:
    if subprocess.run([sys.executable, "-m", "pip", "--version"], capture_output=True).returncode != 0:
        pytest.skip("pip is not installed (apt install python3-pip)")
    # A copy, so that the build leaves nothing in the source tree.
    source = tmp_path / "src"
    shutil.copytree(PYTHON_DIR, source, ignore=shutil.ignore_patterns("tests", "__pycache__", "build",
                                                                       "*.egg-info"))
    target = tmp_path / "site"
    done = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps",
                           "--no-index", "--target", str(target), str(source)],
                          capture_output=True, text=True, timeout=INSTALL_TIMEOUT_S)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (target / "coremodal" / "paraview_mode.py").is_file()
    assert not (target / "tests").exists()
    # Imported from the install, in a folder far from the sources.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(target)
    code = "import coremodal, sys; r = coremodal.load(sys.argv[1]); print(coremodal.__file__); print(repr(r))"
    used = subprocess.run([sys.executable, "-c", code, str(modes_h5.parent)], capture_output=True, text=True,
                          env=env, cwd=tmp_path)
    assert used.returncode == 0, used.stderr
    where, text = used.stdout.splitlines()
    assert Path(where).is_relative_to(target)
    assert text.startswith("<coremodal run tiny: solid, 10 modes")


def test_the_install_of_the_readme_gives_the_coremodal_plot_command(tmp_path: Path) -> None:
    # README.md's recipe, as written: a venv that sees Debian's numpy, h5py
    # and matplotlib, and pip without network or build isolation.
    if subprocess.run([sys.executable, "-m", "venv", "--help"], capture_output=True).returncode != 0:
        pytest.skip("the venv module is missing (apt install python3-venv)")
    source = tmp_path / "python"
    shutil.copytree(PYTHON_DIR, source, ignore=shutil.ignore_patterns("tests", "__pycache__", "build",
                                                                       "*.egg-info"))
    venv = tmp_path / "venv"
    made = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
                          capture_output=True, text=True, timeout=INSTALL_TIMEOUT_S)
    assert made.returncode == 0, made.stdout + made.stderr
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_INDEX_URL")}
    done = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-deps", "--no-build-isolation",
                           "--no-index", str(source)],
                          capture_output=True, text=True, env=env, cwd=tmp_path, timeout=INSTALL_TIMEOUT_S)
    assert done.returncode == 0, done.stdout + done.stderr
    command = venv / "bin" / "coremodal-plot"
    assert command.is_file()
    version = subprocess.run([str(command), "--version"], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert version.returncode == 0, version.stderr
    assert version.stdout.strip() == f"coremodal-plot {coremodal.__version__}"
    helped = subprocess.run([str(command), "--help"], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert helped.returncode == 0, helped.stderr
    assert helped.stdout.startswith("usage: coremodal-plot")
    for name in ("run-plot", "campbell-plot", "limits-plot", "study-plot"):
        assert name in helped.stdout
    # A usage error is argparse's exit 2, a folder it cannot read exit 1 with one line.
    wrong = subprocess.run([str(command), "campbell-plot", str(tmp_path / "nowhere")], capture_output=True,
                           text=True, env=env, cwd=tmp_path)
    assert wrong.returncode == 1 and wrong.stderr.startswith("coremodal: error: "), wrong.stderr
    assert subprocess.run([str(command), "no-such-command"], capture_output=True, env=env).returncode == 2


def test_cmake_install_gives_a_program_that_draws_with_the_installed_package(tmp_path: Path) -> None:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    build = Path(binary).resolve().parent
    cmake = shutil.which("cmake")
    if cmake is None or not (build / "CMakeCache.txt").is_file():
        pytest.skip(f"{build} is not a CMake build folder (or cmake is missing)")
    prefix = tmp_path / "prefix"
    done = subprocess.run([cmake, "--install", str(build), "--prefix", str(prefix)], capture_output=True,
                          text=True, timeout=INSTALL_TIMEOUT_S)
    assert done.returncode == 0, done.stdout + done.stderr
    program = prefix / "bin" / "coremodal"
    package = prefix / "share" / "coremodal" / "python" / "coremodal"
    assert program.is_file() and (package / "__init__.py").is_file()
    assert (prefix / "share" / "coremodal" / "cases" / "02-clamped-76x15.toml").is_file()
    # The installed package tells us it was the one imported.
    marker = tmp_path / "imported_from"
    with open(package / "__init__.py", "a") as f:
        f.write('\nimport os as _os\nif _os.environ.get("COREMODAL_TEST_IMPORT_MARKER"):\n'
                '    open(_os.environ["COREMODAL_TEST_IMPORT_MARKER"], "w").write(__file__)\n')

    work = tmp_path / "work"  # outside the source tree
    work.mkdir()
    shutil.copy(DATA_DIR / "tiny.toml", work / "tiny.toml")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "COREMODAL_PYTHON_DIR")}
    env.update(COREMODAL_TEST_IMPORT_MARKER=str(marker), OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    run = subprocess.run([str(program), "run", "tiny.toml", "-o", "out", "-q"], capture_output=True,
                         text=True, env=env, cwd=work, timeout=INSTALL_TIMEOUT_S)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stderr == "", run.stderr  # no "no pictures" warning
    report = (work / "out" / "report.md").read_text()
    assert "![frequencies by mode type](spectrum.png)" in report
    assert (work / "out" / "spectrum.png").is_file()
    assert Path(marker.read_text()).resolve() == (package / "__init__.py").resolve()
