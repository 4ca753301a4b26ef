"""Render a mode of a coremodal run with ParaView: a pvpython script.

    pvpython paraview_mode.py RESULTS_DIR --list
    pvpython paraview_mode.py RESULTS_DIR --mode 1 --out mode_01.png
    pvpython paraview_mode.py RESULTS_DIR --mode 1 --frames 12 --gif mode_01.gif

Without a display, run it under a virtual one:
``xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" pvpython ...`` (without
-noreset the X server resets between ParaView's first two connections and
pvpython aborts now and then: "bad X server connection"). ``python3 -m
coremodal paraview RESULTS_DIR ...`` finds pvpython and xvfb-run and does
that for you.

It opens the run's modes.xdmf with the Xdmf3ReaderS reader, in which the
modes are time steps (time = mode number), goes to the chosen mode, warps
the mesh by its "displacement" with the mode's suggested scale (the field
data "warp_scale", which makes a bending deflection 10 % of the model's
length), colours it by |u| and saves a PNG. With ``--frames N`` it also
saves N frames of the mode swinging, warped by scale * sin(phase), and with
``--gif`` joins them into an animated GIF (with PIL, else ImageMagick).

Only ParaView's own python is needed: nothing here imports the coremodal
package, h5py or numpy, so the script runs in any pvpython.
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

#: Frames of one period of the animation when --frames is given without a number.
DEFAULT_FRAMES = 12
#: Milliseconds per frame of the GIF: 12 frames make a 1.2 s period.
GIF_FRAME_MS = 100
#: The undeformed roll, drawn faintly behind the warped one.
UNDEFORMED_OPACITY = 0.15
#: Every text of the picture (labels, scalar bar, orientation axes) on its white background.
DARK_TEXT = (0.1, 0.1, 0.1)
#: The side view looks down on the plane of motion by atan(0.2) = 11 degrees:
#: enough to see the roll is round, little enough to keep the deflection true.
CAMERA_ELEVATION = 0.2
#: Room around the roll and its swing, as a factor on the picture's half-height.
FRAME_MARGIN = 1.15


def xdmf_path(target: str) -> str:
    """modes.xdmf of a results folder (or the file itself), as an absolute
    path: the Xdmf3 reader resolves modes.h5 from the XDMF file's directory,
    and a bare relative name makes it look in the wrong place."""
    path = os.path.join(target, "modes.xdmf") if os.path.isdir(target) else target
    if not os.path.isfile(path):
        raise SystemExit(f"paraview_mode: error: {path}: no such file (a coremodal run folder holds modes.xdmf)")
    return os.path.abspath(path)


def mode_labels(xdmf: str) -> dict[int, str]:
    """Mode number -> "mode 7: 48.80 Hz, bending, n=1, m=0", from the XDMF
    file's own Information elements (the type is not a number, so it is no
    plain field data)."""
    labels = {}
    for grid in ET.parse(xdmf).getroot().iter("Grid"):
        time, info = grid.find("Time"), grid.find("Information[@Name='label']")
        if time is not None and info is not None:
            labels[int(float(time.get("Value")))] = info.get("Value")
    return labels


def field_value(source, name: str) -> float:
    """One number of the current time step's field data."""
    array = source.FieldData[name]
    if array is None:
        raise SystemExit(f"paraview_mode: error: the results have no field data {name!r}: "
                         "written by a coremodal older than the temporal modes.xdmf")
    return array.GetRange(0)[0]


def open_modes(xdmf: str):
    """The reader, its time steps (mode numbers) read."""
    from paraview import simple

    reader = simple.Xdmf3ReaderS(FileName=[xdmf])
    reader.UpdatePipelineInformation()
    return reader, [int(round(t)) for t in reader.TimestepValues]


def list_modes(reader, steps: list[int], labels: dict[int, str]) -> None:
    """One line per time step, with the numbers ParaView read for it."""
    print(f"time steps: {len(steps)}")
    for step in steps:
        reader.UpdatePipeline(step)
        print(f"{step}: {labels.get(step, f'mode {step}')}; frequency_hz "
              f"{field_value(reader, 'frequency_hz'):.6g}, warp_scale {field_value(reader, 'warp_scale'):.4g}")


def _side_camera(view, reader, scale: float, size: tuple[int, int]) -> None:
    """A parallel side view across the roll: its axis (z) left to right, the
    plane the mode moves in most (x or y) up the screen, seen from a little
    above it, zoomed so that the roll and its swing fill the picture."""
    displacement = reader.PointData["displacement"]
    ux = max(abs(v) for v in displacement.GetRange(0))
    uy = max(abs(v) for v in displacement.GetRange(1))
    swing = scale * max(abs(v) for v in displacement.GetRange(-1))  # largest warped |u|
    x0, x1, y0, y1, z0, z1 = reader.GetDataInformation().GetBounds()
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    length = max(z1 - z0, 1e-12)
    if ux >= uy:  # moving in x: x up, look along -y (then +z runs to the right)
        up, across, height = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], x1 - x0
    else:  # moving in y: y up, look along +x
        up, across, height = [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], y1 - y0
    distance = 4 * length  # any distance will do in a parallel projection
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + distance * (a + CAMERA_ELEVATION * u) for c, a, u in zip(centre, across, up)]
    view.CameraViewUp = up
    aspect = size[0] / size[1]
    view.CameraParallelScale = FRAME_MARGIN * max(length / (2 * aspect), height / 2 + swing)


