#!/usr/bin/env python3
# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks the documents against the results files and the examples (python3, standard library).

Run from anywhere: python3 scripts/check_docs.py [--root DIR] (DIR: the repository, by default
the one holding this script). Prints one line per problem, "file:line: what", and exits with
status 1 if there is any, 0 otherwise. Takes about a second.

Documents: README.md, benchmark/README.md and doc/Delaunay_from_prediction/*.txt (the manual,
the package description, the list of examples). Results files: the files of
benchmark/Delaunay_from_prediction/results/.

1. Results files named exist. A results file is named by a path containing `results/` (in
   prose, in code, or as a Markdown link) or by a bare name ending in .txt or .csv (other than
   the package's own text files and the papers' file names, listed in NOT_RESULTS). A name
   followed by "(and `.csv`)" also names the .csv file. Names with wildcards (`*`, `{`) are
   refused: a document names each file it means. The arguments of
   --csv, --out and -o are output names, not citations. In README.md and benchmark/README.md,
   every Markdown link to a local file must point to an existing file.

2. Figures come from the results files cited. The documents are cut into units: a paragraph
   (the lines between blank lines, its list items included), a table (consecutive lines
   starting with "|"), a heading (not checked). Code (``` fences, 4-space indented blocks in
   Markdown, \\code ... \\endcode, \\verbatim ... \\endverbatim, `code spans`, even over a line
   break), link targets, and the arguments of \\ref, \\image, \\cgalExample and \\cgalBigO hold
   no figures: a constant of the code (a threshold such as `max_flips / 1.35`) is written as
   code. A paragraph cites the results files it names; a table cites those it names and those
   of the paragraphs just before and just after it (its caption and its note).
   A figure is
     - a decimal number with a fraction: 3.91, 0.0068 (a ratio 1.23x is the figure 1.23; the two
       ends of a range 1.22-1.54 are two figures; 0.32% is the figure 0.32);
     - a count written with thousands separators: 160,845 (the figure 160845).
   Not figures (exempt): integers written without separators (sizes, thresholds, counts such as
   4096 or 655, integer percentages such as 10-30%); numbers written as powers or in exponent
   form (1e6, 10^6, 2^{16}, and the mantissa of 6.5 \\cdot 10^4 or 2 \\times 10^5); version
   numbers (any a.b.c, and the number after g++, gcc, CGAL, \\cgal, gmsh, doxygen, Debian,
   Python, numpy, scipy, pybind11, oneTBB, TBB, MPI, MathJax, CMake, PEP); the numbers of the
   paper's parts (after Theorem, Lemma, Corollary, Section, Appendix, Figure, Table, Step,
   Remark, Claim, Definition or their plurals, with the numbers listed after them joined by
   ",", "and", "or", "to" or "-"); a clock rate (a number before GHz); the version in GPL-3.0;
   the cells of a table column whose header says "paper" (the paper's own figures, quoted
   beside ours).
   Rules:
     a. In a unit that cites results files, every figure appears in at least one of them at
        the digits shown: the file holds the same characters as a number (thousands separators
        ignored, so 160,845 matches 160845; 1.3 does not match 1.30, nor 0.168 0.1684).
     b. A unit that cites no results file must have no figure if it speaks of measurements:
        if it holds one of MEASURE_WORDS (measured, faster, slower, ratio, median, took, speed,
        times as long, times CGAL's, times a rebuild, us, ns, ms, MiB, MB, GB, seconds, a number
        followed by " s", per point, a point). So every measured figure comes from a results
        file named next to it.
     c. Every row of a table has as many cells as its header, and ends with "|" if the header
        does.

3. The README's first C++ example is examples/Delaunay_from_prediction/first_program.cpp: the
   first ```cpp block of README.md equals that file from its first line starting with
   "#include" to its end (the excerpt leaves out only the file's leading comment, its licence
   header), and the file is listed in examples/Delaunay_from_prediction/CMakeLists.txt (so that
   the tests compile and run it) and in doc/Delaunay_from_prediction/examples.txt.

4. No history: none of HISTORY_PATTERNS (this version, in this release, not done yet, not yet
   done/implemented/measured, currently, for now, at the moment, the current code/headers/tree/
   program/version/implementation, earlier/older/old/previous/former/reference/refactored/tested/
   new code/headers/version/implementation, reference implementation, refactor(ed), restructured,
   code of <year>, "that X is gone", not explained yet, issue or stop numbers, #NN, commit
   hashes, ISO dates) in the documents, every doc/**/*.txt, the headers (include/**/*.h) and the
   Python module's sources; none of HISTORY_NAME_WORDS (reference, refactor(ed), previous, old,
   new, other, rerun, current, earlier, later, before, after, first, second, version, commit,
   code, inline, early, handover) among the words of a results file's name; no commit hash or
   word "commit" anywhere in a results file (results files keep their dates). Documents say what
   the code does, not how it came to be. The headers and the module's sources name only results
   files that exist (`results/NAME.txt` or `.csv` in a comment).

