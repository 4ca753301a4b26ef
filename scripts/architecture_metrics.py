#!/usr/bin/env python3
"""Measures what docs/architecture.md claims about src/ (issue 34).

    python3 scripts/architecture_metrics.py [ROOT] [--max-level-comparisons N] [--max-level-switches N]
                                            [--max-circles N] [--max-long-files N] [--max-long-functions N]
                                            [--max-loss-factor-files N]

Prints three things about ROOT/src (ROOT: the repository, default the one
this script is in):

1. Branches on the model level outside the one place that chooses a level
   (src/models/choose.cpp); comments do not count, file:line for each.
   Comparisons: a string literal "beam", "harmonic", "coupled", "solid" or
   "solid3d", or a level of the enum (ModelChoice::beam, ...; not
   ModelChoice::automatic, which is the user's "auto", not a level), on
   either side of == or !=, and "solid3d" anywhere. Switches: each
   `case ModelChoice::<level>:` label, counted apart (--max-level-switches):
   per-level code an analysis still dispatches to itself, where a level
   object would provide it (issue 34).
2. Include circles between src/ folders: the graph of top-level folders
   (src/<folder>/...) with an edge A -> B for every `#include "B/..."` in a
   file of A; every strongly connected component of more than one folder,
   with one include per edge inside it as evidence. The count the ratchet
   checks is the number of such edges (an edge inside a component lies on a
   circle; removing it can only shrink the circles).
3. Sizes: lines per file (.cpp and .hpp) and per function body (median, 90th
   percentile, max; files over 500 lines, functions over 60 lines).
4. The proof effect (issue 34: "adding an effect touches <= 8 files"): the
   files under src/ whose text (comments too) names the structural loss
   factor, its physics or its term, case-insensitive "loss.factor",
   "hysteretic" or "structural.damping" (the same count as
   `git grep -l -i -E "loss.factor|hysteretic|structural.damping" -- src`).

The function parser is a brace matcher, not a C++ parser. With comments,
string and character literals blanked out, a `{` opens a function body when
it appears at namespace or class scope and the text before it since the last
`;`, `{` or `}` ends with `)` followed only by qualifiers (const, noexcept,
override, final, mutable, &, &&, a trailing return type) or is a
constructor's initializer list. A function's size is its body: the lines
from its opening brace to its closing brace, both included. Lambdas and
local classes count towards the function that holds them; a lambda assigned
at namespace scope counts as a function; code hidden in macros is not seen.

Exit status 0, or 1 when a count is above its --max-... (CI ratchets them
down: set each maximum to today's count, so the numbers can only fall).
"""

import argparse
import re
import statistics
import sys
from pathlib import Path

LEVEL_NAMES = ("beam", "harmonic", "coupled", "solid", "solid3d")
CHOOSER = "src/models/choose.cpp"
LONG_FILE = 500
LONG_FUNCTION = 60

_LEVEL = "|".join(LEVEL_NAMES)
_ENUM_LEVEL = r"ModelChoice::(?:beam|harmonic|coupled|solid)\b"
LEVEL_COMPARISON = re.compile(r'(?:==|!=)\s*"(?:%s)"|"(?:%s)"\s*(?:==|!=)|"solid3d"|(?:==|!=)\s*%s|%s\s*(?:==|!=)' %
                              (_LEVEL, _LEVEL, _ENUM_LEVEL, _ENUM_LEVEL))
LEVEL_SWITCH = re.compile(r"\bcase\s+%s\s*:" % _ENUM_LEVEL)
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"/]+)/[^"]*"')
QUALIFIERS = re.compile(
    r"\)\s*(?:(?:const|noexcept(?:\s*\([^()]*\))?|override|final|mutable|&&|&|volatile)\s*)*"
    r"(?:->\s*[\w:<>,\s\*&]+)?\s*$")
CONTROL = re.compile(r"\b(?:if|for|while|switch|catch|do|else|try)\s*(?:\(|$)")
SCOPE = re.compile(r"(?:^|\s)(namespace|class|struct|union|enum)\b")
LOSS_FACTOR = re.compile(r"loss.factor|hysteretic|structural.damping", re.IGNORECASE)


