"""scripts/check_citations.py: every file a project file cites is in the
repository (docs/reference/references.md). Checked on a small tree with one planted
fault of each kind, then on this repository itself."""

from __future__ import annotations

import importlib.util
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location("check_citations", REPO / "scripts" / "check_citations.py")
check_citations = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(check_citations)

# The private notes' names, in two parts so this file does not cite them.
NOTES = "DOMAIN" + ".md"
SHARED = "../" + "shared"


def _tree(tmp_path: Path) -> Path:
    (tmp_path / "docs").mkdir()
    (tmp_path / "src").mkdir()
    (tmp_path / "cases").mkdir()
    (tmp_path / "docs" / "beam.md").write_text("# Beam\n", encoding="utf-8")
    (tmp_path / "docs" / "good.md").write_text(
        "See [beam](beam.md#symbols), ![](beam.md), [web](https://example.org/x.md), [top](#good).\n",
        encoding="utf-8")
    return tmp_path


def test_a_clean_tree_has_no_findings(tmp_path):
    root = _tree(tmp_path)
    (root / "src" / "a.cpp").write_text("// Ilomäki I-5 (docs/beam.md); writes results/summary.json\n",
                                        encoding="utf-8")
    assert list(check_citations.findings(str(root))) == []


def test_each_kind_of_fault_is_found_with_its_file_and_line(tmp_path):
    root = _tree(tmp_path)
    (root / "src" / "a.cpp").write_text(f"int x;\n// safe speed ({NOTES} section 3)\n// docs/nowhere.md\n",
                                        encoding="utf-8")
    (root / "cases" / "c.toml").write_text(f"# see {SHARED}/sources\n", encoding="utf-8")
    (root / "docs" / "bad.md").write_text("Text.\nSee [missing](missing.md#x) and ![pic](img/none.png).\n",
                                          encoding="utf-8")
    found = list(check_citations.findings(str(root)))
    assert len(found) == 5, found
    assert any(f.startswith("src/a.cpp:2:") and "private notes" in f for f in found)
    assert any(f.startswith("src/a.cpp:3:") and "docs/nowhere.md" in f for f in found)
    assert any(f.startswith("cases/c.toml:1:") and "private notes" in f for f in found)
    assert any(f.startswith("docs/bad.md:2:") and "missing.md#x" in f for f in found)
    assert any(f.startswith("docs/bad.md:2:") and "img/none.png" in f for f in found)


def test_this_repository_cites_only_what_it_holds():
    found = list(check_citations.findings(str(REPO)))
    assert found == [], "\n".join(found)