What it cannot see: whether a sentence is true of the code, integer figures and percentages,
figures derived from a file by hand (a reciprocal, a quotient of two columns: write the file's
own numbers instead), and numbers in the headers' comments other than history.
"""

import argparse
import os
import re
import sys

DOCS = ["README.md", "benchmark/README.md"]
MANUAL_DIR = "doc/Delaunay_from_prediction"
RESULTS_DIR = "benchmark/Delaunay_from_prediction/results"
EXAMPLE = "examples/Delaunay_from_prediction/first_program.cpp"
EXAMPLES_CMAKE = "examples/Delaunay_from_prediction/CMakeLists.txt"
EXAMPLES_LIST = "doc/Delaunay_from_prediction/examples.txt"
SOURCES_FOR_HISTORY = ["include", "examples/Delaunay_from_prediction/python"]

# Text files named in the documents that are not results files.
NOT_RESULTS = {
    "CMakeLists.txt", "description.txt", "long_description.txt", "license.txt", "examples.txt",
    "PackageDescription.txt", "Delaunay_from_prediction.txt", "copyright", "maintainer",
    # the papers, as the manual names them
    "delaunay_with_predictions.txt", "delaunay_imprecise_points_disks.txt",
    "splitting_delaunay_linear_time.txt", "brio_dc_nng_linear_time.txt",
}

HISTORY_PATTERNS = [
    r"\bthis version\b", r"\bin this release\b", r"\bnot done yet\b", r"\bnot yet (?:done|implemented|measured)\b",
    r"\bcurrently\b", r"\bfor now\b", r"\bat the moment\b",
    r"\b(?:the )?current (?:code|headers?|tree|program|version|implementation|state)\b",
    r"\b(?:earlier|older|old|previous|former|reference|refactored|tested|new) (?:code|headers?|versions?|implementation|tree)\b",
    r"\breference implementation\b", r"\brefactor(?:ed|ing)?\b", r"\brestructur(?:ed|ing)\b",
    r"\bcode of 20\d\d", r"\b(?:that|this|the old) \w+ (?:is|are) gone\b", r"\bnot explained yet\b",
    r"\bissues? #?\d+\b", r"\bstops? #?\d+\b", r"#\d{2,}\b",
    r"\bcommit\s+[0-9a-f]{7,40}\b", r"\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b",
    r"\b20\d\d-\d\d-\d\d\b",
]
HISTORY_RE = re.compile("|".join(HISTORY_PATTERNS), re.IGNORECASE)
# Words that make a results file's name say which code it ran rather than what it measures.
HISTORY_NAME_WORDS = {
    "reference", "refactor", "refactored", "previous", "old", "new", "other", "rerun", "current",
    "earlier", "later", "before", "after", "first", "second", "version", "commit", "code", "inline",
    "early", "handover",
}
RESULTS_COMMIT_RE = re.compile(r"\bcommits?\b|\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b", re.IGNORECASE)

MEASURE_WORDS = re.compile(
    r"\bmeasured\b|\bmeasurements?\b|faster|slower|\bratios?\b|\bmedians?\b|\btook\b|\bspeed|\btimes (?:as long|as fast|faster|slower|\\cgal|cgal|the speed|the time|a rebuild|its (?:time|speed))"
    r"|\b(?:us|ns|ms|MiB|MB|GB)\b|\bseconds?\b|\d s\b|\bper point\b|\ba point\b",
    re.IGNORECASE)

FIGURE_RE = re.compile(r"(?<![\w.])(?<![A-Za-z]-)(\d{1,3}(?:,\d{3})+(?!\d)(?:\.\d+)?|\d+\.\d+)(?![\w.]*\d)")
NUMBER_RE = re.compile(r"\d{1,3}(?:,\d{3})+(?![\d])(?:\.\d+)?|\d+(?:\.\d+)?")
VERSION_WORDS = r"(?:g\+\+|gcc|CGAL|\\cgal|gmsh|doxygen|Debian|Python|python3?|numpy|scipy|pybind11|oneTBB|TBB|MPI|MathJax|cmake|CMake|PEP)"
PART_WORDS = r"(?:Theorems?|Lemmas?|Corollar(?:y|ies)|Sections?|Appendix|Appendices|Figures?|Tables?|Steps?|Remarks?|Claims?|Definitions?)"
PART_CHAIN_RE = re.compile(PART_WORDS + r"\s+[A-Z]?\d+(?:\.\d+)*(?:(?:\s*,\s*|\s+and\s+|\s+or\s+|\s*-\s*|\s+to\s+)[A-Z]?\d+(?:\.\d+)*)*")
VERSION_RE = re.compile(VERSION_WORDS + r"\s+\d+(?:\.\d+)+|\b\d+\.\d+\.\d+(?:\.\d+)*\b")
EXPONENT_RE = re.compile(r"\d+(?:\.\d+)?\s*(?:\\cdot|\\times)\s*10\^?\{?-?\d*\}?|\d+(?:\.\d+)?[eE][-+]?\d+|10\^\{?-?\d+\}?|\^\{[^}]*\}|\^-?\d+(?:\.\d+)?")
GHZ_RE = re.compile(r"\d+(?:\.\d+)?\s*GHz")

problems = []


def problem(path, line, what):
    problems.append(f"{path}:{line}: {what}")


def read(root, rel):
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        return f.read()


# ---------------------------------------------------------------- results files

class Results:
    def __init__(self, root):
        self.root = root
        self.dir = os.path.join(root, RESULTS_DIR)
        self.names = set(os.listdir(self.dir)) if os.path.isdir(self.dir) else set()
        self._numbers = {}

    def numbers(self, name):
        if name not in self._numbers:
            text = read(self.root, f"{RESULTS_DIR}/{name}")
            self._numbers[name] = {m.group(0).replace(",", "") for m in NUMBER_RE.finditer(text)}
        return self._numbers[name]


# ---------------------------------------------------------------- cutting documents into units

class Unit:
    def __init__(self, kind, start):
        self.kind = kind  # "text", "table", "heading"
        self.start = start  # first line number (1-based)
        self.lines = []  # (line number, text)

    def text(self):
        return "\n".join(t for _, t in self.lines)


def units_of(text, markdown):
    """Cuts a document into units; code blocks are left out (they separate units)."""
    units = []
    current = None
    in_code = None
    for number, line in enumerate(text.split("\n"), 1):
        stripped = line.strip()
        if in_code:
            if (in_code == "```" and stripped.startswith("```")) or (in_code != "```" and in_code in stripped):
                in_code = None
            current = None
            continue
        if stripped.startswith("```"):
            in_code = "```"
            current = None
            continue
        opener = re.search(r"\\(code|verbatim)\b", stripped)
        if opener:
            closer = "\\end" + opener.group(1)
            if closer not in stripped[opener.end():]:
                in_code = closer
            before = line[: line.find("\\" + opener.group(1))]
            if before.strip() and current is not None:
                current.lines.append((number, before))
            current = None
            continue
        if not stripped or stripped in ("/*!", "*/"):
            current = None
            continue
        if markdown and line.startswith("    ") and (current is None or current.kind != "text"):
            current = None  # an indented code block
            continue
        kind = "table" if stripped.startswith("|") else (
            "heading" if re.match(r"(#+\s|\\(?:main)?(?:page|section|subsection|subsubsection)\b)", stripped) else "text")
        if current is None or current.kind != kind or kind == "heading":
            current = Unit(kind, number)
            units.append(current)
        current.lines.append((number, line))
    return units


CODE_SPAN_RE = re.compile(r"`[^`\n]*`")
LINK_TARGET_RE = re.compile(r"\]\(([^)\s]*)\)")
DOXY_ARG_RE = re.compile(r"\\(?:ref|anchor|image html|cgalExample|cgalFigureBegin|cgalFigureRef|example)\s*\{?[^\s}]*\}?")


def cited_names(text):
    """Results-file names a unit's raw text cites, with the position of each."""
    names = []
    # output names of commands are not citations
    text = re.sub(r"(--csv|--out|-o)\s+[^\s`]+", r"\1 OUTPUT", text)
    for m in re.finditer(r"(?:[\w./-]*results/)([\w.*{}\-]+)|(?<![\w/.-])([\w.*{}-]+\.(?:txt|csv))\b", text):
        name = m.group(1) or m.group(2)
        if not m.group(1) and name in NOT_RESULTS:
            continue
        names.append((name, m.start()))
        tail = text[m.end(): m.end() + 20]
        if name.endswith(".txt") and re.match(r"`?\)?\s*\(and `\.csv`", tail):
            names.append((name[:-4] + ".csv", m.start()))
    return names