def blank(text, keep_strings):
    """The text with comments (and, unless keep_strings, string and character
    literals) replaced by spaces; newlines are kept so that lines still count."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delimiter = ")" + text[i + 2:open_paren] + '"'
            j = text.find(delimiter, open_paren)
            j = n if j < 0 else j + len(delimiter)
            literal = text[i:j]
            out.append(literal if keep_strings else re.sub(r"[^\n]", " ", literal))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            literal = text[i:j]
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(c)
                i += 1
                continue
            out.append(literal if keep_strings else c + " " * (len(literal) - 2) + c if len(literal) >= 2 else literal)
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def source_files(root):
    return sorted(p for p in (root / "src").rglob("*") if p.suffix in (".cpp", ".hpp") and p.is_file())


def level_comparisons(root, files, pattern=LEVEL_COMPARISON):
    found = []
    for path in files:
        rel = path.relative_to(root).as_posix()
        if rel == CHOOSER:
            continue
        code = blank(path.read_text(encoding="utf-8", errors="replace"), keep_strings=True)
        for number, line in enumerate(code.splitlines(), 1):
            count = len(pattern.findall(line))
            if count:
                found.append((rel, number, count, line.strip()))
    return found


def include_graph(root, files):
    """{folder: {included folder: (file, line)}}: one include per edge as evidence."""
    folders = {p.name for p in (root / "src").iterdir() if p.is_dir()}
    graph = {f: {} for f in sorted(folders)}
    for path in files:
        rel = path.relative_to(root / "src")
        if len(rel.parts) < 2:
            continue
        source = rel.parts[0]
        for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if m and m.group(1) in folders and m.group(1) != source:
                graph[source].setdefault(m.group(1), ("src/" + rel.as_posix(), number))
    return graph


def strongly_connected(graph):
    """Tarjan's algorithm; components of more than one node, each sorted."""
    index, low, on_stack, stack, out = {}, {}, set(), [], []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    sys.setrecursionlimit(max(1000, 10 * len(graph)))
    for v in graph:
        if v not in index:
            visit(v)
    return sorted(out)


def function_sizes(code):
    """[(first line, lines)] of the function bodies in blanked code (see the module's note)."""
    sizes = []
    scopes = []  # "namespace" / "class" / "other" for each open brace outside functions
    header_start = 0
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        if c in ";":
            header_start = i + 1
        elif c == "}":
            if scopes:
                scopes.pop()
            header_start = i + 1
        elif c == "{":
            header = code[header_start:i]
            flat = " ".join(header.split())
            in_init_list = re.search(r"\)\s*(?:noexcept\s*)?:(?!:)", flat) is not None
            before = flat[-1:] if flat else ""
            if in_init_list and (before.isalnum() or before in "_>"):
                i = matching(code, i) + 1  # a member's brace initializer: still the header
                continue
            at_outer_scope = all(s in ("namespace", "class") for s in scopes)
            scope = SCOPE.search(flat)
            if at_outer_scope and (QUALIFIERS.search(flat) or in_init_list) and not CONTROL.search(flat) \
                    and not (scope and scope.group(1) in ("namespace",)):
                end = matching(code, i)
                first = code.count("\n", 0, i) + 1
                sizes.append((first, code.count("\n", i, end) + 1))
                i = end + 1
                header_start = i
                continue
            if scope and scope.group(1) == "namespace" or flat.startswith('extern "C"') or flat == "extern":
                scopes.append("namespace")
            elif scope and "(" not in flat.split(scope.group(1), 1)[1] and "=" not in flat:
                scopes.append("class")
            else:
                scopes.append("other")
            header_start = i + 1
        elif c == ":" and re.search(r"\b(?:public|private|protected)\s*$", code[header_start:i]):
            header_start = i + 1  # an access specifier ends a class member's header
        i += 1
    return sizes


def matching(code, open_index):
    depth = 0
    for j in range(open_index, len(code)):
        if code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    return len(code) - 1


def percentile(values, q):
    ordered = sorted(values)
    if not ordered:
        return 0
    k = (len(ordered) - 1) * q
    low = int(k)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (k - low)