def build_scene(reader, mode: int, scale: float | None, size: tuple[int, int], label: str):
    """View, warp filter and the scale used, at time step ``mode``."""
    from paraview import simple

    reader.UpdatePipeline(mode)
    if scale is None:
        scale = field_value(reader, "warp_scale")
    view = simple.CreateView("RenderView")
    view.ViewSize = list(size)
    view.ViewTime = mode
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    # The orientation axes' X, Y, Z are white by default: dark on the white background.
    view.OrientationAxesLabelColor = list(DARK_TEXT)
    view.OrientationAxesOutlineColor = list(DARK_TEXT)
    try:  # ParaView 5.10+ takes the background from the colour palette unless told not to
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass

    undeformed = simple.Show(reader, view)
    undeformed.Representation = "Surface"
    simple.ColorBy(undeformed, None)
    undeformed.AmbientColor = undeformed.DiffuseColor = [0.6, 0.6, 0.6]
    undeformed.Opacity = UNDEFORMED_OPACITY

    warp = simple.WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    warp.ScaleFactor = scale
    shown = simple.Show(warp, view)
    simple.ColorBy(shown, ("POINTS", "displacement", "Magnitude"))
    lut = simple.GetColorTransferFunction("displacement")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    shown.RescaleTransferFunctionToDataRange(True, False)
    bar = simple.GetScalarBar(lut, view)
    bar.Title = "displacement magnitude (mass-normalised)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = list(DARK_TEXT)
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Lower Center"
    shown.SetScalarBarVisibility(view, True)

    text = simple.Text(Text=f"{label}\nwarp x{scale:.3g}")
    text_display = simple.Show(text, view)
    text_display.WindowLocation = "Upper Left Corner"
    text_display.Justification = "Left"
    text_display.FontSize = 14
    text_display.Color = list(DARK_TEXT)

    _side_camera(view, reader, scale, size)
    return view, warp, scale


def save_frames(view, warp, scale: float, n_frames: int, stem: str, size: tuple[int, int]) -> list[str]:
    """N PNGs of one period: the mode warped by scale * sin(2 pi k / N)."""
    from paraview import simple

    paths = []
    for k in range(n_frames):
        warp.ScaleFactor = scale * math.sin(2 * math.pi * k / n_frames)
        path = f"{stem}_{k:03d}.png"
        simple.SaveScreenshot(path, view, ImageResolution=list(size))
        paths.append(path)
    warp.ScaleFactor = scale
    return paths


def write_gif(frames: list[str], gif: str) -> str:
    """Joins the frames into a looping GIF; returns "" or why there is none."""
    try:
        from PIL import Image
    except ImportError:
        Image = None
    if Image is not None:
        images = [Image.open(p).convert("RGB") for p in frames]
        images[0].save(gif, save_all=True, append_images=images[1:], duration=GIF_FRAME_MS, loop=0)
        return ""
    magick = shutil.which("magick") or shutil.which("convert")
    if magick is None:
        return "neither PIL nor ImageMagick is installed"
    done = subprocess.run([magick, "-delay", str(GIF_FRAME_MS // 10), "-loop", "0", *frames, gif],
                          capture_output=True, text=True)
    return "" if done.returncode == 0 and os.path.isfile(gif) else f"{magick} failed: {done.stderr.strip()}"


def _size(text: str) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, got {text!r}")
    return width, height


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="pvpython paraview_mode.py",
                                description="Render a mode of a coremodal run with ParaView.")
    p.add_argument("results", help="results folder of coremodal run (holding modes.xdmf and modes.h5), or modes.xdmf")
    p.add_argument("--list", action="store_true", help="print the time steps (modes) and exit")
    p.add_argument("--mode", type=int, default=1, help="mode number = time step (default 1)")
    p.add_argument("--out", help="PNG to write (default mode_NN_paraview.png in the current folder)")
    p.add_argument("--scale", type=float, help="warp scale factor (default: the mode's warp_scale)")
    p.add_argument("--size", type=_size, default=(1200, 600), metavar="WxH",
                   help="picture size in pixels (default 1200x600)")
    p.add_argument("--frames", type=int, nargs="?", const=DEFAULT_FRAMES, default=0,
                   help=f"also write N frames of one period (default N = {DEFAULT_FRAMES})")
    p.add_argument("--gif", help="join the frames into this animated GIF (implies --frames)")
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    xdmf = xdmf_path(args.results)
    labels = mode_labels(xdmf)
    reader, steps = open_modes(xdmf)
    if args.list:
        list_modes(reader, steps, labels)
        return 0
    if args.mode not in steps:
        print(f"paraview_mode: error: mode {args.mode} is not a time step of {xdmf} "
              f"(it holds modes {steps[0] if steps else '-'} to {steps[-1] if steps else '-'})", file=sys.stderr)
        return 1
    from paraview import simple

    out = args.out or f"mode_{args.mode:02d}_paraview.png"
    view, warp, scale = build_scene(reader, args.mode, args.scale, args.size,
                                    labels.get(args.mode, f"mode {args.mode}"))
    try:
        simple.SaveScreenshot(out, view, ImageResolution=list(args.size))
        print(out)
        n_frames = args.frames or (DEFAULT_FRAMES if args.gif else 0)
        if n_frames:
            stem = os.path.splitext(args.gif or out)[0] + "_frame"
            frames = save_frames(view, warp, scale, n_frames, stem, args.size)
            print(f"{len(frames)} frames: {frames[0]} ... {frames[-1]}")
            if args.gif:
                why = write_gif(frames, args.gif)
                print(args.gif if not why else f"no GIF: {why}")
    finally:
        # A render view still alive when the interpreter exits is torn down
        # after the X connection under xvfb-run: "GLXBadContext" and exit
        # status 1 although every picture was written.
        simple.Delete(view)
    return 0


if __name__ == "__main__":
    sys.exit(main())
