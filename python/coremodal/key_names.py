"""Words for case-file keys and units for their values, for the axes of the
study plots: "roll width (m)", not ``core.length [m]``; "rest paper
thickness (mm)" in the unit the study's values were written in.

A key's name is looked up in HUMAN_NAMES, where ``*`` stands for one part of
the path (``supports.*.center``: the left or the right clamp, or both); a
material constant is named by its owner and MATERIAL_NAMES; any other key
falls back to its last part in words with its table in brackets
(``analysis.tolerance`` -> "tolerance (analysis)").
"""

from __future__ import annotations

import math
import re
from fnmatch import fnmatchcase

#: The keys a study of a roll varies, in the words of the press room and of
#: docs/reference/case-files.md.
HUMAN_NAMES = {
    "core.length": "roll width",
    "core.inner_diameter": "core inner diameter",
    "core.outer_diameter": "core outer diameter",
    "core.wall": "core wall thickness",
    "rest_paper.thickness": "rest paper thickness",
    "rest_paper.outer_diameter": "rest roll diameter",
    "supports.*.center": "clamp zone centre",
    "supports.*.start": "clamp zone start",
    "supports.*.length": "clamp zone length",
    "supports.*.inserted_length": "chuck insertion depth",
    "supports.*.clearance": "chuck clearance",
    "supports.*.body_diameter": "chuck body diameter",
    "supports.*.shaft_diameter": "chuck shaft diameter",
    "supports.*.shaft_length": "chuck shaft length",
    "supports.*.expansion_pressure": "expansion pressure",
    "supports.*.normal_stiffness": "contact normal stiffness",
    "supports.*.tangential_stiffness": "contact tangential stiffness",
    "supports.*.expanding.*.center": "expanding element position",
    "supports.*.expanding.*.width": "expanding element width",
    "supports.*.expanding.*.segments": "expanding element segments",
    "supports.*.expanding.*.segment_angle": "expanding segment angle",
    "supports.*.bearing.radial_stiffness": "bearing radial stiffness",
    "supports.*.bearing.tilting_stiffness": "bearing tilting stiffness",
    "supports.*.bearing.frame_mass": "frame mass",
    "supports.*.bearing.frame_stiffness": "frame stiffness",
    "mesh.through_wall": "elements through the wall",
    "mesh.through_rest_paper": "elements through the rest paper",
    "mesh.around": "elements around",
    "mesh.along": "elements along",
}
#: The constants of a material table (docs/reference/case-scene.md, "Materials").
MATERIAL_NAMES = {
    "E": "Young's modulus E",
    "nu": "Poisson's ratio ν",
    "E_r": "radial modulus E_r",
    "E_theta": "hoop modulus E_θ",
    "E_z": "axial modulus E_z",
    "G_rtheta": "shear modulus G_rθ",
    "G_rz": "shear modulus G_rz",
    "G_thetaz": "shear modulus G_θz",
    "nu_rtheta": "Poisson's ratio ν_rθ",
    "nu_rz": "Poisson's ratio ν_rz",
    "nu_thetaz": "Poisson's ratio ν_θz",
    "density": "density",
}
#: Whose material a path's first part names.
MATERIAL_OWNERS = {"core": "core", "rest_paper": "rest paper", "supports": "chuck"}

_NUMBER_AND_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
#: Written values and SI values agree on the factor to this relative error:
#: a range's labels are written with 4 significant digits (%.4g,
#: scene/case_sweep_reader.cpp), so their ratios differ by up to 5e-4.
_FACTOR_TOLERANCE = 1e-3


def human_name(key: str) -> str:
    """Words for a case-file key (see the module's description)."""
    for pattern, name in HUMAN_NAMES.items():
        if fnmatchcase(key, pattern) and key.count(".") == pattern.count("."):
            return name
    parts = key.split(".")
    if len(parts) >= 3 and parts[-2] == "material" and parts[-1] in MATERIAL_NAMES:
        owner = MATERIAL_OWNERS.get(parts[0], parts[0].replace("_", " "))
        return f"{owner} {MATERIAL_NAMES[parts[-1]]}"
    words = parts[-1].replace("_", " ")
    return f"{words} ({'.'.join(parts[:-1])})" if len(parts) > 1 else words


def written_unit(labels: list[str], si_values: list[float], si_unit: str) -> tuple[str, float]:
    """The unit the values were written in and the factor from SI to it:
    ("mm", 1000) for labels "10 mm", "30 mm" of 0.01, 0.03 m. Falls back to
    (``si_unit``, 1) when the labels have no unit, differ in unit, or do
    not match the values."""
    if not labels or len(labels) != len(si_values):
        return si_unit, 1.0
    units, factors = set(), []
    for label, value in zip(labels, si_values):
        match = _NUMBER_AND_UNIT.match(str(label))
        if not match:
            return si_unit, 1.0
        written = float(match.group(1))
        units.add(match.group(2))
        if value != 0:
            factors.append(written / value)
    unit = units.pop() if len(units) == 1 else ""
    if not unit or not factors or factors[0] <= 0:
        return si_unit, 1.0
    if any(not math.isclose(f, factors[0], rel_tol=_FACTOR_TOLERANCE) for f in factors):
        return si_unit, 1.0
    return unit, _round_factor(sum(factors) / len(factors))


def _round_factor(factor: float) -> float:
    """The factor read back from rounded labels, made exact when it is a
    power of ten (mm, kPa, GPa: almost every unit written): 999.96 -> 1000;
    any other factor (bar, m/min) is kept as read, good to 5e-4."""
    power = 10.0 ** round(math.log10(factor))
    return power if math.isclose(factor, power, rel_tol=_FACTOR_TOLERANCE) else factor
