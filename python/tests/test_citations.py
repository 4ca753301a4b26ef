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
# The planted tree's pages, in two parts so the check of this repository
# (which reads docs/ paths in tests too) does not look for them here.
DOCS = "docs" + "/"


def _tree(tmp_path: Path) -> Path:
    (tmp_path / "docs").mkdir()
    (tmp_path / "src").mkdir()
    (tmp_path / "cases").mkdir()
    (tmp_path / "docs" / "beam.md").write_text("# Beam\n\n## Symbols\n", encoding="utf-8")
    (tmp_path / "docs" / "good.md").write_text(
        "# Good\nSee [beam](beam.md#symbols), ![](beam.md), [web](https://example.org/x.md), [top](#good).\n",
        encoding="utf-8")
    return tmp_path


def test_a_clean_tree_has_no_findings(tmp_path):
    root = _tree(tmp_path)
    (root / "src" / "a.cpp").write_text(f"// Ilomäki I-5 ({DOCS}beam.md#symbols); writes results/summary.json\n",
                                        encoding="utf-8")
    assert list(check_citations.findings(str(root))) == []


def test_each_kind_of_fault_is_found_with_its_file_and_line(tmp_path):
    root = _tree(tmp_path)
    (root / "src" / "a.cpp").write_text(f"int x;\n// safe speed ({NOTES} section 3)\n// {DOCS}nowhere.md\n",
                                        encoding="utf-8")
    (root / "cases" / "c.toml").write_text(f"# see {SHARED}/sources\n", encoding="utf-8")
    (root / "docs" / "bad.md").write_text("Text.\nSee [missing](missing.md#x) and ![pic](img/none.png).\n",
                                          encoding="utf-8")
    found = list(check_citations.findings(str(root)))
    assert len(found) == 5, found
    assert any(f.startswith("src/a.cpp:2:") and "private notes" in f for f in found)
    assert any(f.startswith("src/a.cpp:3:") and f"{DOCS}nowhere.md" in f for f in found)
    assert any(f.startswith("cases/c.toml:1:") and "private notes" in f for f in found)
    assert any(f.startswith(f"{DOCS}bad.md:2:") and "missing.md#x" in f for f in found)
    assert any(f.startswith(f"{DOCS}bad.md:2:") and "img/none.png" in f for f in found)


def test_a_stale_docs_path_is_found_in_tests_too_but_not_their_made_up_inputs(tmp_path):
    root = _tree(tmp_path)
    (root / "tests").mkdir()
    (root / "tests" / "test_a.cpp").write_text(
        f"// measured in {DOCS}beam.md\n// reads cases/made-up.toml\n// as in {DOCS}moved.md\n", encoding="utf-8")
    found = list(check_citations.findings(str(root)))
    assert len(found) == 1, found
    assert found[0].startswith("tests/test_a.cpp:3:") and f"{DOCS}moved.md" in found[0]


def test_a_section_the_page_does_not_have_is_found(tmp_path):
    root = _tree(tmp_path)
    (root / DOCS / "beam.md").write_text("# Beam\n\n## The `[beam]` table: symbols\n```toml\n# not a heading\n```\n",
                                         encoding="utf-8")
    (root / "src" / "a.cpp").write_text(f"// {DOCS}beam.md#the-beam-table-symbols\n// {DOCS}beam.md#symbols\n",
                                        encoding="utf-8")
    (root / DOCS / "good.md").write_text(
        "# Good\n[a](beam.md#the-beam-table-symbols) [b](#good) [c](beam.md#not-a-heading)\n", encoding="utf-8")
    found = list(check_citations.findings(str(root)))
    assert len(found) == 2, found
    assert any(f.startswith("src/a.cpp:2:") and "#symbols" in f for f in found)
    assert any(f.startswith(f"{DOCS}good.md:2:") and "#not-a-heading" in f for f in found)


def test_this_repository_cites_only_what_it_holds():
    found = list(check_citations.findings(str(REPO)))
    assert found == [], "\n".join(found)