def paper_columns(header):
    cells = split_cells(header)
    return {i for i, c in enumerate(cells) if "paper" in c.lower()}


def split_cells(row):
    masked = re.sub(r"\\f\$.*?\\f\$", lambda m: "x" * len(m.group(0)), row)
    masked = CODE_SPAN_RE.sub(lambda m: "x" * len(m.group(0)), masked)
    masked = masked.replace("\\|", "xx")
    cells, start = [], 0
    positions = [i for i, c in enumerate(masked) if c == "|"]
    stripped = row.strip()
    for a, b in zip(positions, positions[1:]):
        cells.append(row[a + 1:b])
    if not stripped.endswith("|"):
        cells.append(row[positions[-1] + 1:] if positions else row)
    return cells


def blank_exempt(text):
    """`text` with its code, link targets and exempt numbers blanked (line breaks kept)."""
    blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))
    text = re.sub(r"`[^`]*`", blank, text)
    text = LINK_TARGET_RE.sub(blank, text)
    text = DOXY_ARG_RE.sub(blank, text)
    text = re.sub(r"\\(?:cgalBigO|cgalParam\w*|cgalPkg\w*)\{[^}]*\}", blank, text)
    for r in (EXPONENT_RE, VERSION_RE, PART_CHAIN_RE, GHZ_RE):
        text = r.sub(blank, text)
    return text


