"""Where the roll is held, from the resolved case in modes.h5: the spans
along z that the pictures shade (clamp zones, chuck bodies, expanding
elements, bearings), so that a mode's shape can be read against its supports.

The case's chucks give their positions from their own core end, inwards
(``inserted_length_m``, ``expanding[].center_m``) and the shaft outwards to
the bearing (``shaft_length_m``), as src/effects/chuck_placement.hpp states;
here they become z from the left core end (z = 0).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

#: A bearing acts at one z (the shaft's end); it is shaded over this fraction
#: of the core's length around that z, so that it shows at any picture size.
BEARING_WIDTH_FRACTION = 0.012
#: Colour and opacity per kind of span, and the order they are drawn in
#: (expanding elements over the chuck body that carries them).
STYLES = {
    "clamp": ("0.55", 0.30),
    "chuck body": ("tab:brown", 0.22),
    "expanding element": ("tab:orange", 0.50),
    "bearing": ("0.15", 0.45),
}


@dataclass(frozen=True)
class SupportSpan:
    kind: str  # a key of STYLES
    z_start: float  # m, z_start <= z_end
    z_end: float


def clamp_spans(case: dict[str, Any]) -> list[tuple[float, float]]:
    """(z_start, z_end) of every clamp in the case's ``supports.clamps``."""
    supports = case.get("supports") if isinstance(case, dict) else None
    clamps = supports.get("clamps") if isinstance(supports, dict) else None
    spans = []
    for clamp in clamps or []:
        try:
            spans.append((float(clamp["z_start"]), float(clamp["z_end"])))
        except (KeyError, TypeError, ValueError):
            continue  # not a zone along z: nothing to shade
    return spans


def _span(kind: str, a: float, b: float) -> SupportSpan:
    return SupportSpan(kind, min(a, b), max(a, b))


def _chuck_spans(chuck: dict[str, Any], core_length: float) -> list[SupportSpan]:
    """The body, expanding elements and bearing of one chuck of the case."""
    right = chuck.get("name") == "right"
    at = (lambda offset: core_length - offset) if right else (lambda offset: offset)  # noqa: E731
    spans = [_span("chuck body", at(0.0), at(float(chuck["inserted_length_m"])))]
    for element in chuck.get("expanding") or []:
        centre, half = float(element["center_m"]), float(element["width_m"]) / 2
        spans.append(_span("expanding element", at(centre - half), at(centre + half)))
    bearing = at(-float(chuck.get("shaft_length_m", 0.0)))
    half = BEARING_WIDTH_FRACTION * core_length / 2
    spans.append(_span("bearing", bearing - half, bearing + half))
    return spans


def support_spans(case: dict[str, Any]) -> list[SupportSpan]:
    """Every clamp zone and every chuck's body, expanding elements and
    bearing of the case, in the order of STYLES (a case without them, or
    with entries that are not spans along z, gives fewer or none)."""
    spans = [SupportSpan("clamp", min(a, b), max(a, b)) for a, b in clamp_spans(case)]
    supports = case.get("supports") if isinstance(case, dict) else None
    chucks = supports.get("chucks") if isinstance(supports, dict) else None
    try:
        core_length = float(case["core"]["length"])
    except (KeyError, TypeError, ValueError):
        core_length = 0.0
    for chuck in chucks or []:
        try:
            spans += _chuck_spans(chuck, core_length)
        except (KeyError, TypeError, ValueError):
            continue  # an incomplete chuck: nothing to shade
    order = list(STYLES)
    return sorted(spans, key=lambda s: order.index(s.kind))


def shade_supports(axes, spans: list[SupportSpan], label: bool = True) -> None:
    """Shades every span across the whole height of ``axes``; with ``label``,
    one legend entry per kind."""
    labelled: set[str] = set()
    for span in spans:
        colour, alpha = STYLES[span.kind]
        name = span.kind if label and span.kind not in labelled else None
        labelled.add(span.kind)
        axes.axvspan(span.z_start, span.z_end, color=colour, alpha=alpha, lw=0, label=name)
