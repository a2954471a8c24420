#!/usr/bin/env python3
"""Fails when the installed headers (each library's facade) reach past it.
Run by ctest (test public_headers, label fast) and by hand:

    python3 scripts/check_public_headers.py                # the source tree
    python3 scripts/check_public_headers.py --prefix P     # an installed tree

A library is a folder whose CMakeLists.txt calls gridlock_library(); its
installed headers are the folder's own *.hpp (the top CMakeLists.txt
installs exactly those; <folder>/internal/ is not installed). Two checks:

1. The include closure of every installed header stays inside the installed
   set: each `#include "folder/file.hpp"` of an installed header names
   another installed header (so a user with the installed package alone can
   compile every header it has).
2. No library header outside an internal/ folder includes an internal/
   header (the rule that keeps check 1 true as headers move).
3. docs/architecture.md's table of public headers ("| **folder** | public
   | internal |") lists exactly the headers of each library folder and of
   its internal/ folder.

With --prefix P it checks the headers actually installed under
P/include/gridlock instead: every quoted include resolves inside it.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def includes(path):
    with open(path, encoding="utf-8") as f:
        return INCLUDE.findall(f.read())


def libraries():
    for name in sorted(os.listdir(ROOT)):
        cmake = os.path.join(ROOT, name, "CMakeLists.txt")
        if os.path.isfile(cmake):
            with open(cmake, encoding="utf-8") as f:
                if re.search(r"^\s*gridlock_library\(", f.read(), re.M):
                    yield name


def check_source_tree():
    problems = []
    libs = list(libraries())
    if len(libs) < 5:
        return ["found only %d libraries (gridlock_library() calls): %s" % (len(libs), ", ".join(libs))], 0
    installed = set()
    for lib in libs:
        for name in os.listdir(os.path.join(ROOT, lib)):
            if name.endswith(".hpp"):
                installed.add(lib + "/" + name)
    for header in sorted(installed):
        for inc in includes(os.path.join(ROOT, header)):
            if inc not in installed:
                problems.append("%s (installed) includes %s, which is not installed" % (header, inc))
    for lib in libs:
        for root, dirs, files in os.walk(os.path.join(ROOT, lib)):
            rel = os.path.relpath(root, ROOT)
            if "internal" in rel.split(os.sep):
                continue
            for name in files:
                if not name.endswith((".hpp", ".h")):
                    continue
                path = os.path.join(root, name)
                for inc in includes(path):
                    if "/internal/" in inc:
                        problems.append("%s (not internal) includes the internal header %s"
                                        % (os.path.relpath(path, ROOT), inc))
    problems += check_table(libs)
    return problems, len(installed)


def names(folder):
    if not os.path.isdir(folder):
        return set()
    return {n[:-4] for n in os.listdir(folder) if n.endswith(".hpp")}


def check_table(libs):
    with open(os.path.join(ROOT, "docs", "architecture.md"), encoding="utf-8") as f:
        rows = re.findall(r"^\| \*\*([a-z_]+)\*\* \| (.*) \| (.*) \|$", f.read(), re.M)
    problems = []
    listed = {lib for lib, _, _ in rows}
    for lib in sorted(set(libs) - listed):
        problems.append("docs/architecture.md: the public header table has no row for %s/" % lib)
    for lib, public, internal in rows:
        for kind, text, folder in (("public", public, lib), ("internal", internal, os.path.join(lib, "internal"))):
            want = names(os.path.join(ROOT, folder))
            got = {w.strip() for w in text.split(",") if w.strip() not in ("", "\u2014")}
            if got != want:
                problems.append("docs/architecture.md: %s/ %s headers listed %s, the tree has %s"
                                % (lib, kind, ", ".join(sorted(got)) or "none", ", ".join(sorted(want)) or "none"))
    return problems


def check_prefix(prefix):
    base = os.path.join(prefix, "include", "gridlock")
    if not os.path.isdir(base):
        return ["%s: no installed headers" % base], 0
    problems = []
    count = 0
    for root, _, files in os.walk(base):
        for name in files:
            path = os.path.join(root, name)
            rel = os.path.relpath(path, base)
            count += 1
            if "internal" in rel.split(os.sep):
                problems.append("%s: an internal header is installed" % rel)
            for inc in includes(path):
                if not os.path.isfile(os.path.join(base, inc)):
                    problems.append("%s (installed) includes %s, which is not installed" % (rel, inc))
    return problems, count


def main(argv):
    if len(argv) == 3 and argv[1] == "--prefix":
        problems, count = check_prefix(argv[2])
    elif len(argv) == 1:
        problems, count = check_source_tree()
    else:
        print(__doc__, file=sys.stderr)
        return 2
    for p in problems:
        print("check_public_headers: " + p, file=sys.stderr)
    if problems:
        return 1
    print("check_public_headers: %d installed headers include only installed headers" % count)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