def figures_in(text):
    """The figures of a piece of text (see the header), with their offsets."""
    blank = lambda m: " " * len(m.group(0))
    text = CODE_SPAN_RE.sub(blank, text)
    text = LINK_TARGET_RE.sub(blank, text)
    text = DOXY_ARG_RE.sub(blank, text)
    text = re.sub(r"\\(?:cgalBigO|cgalParam\w*|cgalPkg\w*)\{[^}]*\}", blank, text)
    for r in (EXPONENT_RE, VERSION_RE, PART_CHAIN_RE, GHZ_RE):
        text = r.sub(blank, text)
    return [(m.group(1).replace(",", ""), m.group(1), m.start()) for m in FIGURE_RE.finditer(text)]


def check_document(root, rel, results, markdown):
    text = read(root, rel)
    units = units_of(text, markdown)
    base = os.path.dirname(rel)
    # 1. names and links
    for unit in units:
        for number, line in unit.lines:
            for name, _ in cited_names(line):
                if any(c in name for c in "*{}") or name.startswith("..") or name.endswith("_"):
                    problem(rel, number, f"names results files by a pattern ('{name}'): name each file")
                elif name not in results.names:
                    problem(rel, number, f"names the results file '{name}', which does not exist in {RESULTS_DIR}")
            for target in (LINK_TARGET_RE.findall(line) if markdown else []):
                if re.match(r"[a-z]+:", target) or target.startswith("#") or not target:
                    continue
                path = os.path.normpath(os.path.join(root, base, target.split("#")[0]))
                if not os.path.exists(path):
                    problem(rel, number, f"links to '{target}', which does not exist")
    # 2. figures
    for i, unit in enumerate(units):
        if unit.kind == "heading":
            continue
        cited = {n for _, l in unit.lines for n, _ in cited_names(l)}
        scope_text = unit.text()
        if unit.kind == "table":
            for j in (i - 1, i + 1):
                if 0 <= j < len(units) and units[j].kind == "text":
                    cited |= {n for _, l in units[j].lines for n, _ in cited_names(l)}
                    scope_text += "\n" + units[j].text()
        cited = {n for n in cited if n in results.names}
        measured = bool(MEASURE_WORDS.search(re.sub(r"`[^`]*`", "", scope_text)))
        skip_columns = set()
        header_cells = None
        # code spans and references like "Lemma\n5.2" may run over a line break: blank them in
        # the whole unit first
        masked = blank_exempt(unit.text()).split("\n")
        for k, (number, line) in enumerate(unit.lines):
            pieces = [line if unit.kind == "table" else masked[k]]
            if unit.kind == "table":
                cells = split_cells(line)
                if k == 0:
                    header_cells = len(cells)
                    header_closed = line.rstrip().endswith("|")
                    skip_columns = paper_columns(line)
                elif len(cells) != header_cells:
                    problem(rel, number, f"a table row with {len(cells)} cells under a header of {header_cells}")
                elif line.rstrip().endswith("|") != header_closed:
                    problem(rel, number, "a table row not closed by '|' as its header is")
                if k == 1:
                    continue
                pieces = [c for c_i, c in enumerate(cells) if c_i not in skip_columns]
            for piece in pieces:
                for value, shown, _ in figures_in(piece):
                    if cited:
                        if not any(value in results.numbers(n) for n in cited):
                            problem(rel, number, f"the figure {shown} is in none of the results files cited here "
                                                 f"({', '.join(sorted(cited))})")
                    elif measured:
                        problem(rel, number, f"the figure {shown} comes from no results file: this "
                                             f"{'table' if unit.kind == 'table' else 'paragraph'} cites none")
    # 4. history
    check_history(rel, text)


