#!/usr/bin/env python3
"""Fails when the documentation has drifted from the code it describes
(issue 22: "docs the build keeps true"). Run by ctest (test docs_in_sync)
and by hand: python3 scripts/check_docs.py. Three checks:

1. docs/architecture.md's include table: for every row that lists folders,
   the folders are exactly those its files include (`#include "folder/...`),
   the row's own folder aside; words in parentheses are notes.
2. Every `enum class NAME` and `struct NAME` shown in docs/*.md or README.md
   is declared in a header of the repository (a copied struct that was
   renamed or removed is caught; its fields are not compared, so docs
   should point at the header rather than copy it).
3. README's fuzzing rates are those of the last "formulas/s/core" table of
   docs/performance.md, the one place they come from.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
problems = []


def read(path):
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        return f.read()


def sources(folder):
    for root, dirs, files in os.walk(os.path.join(ROOT, folder)):
        dirs[:] = [d for d in dirs if d not in ("data",)]
        for name in files:
            if name.endswith((".cpp", ".hpp")):
                yield os.path.join(root, name)


def check_include_table():
    doc = read("docs/architecture.md")
    rows = re.findall(r"^\| `([a-z_/]+)/` \| (.*) \|$", doc, re.M)
    if len(rows) < 10:
        problems.append("docs/architecture.md: the include table was not found")
    for folder, listed_text in rows:
        if listed_text.startswith("every"):
            continue  # "every library above": a description, not a list
        own = folder.split("/")[-1]
        listed = set()
        if listed_text != "—":
            for word in re.sub(r"\([^)]*\)", "", listed_text).replace("and", ",").split(","):
                word = word.strip().strip("`").rstrip("/").split("/")[-1]
                if word:
                    listed.add(word)
        found = set()
        for path in sources(folder):
            with open(path, encoding="utf-8") as f:
                found.update(re.findall(r'#include "([a-z_]+)/', f.read()))
        listed.discard(own)
        found.discard(own)
        if listed != found:
            problems.append(
                "docs/architecture.md: the row of %s/ lists %s but its files include %s"
                % (folder, ", ".join(sorted(listed)) or "nothing", ", ".join(sorted(found)) or "nothing"))


def check_declarations():
    declared = set()
    for folder in os.listdir(ROOT):
        if folder.startswith((".", "build")) or not os.path.isdir(os.path.join(ROOT, folder)):
            continue
        for path in sources(folder):
            if path.endswith(".hpp"):
                with open(path, encoding="utf-8") as f:
                    declared.update(re.findall(r"\b(?:enum class|struct|class)\s+(\w+)", f.read()))
    docs = ["README.md"] + ["docs/" + n for n in sorted(os.listdir(os.path.join(ROOT, "docs"))) if n.endswith(".md")]
    for doc in docs:
        for lineno, line in enumerate(read(doc).splitlines(), 1):
            for kind, name in re.findall(r"\b(enum class|struct)\s+([A-Z]\w*)\s*\{", line):
                if name not in declared:
                    problems.append("%s:%d: shows %s %s, which no header declares" % (doc, lineno, kind, name))


def number(text):
    return int(text.replace(" ", "").replace("\u202f", ""))


def check_fuzz_figures():
    perf = read("docs/performance.md")
    tables = re.findall(r"\| kind \| variables \|[^\n]*formulas/s/core \|\n\|[^\n]*\n((?:\|[^\n]*\n)+)", perf)
    if not tables:
        problems.append("docs/performance.md: no table with a formulas/s/core column")
        return
    rate = {}
    for row in tables[-1].splitlines():
        cells = [c.strip() for c in row.strip("|").split("|")]
        rate[(cells[0], cells[1])] = number(cells[-1])
    readme = read("README.md")
    m = re.search(r"Fuzzing runs at ([\d ]+) formulas per second per core for random 3-SAT with\s+3–6 variables "
                  r"\(([\d ]+) at 3 variables, ([\d ]+) at 6\) and ([\d ]+)–([\d ]+) for LSAT", readme)
    if not m:
        problems.append("README.md: the fuzzing rates sentence was not found (update scripts/check_docs.py with it)")
        return
    want = {
        "3-SAT, 3–6 variables": rate.get(("ksat", "3–6")),
        "3-SAT, 3 variables": rate.get(("ksat", "3")),
        "3-SAT, 6 variables": rate.get(("ksat", "6")),
        "LSAT, lowest": min((v for (k, _), v in rate.items() if k == "lsat"), default=None),
        "LSAT, highest": max((v for (k, _), v in rate.items() if k == "lsat"), default=None),
    }
    for (what, expected), quoted in zip(want.items(), m.groups()):
        if expected != number(quoted):
            problems.append("README.md: fuzzing rate for %s is %s, docs/performance.md's last table says %s"
                            % (what, quoted.strip(), expected))


check_include_table()
check_declarations()
check_fuzz_figures()
for p in problems:
    print("check_docs: " + p, file=sys.stderr)
if problems:
    sys.exit(1)
print("check_docs: the include table, the declarations shown and README's fuzz rates agree with the tree")