def describe(values):
    return "median %g, 90th percentile %g, max %d" % (statistics.median(values), round(percentile(values, 0.9), 1),
                                                       max(values))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=str(Path(__file__).resolve().parent.parent))
    parser.add_argument("--max-level-comparisons", type=int, default=None,
                        help="fail when there are more comparisons of level names than this")
    parser.add_argument("--max-level-switches", type=int, default=None,
                        help="fail when more case labels switch on the level than this")
    parser.add_argument("--max-circles", type=int, default=None,
                        help="fail when more include edges between folders lie on a circle than this")
    parser.add_argument("--max-long-files", type=int, default=None,
                        help="fail when more files than this are over %d lines" % LONG_FILE)
    parser.add_argument("--max-long-functions", type=int, default=None,
                        help="fail when more function bodies than this are over %d lines" % LONG_FUNCTION)
    parser.add_argument("--max-loss-factor-files", type=int, default=None,
                        help="fail when more source files than this name the structural loss factor")
    args = parser.parse_args(argv)
    root = Path(args.root).resolve()
    files = source_files(root)
    if not files:
        print("architecture_metrics: no .cpp or .hpp files under %s/src" % root, file=sys.stderr)
        return 1

    comparisons = level_comparisons(root, files)
    n_comparisons = sum(count for _, _, count, _ in comparisons)
    print("1. level-name comparisons outside %s: %d in %d files" %
          (CHOOSER, n_comparisons, len({f for f, _, _, _ in comparisons})))
    for f, line, count, text in comparisons:
        print("   %s:%d: %s%s" % (f, line, "(x%d) " % count if count > 1 else "", text[:110]))

    switches = level_comparisons(root, files, LEVEL_SWITCH)
    n_switches = sum(count for _, _, count, _ in switches)
    print("   level switches (case labels) outside %s: %d in %d files" %
          (CHOOSER, n_switches, len({f for f, _, _, _ in switches})))
    for f, line, count, text in switches:
        print("   %s:%d: %s" % (f, line, text[:110]))

    graph = include_graph(root, files)
    components = strongly_connected(graph)
    circle_edges = [(a, b, graph[a][b]) for c in components for a in c for b in sorted(graph[a]) if b in c]
    print("2. include circles between src/ folders: %d strongly connected components, %d include edges on circles" %
          (len(components), len(circle_edges)))
    for c in components:
        print("   {%s}" % ", ".join(c))
        for a, b, (f, line) in circle_edges:
            if a in c:
                print("     %s -> %s  (%s:%d)" % (a, b, f, line))

    file_lines, functions = [], []
    for path in files:
        text = path.read_text(encoding="utf-8", errors="replace")
        rel = path.relative_to(root).as_posix()
        file_lines.append((text.count("\n") + (0 if text.endswith("\n") else 1), rel))
        functions += [(size, "%s:%d" % (rel, first)) for first, size in function_sizes(blank(text, False))]
    long_files = sorted((n, f) for n, f in file_lines if n > LONG_FILE)[::-1]
    long_functions = sorted((n, f) for n, f in functions if n > LONG_FUNCTION)[::-1]
    print("3. sizes: %d files, %d lines; files: %s lines; functions (%d bodies): %s lines" %
          (len(file_lines), sum(n for n, _ in file_lines), describe([n for n, _ in file_lines]), len(functions),
           describe([n for n, _ in functions])))
    print("   files over %d lines: %d" % (LONG_FILE, len(long_files)))
    for n, f in long_files:
        print("     %5d  %s" % (n, f))
    print("   functions over %d lines: %d" % (LONG_FUNCTION, len(long_functions)))
    for n, f in long_functions:
        print("     %5d  %s" % (n, f))

    loss_files = sorted(path.relative_to(root).as_posix() for path in files
                        if LOSS_FACTOR.search(path.read_text(encoding="utf-8", errors="replace")))
    print("4. files naming the structural loss factor (the proof effect): %d" % len(loss_files))
    for f in loss_files:
        print("     %s" % f)

    failed = False
    for name, count, limit in (("level-name comparisons", n_comparisons, args.max_level_comparisons),
                               ("level switch labels", n_switches, args.max_level_switches),
                               ("include edges on circles", len(circle_edges), args.max_circles),
                               ("files over %d lines" % LONG_FILE, len(long_files), args.max_long_files),
                               ("functions over %d lines" % LONG_FUNCTION, len(long_functions),
                                args.max_long_functions),
                               ("files naming the loss factor", len(loss_files), args.max_loss_factor_files)):
        if limit is not None and count > limit:
            print("architecture_metrics: %d %s, above the maximum %d: remove them rather than raise it" %
                  (count, name, limit), file=sys.stderr)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
