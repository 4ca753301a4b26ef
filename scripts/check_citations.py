#!/usr/bin/env python3
"""Fail if a project file cites a file that is not in the repository.

A reader of a comment, a case file, a doc page or a run's output must be able
to follow every source it names (docs/reference/references.md). This check finds
  - citations of the team's private notes (the domain notes and the shared
    folder beside the work trees), which no reader has;
  - relative links and images in Markdown pages that point nowhere, or to a
    section (page.md#section) the page does not have;
  - repository paths (docs/..., src/..., tests/..., cases/..., scripts/...,
    python/..., bench/...) named anywhere that do not exist; in tests, which
    name made-up input files, only docs/ paths (a page a test cites or reads);
  - a section named after a docs path (a page, then #section) that the page
    does not have.
Usage: check_citations.py [REPO_ROOT]; prints each finding as file:line: what,
exits 1 if there is any, 0 otherwise. Run by ctest as `citations`.
"""
import os
import re
import sys

# The directories and files whose text a user reads (the build tree and git's
# own files are not).
SCANNED = ["src", "docs", "cases", "python", "scripts", "bench", "tests", "fuzz", ".ci", "README.md", "CMakeLists.txt"]
TEXT_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".py", ".md", ".toml", ".txt", ".sh", ".cmake", ".json", ".cfg", ".geo", ".yml", ".yaml", ""}

# Written in two parts so that this file does not cite them itself.
PRIVATE_NOTES = [re.compile(p) for p in (r"DOMAIN" r"\.md", r"\.\./" r"shared\b", r"/work/" r"shared\b", r"\bshared/" r"(?:sources|DESIGN|STYLE)")]

# A repository path: a top-level folder, then path characters, ending in a
# file name with an extension (a folder alone is not checked).
REPO_PATH = re.compile(r"(?<![\w./-])((?:docs|src|tests|cases|scripts|python|bench|fuzz|meshes)/[\w./+-]*\w\.[A-Za-z0-9]+)(#[\w-]+)?")
# A Markdown link or image target: [text](target) or ![alt](target).
MD_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
# Paths that name what a command writes, a pattern, or an example a user
# writes (cases/x.toml, cases/10.toml in an error message), not a repository file.
GENERATED = re.compile(r"(^|/)(build|results?|out|runs?)/|[*?{}<>$]|\.\.\.|^cases/\w{1,2}\.toml$")
# Tests name made-up paths for their inputs: only private notes and docs/
# pages are looked for there.
PATHS_NOT_CHECKED = ("tests" + os.sep, os.path.join("python", "tests") + os.sep)
# A Markdown heading, outside fenced code.
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")


def anchor(heading):
    """The section name GitHub gives a heading: lower case, punctuation
    dropped, spaces to hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


_anchors = {}


def anchors_of(path):
    """Every section name of a Markdown page (duplicates numbered -1, -2 as GitHub does)."""
    if path not in _anchors:
        names, fenced = set(), False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.lstrip().startswith("```"):
                    fenced = not fenced
                    continue
                match = None if fenced else HEADING.match(line)
                if match:
                    name = anchor(match.group(1))
                    numbered, n = name, 0
                    while numbered in names:
                        n += 1
                        numbered = f"{name}-{n}"
                    names.add(numbered)
        _anchors[path] = names
    return _anchors[path]


def missing_section(path, section):
    """Whether a Markdown page lacks the section a link names."""
    return bool(section) and path.endswith(".md") and os.path.isfile(path) and section not in anchors_of(path)


def text_files(root):
    for entry in SCANNED:
        path = os.path.join(root, entry)
        if os.path.isfile(path):
            yield path
            continue
        for folder, dirs, files in os.walk(path):
            dirs[:] = [d for d in dirs if d not in ("__pycache__", ".pytest_cache", "build")]
            for name in files:
                if os.path.splitext(name)[1] in TEXT_SUFFIXES:
                    yield os.path.join(folder, name)


def findings(root):
    for path in sorted(text_files(root)):
        rel = os.path.relpath(path, root)
        if rel.startswith(os.path.join("python", "tests", "data")) or rel.startswith("tests" + os.sep + "fuzz_regressions"):
            continue
        try:
            with open(path, encoding="utf-8") as f:
                lines = f.read().split("\n")
        except UnicodeDecodeError:
            continue  # a binary file
        is_markdown = path.endswith(".md")
        for number, line in enumerate(lines, 1):
            where = f"{rel}:{number}"
            private = [m.group(0) for m in (p.search(line) for p in PRIVATE_NOTES) if m]
            if private:
                yield f"{where}: cites the team's private notes ({private[0]}); cite the published source or a docs/ page (docs/reference/references.md)"
            in_tests = rel.startswith(PATHS_NOT_CHECKED)
            for match in REPO_PATH.finditer(line):
                target = match.group(1).rstrip(".")
                if GENERATED.search(target) or (in_tests and not target.startswith("docs/")):
                    continue
                if not os.path.exists(os.path.join(root, target)):
                    yield f"{where}: names {target}, which is not in the repository"
                elif missing_section(os.path.join(root, target), (match.group(2) or "#")[1:]):
                    yield f"{where}: names {target}{match.group(2)}, a section {target} does not have"
            if is_markdown:
                for match in MD_LINK.finditer(line):
                    target, _, section = match.group(1).partition("#")
                    if re.match(r"^[a-z]+:", target) or GENERATED.search(target):
                        continue
                    resolved = os.path.normpath(os.path.join(os.path.dirname(path), target)) if target else path
                    if not os.path.exists(resolved):
                        yield f"{where}: links to {match.group(1)}, which is not in the repository"
                    elif missing_section(resolved, section):
                        yield f"{where}: links to {match.group(1)}, a section the page does not have"


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    found = list(findings(root))
    for f in found:
        print(f)
    if found:
        print(f"{len(found)} citation(s) a reader cannot follow", file=sys.stderr)
        return 1
    print("every cited file is in the repository")
    return 0


if __name__ == "__main__":
    sys.exit(main())