def check_history(rel, text, results=None):
    for number, line in enumerate(text.split("\n"), 1):
        for m in HISTORY_RE.finditer(line):
            problem(rel, number, f"history in the documentation: '{m.group(0)}' (describe what the code does)")
        if results is not None:  # a source's comments name results files that exist
            for m in re.finditer(r"\bresults/([\w.-]+\.(?:txt|csv))", line):
                if m.group(1) not in results.names:
                    problem(rel, number, f"names the results file '{m.group(1)}', which does not exist in {RESULTS_DIR}")


# ---------------------------------------------------------------- the README's first program

def check_first_program(root):
    readme = read(root, "README.md")
    m = re.search(r"^```cpp\n(.*?)^```", readme, re.MULTILINE | re.DOTALL)
    if not m:
        problem("README.md", 1, "no ```cpp block: the README's first screen shows the first program")
        return
    block_line = readme[: m.start()].count("\n") + 1
    path = os.path.join(root, EXAMPLE)
    if not os.path.exists(path):
        problem("README.md", block_line, f"the first C++ block must be {EXAMPLE}, which does not exist")
        return
    source = read(root, EXAMPLE)
    lines = source.split("\n")
    first = next((i for i, l in enumerate(lines) if l.startswith("#include")), None)
    if first is None:
        problem(EXAMPLE, 1, "has no #include line")
        return
    shown = "\n".join(lines[first:])
    if not shown.endswith("\n"):
        shown += "\n"
    if m.group(1) != shown:
        a, b = m.group(1).split("\n"), shown.split("\n")
        k = next((i for i in range(min(len(a), len(b))) if a[i] != b[i]), min(len(a), len(b)))
        problem("README.md", block_line + 1 + k,
                f"the first ```cpp block differs from {EXAMPLE} (from its first #include) at this line "
                f"(file line {first + 1 + k}): the README shows the file's lines exactly")
    stem = os.path.splitext(os.path.basename(EXAMPLE))[0]
    cmake = read(root, EXAMPLES_CMAKE)
    if not re.search(r"\b" + stem + r"\b", cmake):
        problem(EXAMPLES_CMAKE, 1, f"does not build {stem}.cpp: the tests must compile and run the README's program")
    if stem not in read(root, EXAMPLES_LIST):
        problem(EXAMPLES_LIST, 1, f"does not list {stem}.cpp")


# ---------------------------------------------------------------- results files: names and contents

def check_results(root, results):
    for name in sorted(results.names):
        words = set(re.split(r"[_.\-]", name.lower()))
        bad = sorted(words & HISTORY_NAME_WORDS)
        if bad:
            problem(f"{RESULTS_DIR}/{name}", 1,
                    f"the name says which code ran ({', '.join(bad)}), not what was measured: rename it or remove it")
        if name.endswith((".txt", ".csv")):
            for number, line in enumerate(read(root, f"{RESULTS_DIR}/{name}").split("\n"), 1):
                m = RESULTS_COMMIT_RE.search(line)
                if m:
                    problem(f"{RESULTS_DIR}/{name}", number, f"names a commit ('{m.group(0)}'): say what was measured")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    root = parser.parse_args().root
    results = Results(root)
    docs = list(DOCS) + sorted(f"{MANUAL_DIR}/{f}" for f in os.listdir(os.path.join(root, MANUAL_DIR)) if f.endswith(".txt"))
    for rel in docs:
        check_document(root, rel, results, markdown=rel.endswith(".md"))
    for rel in sorted({os.path.relpath(os.path.join(d, f), root)
                       for top in ["doc"] for d, _, fs in os.walk(os.path.join(root, top)) for f in fs
                       if f.endswith(".txt")} - set(docs)):
        check_history(rel, read(root, rel))
    for top in SOURCES_FOR_HISTORY:
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith((".h", ".py", ".cpp", ".toml")):
                    rel = os.path.relpath(os.path.join(d, f), root)
                    check_history(rel, read(root, rel), results)
    check_results(root, results)
    check_first_program(root)
    for p in problems:
        print(p)
    if problems:
        print(f"check_docs: {len(problems)} problem(s)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
