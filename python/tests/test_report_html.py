"""report.html, the page one can send (src/output/report_html.hpp), opened in a
real headless browser (Debian's chromium, scripts/setup.sh installs it) for
three kinds of folder: a run, a Campbell diagram and a limits verdict.

The browser, offline (every host name resolves to nothing), must find the
page's title and its first table, decode every picture (naturalWidth > 0),
and record no request for anything: the page carries all it shows. A
screenshot of it must not be blank.

Needs COREMODAL_BIN (the program, with python for the pictures) and
chromium; skipped, saying which, without either.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
DATA_DIR = Path(__file__).resolve().parent / "data"
RUN_TIMEOUT_S = 600
BROWSER_TIMEOUT_S = 120

# A beam-level clamped roll with rest paper and three diameters: the
# smallest limits verdict (tests/app/test_limits_cli.cpp's roll).
LIMITS_CASE = """name = "small"
model = "beam"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2211 mm"
material = { base = "paperboard_core", E_z = "6500 MPa" }
[supports]
type = "clamped"
[supports.left]
length = "70 mm"
[analysis]
modes = 6
[rest_paper]
thickness = "10 mm"
material = "rest_paper"
[limits]
points = 3
web_speed = "15 m/s"
band = false
"""

# What each page's first table is, by its first two columns.
FIRST_TABLE = {"run": ["result", "value"], "campbell": ["order", "speed"], "limits": ["D (mm)", "f1 (Hz)"]}

# Opens report.html in a frame and writes what the browser saw into the
# wrapper's DOM, which --dump-dom prints. Resource timing lists every fetch
# the page started, allowed or blocked (a picture on disk, a font, a link).
WRAPPER = """<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>
<iframe id="report" src="report.html" width="1200" height="900"></iframe><pre id="seen">not loaded</pre>
<script>
const frame = document.getElementById("report");
frame.addEventListener("load", () => {
  const page = frame.contentDocument;
  const table = page.querySelector("table");
  const seen = {
    title: page.title,
    h1: page.querySelector("h1") ? page.querySelector("h1").textContent : null,
    first_table_header: table ? [...table.querySelectorAll("th")].map(th => th.textContent) : null,
    n_tables: page.querySelectorAll("table").length,
    images: [...page.images].map(i => ({alt: i.alt, width: i.naturalWidth, height: i.naturalHeight,
                                        inline: i.src.startsWith("data:")})),
    requests: frame.contentWindow.performance.getEntriesByType("resource").map(e => e.name),
  };
  document.getElementById("seen").textContent = JSON.stringify(seen);
});
</script></body></html>
"""


def chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    pytest.skip("chromium is not installed (apt-get install chromium; scripts/setup.sh installs it): "
                "report.html cannot be opened in a browser")


def browser(*arguments: str) -> subprocess.CompletedProcess:
    # Offline: every host name resolves to nothing, so a page that needed the
    # network would show it. --no-sandbox: CI runs as root.
    command = [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
               "--host-resolver-rules=MAP * ~NOTFOUND", "--allow-file-access-from-files", *arguments]
    return subprocess.run(command, capture_output=True, text=True, timeout=BROWSER_TIMEOUT_S)


def coremodal(*arguments: str, cwd: Path) -> None:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run([binary, *arguments], capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=RUN_TIMEOUT_S)
    assert done.returncode == 0, done.stdout + done.stderr


def made_folder(kind: str, tmp: Path) -> Path:
    out = tmp / kind
    if kind == "run":
        coremodal("run", str(DATA_DIR / "tiny.toml"), "--output", str(out), "-q", cwd=tmp)
    elif kind == "campbell":
        coremodal("campbell", str(REPO / "cases" / "12-rotation-tester-76x15.toml"), "--output", str(out), "-q",
                  cwd=tmp)
    else:
        (tmp / "roll.toml").write_text(LIMITS_CASE)
        coremodal("limits", "roll.toml", "--output", str(out), "-q", cwd=tmp)
    return out


@pytest.fixture(scope="module", params=["run", "campbell", "limits"])
def folder(request, tmp_path_factory: pytest.TempPathFactory) -> Path:
    chromium()  # skip before the runs when there is no browser
    return made_folder(request.param, tmp_path_factory.mktemp(f"report_html_{request.param}"))


def test_the_page_opens_offline_with_its_table_first_and_every_picture_decoded(folder: Path) -> None:
    report_md = (folder / "report.md").read_text()
    pictures = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", report_md)
    assert pictures, "the report shows no picture: nothing to check"
    (folder / "wrapper.html").write_text(WRAPPER)
    done = browser("--virtual-time-budget=10000", "--dump-dom", (folder / "wrapper.html").as_uri())
    assert done.returncode == 0, done.stderr[-2000:]
    match = re.search(r'<pre id="seen">(.*?)</pre>', done.stdout, re.S)
    assert match, done.stdout[-2000:]
    assert match.group(1) != "not loaded", "the browser did not load report.html"
    seen = json.loads(match.group(1).replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">")
                      .replace("&quot;", '"'))
    title = report_md.splitlines()[0].removeprefix("# ")
    assert seen["h1"] == title and seen["title"] == title
    # The answer first: the page's first table is the run's summary, the
    # critical speeds, the limits verdict (report.md's first table, as drawn).
    first_header = re.search(r"^\|(.*)\|\s*$", report_md, re.M).group(1)
    assert seen["first_table_header"] == [cell.strip().replace("`", "") for cell in first_header.split("|")]
    assert seen["first_table_header"][:2] == FIRST_TABLE[folder.name]
    assert seen["n_tables"] == len(re.findall(r"^\|[-:| ]+\|\s*$", report_md, re.M))
    # Every picture of report.md is in the page, carried inside it, and decodes.
    assert len(seen["images"]) == len(pictures)
    for image in seen["images"]:
        assert image["inline"], image
        assert image["width"] > 0 and image["height"] > 0, image
    # Nothing fetched: no picture from disk, no font, no script, no network.
    assert seen["requests"] == []


def test_a_screenshot_of_the_page_is_not_blank(folder: Path) -> None:
    image_module = pytest.importorskip("PIL.Image", reason="python3-pil is missing")
    shot = folder.parent / f"{folder.name}_screenshot.png"
    done = browser(f"--screenshot={shot}", "--window-size=1200,1600", (folder / "report.html").as_uri())
    assert done.returncode == 0 and shot.is_file(), done.stderr[-2000:]
    with image_module.open(shot) as picture:
        grey = picture.convert("L")
        histogram = grey.histogram()
    dark = sum(histogram[:128])  # text, table rules, plot lines
    total = sum(histogram)
    # A blank (or an error page's) screenshot is nearly all one shade; a page of
    # text, tables and pictures has a few percent of dark pixels.
    assert 0.005 < dark / total < 0.6, f"dark share {dark / total:.4f}"
    assert len([n for n in histogram if n > 0]) > 16  # many shades: text and pictures
