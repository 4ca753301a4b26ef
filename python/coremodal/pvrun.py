"""Runs coremodal/paraview_mode.py in ParaView's python (pvpython), under a
virtual display (xvfb-run) when there is no display: what
``python3 -m coremodal paraview RESULTS_DIR ...`` does.

ParaView is optional: Debian's ``paraview`` and ``python3-paraview``
(pvpython) and ``xvfb`` (xvfb-run) provide it; scripts/setup.sh installs
them with COREMODAL_PARAVIEW=1.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

#: The virtual screen, big enough for any picture the script saves, and
#: -noreset: an X server resets when its last client disconnects and refuses
#: connections meanwhile; ParaView closes its first display connection (the
#: OpenGL check) and opens the next at once, so without -noreset pvpython
#: aborts now and then with "bad X server connection" (4 of 10 runs on a
#: loaded machine here).
XVFB_SERVER_ARGS = "-screen 0 1920x1080x24 -noreset"
SCRIPT = Path(__file__).resolve().with_name("paraview_mode.py")


class ParaViewMissing(RuntimeError):
    """pvpython (or a display for it) is not there."""


def pvpython_command(script_args: list[str], env: dict[str, str] | None = None) -> list[str]:
    """The command that runs paraview_mode.py with ``script_args``: pvpython
    from the PATH, behind ``xvfb-run -a`` when DISPLAY is not set. Raises
    ParaViewMissing, saying what to install, when either is missing."""
    env = os.environ if env is None else env
    pvpython = shutil.which("pvpython", path=env.get("PATH"))
    if pvpython is None:
        raise ParaViewMissing("pvpython is not installed: apt install paraview python3-paraview xvfb "
                              "(or COREMODAL_PARAVIEW=1 bash scripts/setup.sh)")
    command = [pvpython, str(SCRIPT), *script_args]
    if env.get("DISPLAY"):
        return command
    xvfb_run = shutil.which("xvfb-run", path=env.get("PATH"))
    if xvfb_run is None:
        raise ParaViewMissing("no display (DISPLAY is not set) and no xvfb-run to make one: apt install xvfb")
    return [xvfb_run, "-a", "-s", XVFB_SERVER_ARGS, *command]
