"""scripts/architecture_metrics.py: the counts docs/architecture.md quotes.
Checked on a small tree whose level comparisons, include circles and
function lengths are known by construction."""

from __future__ import annotations

import importlib.util
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location("architecture_metrics", REPO / "scripts" / "architecture_metrics.py")
metrics = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(metrics)

# A function of 5 body lines, with braces in a comment, a string, a char
# literal, a raw string and a lambda, and a constructor with brace
# initializers: none of them may end a body early or count as a function.
TRICKY = '''namespace a {
struct S {
    int x_, y_;
    S(int x) : x_{x}, y_(x) {
        y_ = 2;
    }
    int get() const { return x_; }
};
// not a function { }
int f(int v) {
    const char* s = "}";  // }
    auto g = [](int w) { return w; };
    char c = '{'; const char* r = R"(}})";
    return g(v);
}
}  // namespace a
'''


def _tree(tmp_path: Path) -> Path:
    src = tmp_path / "src"
    for folder in ("models", "output", "scene", "effects", "common"):
        (src / folder).mkdir(parents=True)
    (src / "models" / "choose.cpp").write_text('bool b(const std::string& l) { return l == "beam"; }\n')
    (src / "models" / "level.cpp").write_text('#include "output/report.hpp"\n'
                                              'bool h(const std::string& l) { return l == "harmonic"; }\n'
                                              '// l == "solid" in a comment does not count\n')
    (src / "output" / "report.hpp").write_text('#include "models/level.hpp"\n#include "common/x.hpp"\n'
                                               'const char* k = "solid3d";\n'
                                               'bool t(const std::string& l) { return "coupled" != l && l == "solid"; }\n')
    (src / "scene" / "scene.cpp").write_text('#include "effects/e.hpp"\n#include "common/x.hpp"\n')
    (src / "effects" / "e.hpp").write_text('#include "scene/scene.hpp"\n')
    (src / "common" / "x.hpp").write_text(TRICKY)
    return tmp_path


def test_level_comparisons_outside_the_chooser(tmp_path):
    root = _tree(tmp_path)
    found = metrics.level_comparisons(root, metrics.source_files(root))
    counts = {(f, line): n for f, line, n, _ in found}
    # choose.cpp is the one place allowed; the comment is not code.
    assert counts == {("src/models/level.cpp", 2): 1, ("src/output/report.hpp", 3): 1,
                      ("src/output/report.hpp", 4): 2}


def test_include_circles_with_their_evidence(tmp_path):
    root = _tree(tmp_path)
    graph = metrics.include_graph(root, metrics.source_files(root))
    assert metrics.strongly_connected(graph) == [["effects", "scene"], ["models", "output"]]
    assert graph["models"]["output"] == ("src/models/level.cpp", 1)
    assert graph["output"]["common"] == ("src/output/report.hpp", 2)  # an edge, but on no circle


def test_function_bodies_by_brace_matching():
    sizes = metrics.function_sizes(metrics.blank(TRICKY, keep_strings=False))
    # The constructor (lines 4-6), the one-line member (7) and f (10-15).
    assert sizes == [(4, 3), (7, 1), (10, 6)]


def test_the_ratchet_fails_only_above_its_maximum(tmp_path, capsys):
    root = _tree(tmp_path)
    assert metrics.main([str(root), "--max-level-comparisons", "4", "--max-circles", "4"]) == 0
    out = capsys.readouterr().out
    assert "1. level-name comparisons outside src/models/choose.cpp: 4 in 2 files" in out
    assert "2 strongly connected components, 4 include edges on circles" in out
    assert metrics.main([str(root), "--max-level-comparisons", "3"]) == 1
    assert metrics.main([str(root), "--max-circles", "3"]) == 1
    assert "remove them rather than raise it" in capsys.readouterr().err


def test_the_enum_levels_count_as_comparisons_and_switches(tmp_path):
    # Comparing with an enum level is a branch on the level like comparing
    # with its word; "automatic" is the user's "auto", not a level.
    src = tmp_path / "src" / "analyses"
    src.mkdir(parents=True)
    (src / "a.cpp").write_text("bool a(ModelChoice l) { return l == ModelChoice::coupled; }\n"
                               "bool b(ModelChoice l) { return ModelChoice::solid != l; }\n"
                               "bool c(ModelChoice l) { return l == ModelChoice::automatic; }\n"
                               "int d(ModelChoice l) {\n"
                               "    switch (l) {\n"
                               "        case ModelChoice::beam: return 1;\n"
                               "        case ModelChoice::harmonic:\n"
                               "        case ModelChoice::automatic: return 2;\n"
                               "        default: return 0;\n"
                               "    }\n"
                               "}\n")
    files = metrics.source_files(tmp_path)
    assert [(line, n) for _, line, n, _ in metrics.level_comparisons(tmp_path, files)] == [(1, 1), (2, 1)]
    switches = metrics.level_comparisons(tmp_path, files, metrics.LEVEL_SWITCH)
    assert [(line, n) for _, line, n, _ in switches] == [(6, 1), (7, 1)]
    assert metrics.main([str(tmp_path), "--max-level-switches", "1"]) == 1
    assert metrics.main([str(tmp_path), "--max-level-switches", "2", "--max-level-comparisons", "2"]) == 0
