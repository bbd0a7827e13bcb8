#!/usr/bin/env python3
"""Checks docs/architecture.md against the build: every library folder under src/ (a
CMakeLists.txt calling globe_module) has a row in the folders' table, and the "Dependencies point
down" block lists each library with exactly the project libraries its globe_module DEPENDS names
(in any order). A folder added, removed or rewired without the document fails here.

    tools/docs/check_architecture.py [--doc docs/architecture.md]

Exit status 1 on a difference (each printed), 0 otherwise.
"""
import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODULE = re.compile(r"globe_module\(\s*globe_(\w+)(.*?)\)", re.S)
ROW = re.compile(r"^\|\s*`src/(\w+)`\s*\|")
DEPENDENCY = re.compile(r"^\s*(\w+)\s*(?:→\s*(.*?))?\s*(?:\(.*\))?\s*$")


def built_modules():
    """{library: set of project libraries it depends on} from src/*/CMakeLists.txt."""
    modules = {}
    for cmake in sorted((ROOT / "src").glob("*/CMakeLists.txt")):
        match = MODULE.search(cmake.read_text(encoding="utf-8"))
        if not match:
            continue
        depends = match.group(2).split("DEPENDS", 1)
        names = depends[1].split() if len(depends) == 2 else []
        modules[match.group(1)] = {n[len("globe_"):] for n in names if n.startswith("globe_")}
    return modules


def documented(text):
    """(folders with a table row, {library: set of dependencies} from the dependency block)."""
    rows = {m.group(1) for line in text.splitlines() if (m := ROW.match(line))}
    block = text.split("## Dependencies point down", 1)[-1].split("```")
    graph = {}
    if len(block) >= 3:
        for line in block[1].splitlines():
            match = DEPENDENCY.match(line)
            if not match or line.strip().startswith("apps/"):
                continue
            targets = match.group(2) or ""
            graph[match.group(1)] = {t.strip() for t in targets.split(",") if t.strip()}
    return rows, graph


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--doc", default=str(ROOT / "docs" / "architecture.md"))
    doc = parser.parse_args().doc
    modules = built_modules()
    rows, graph = documented(Path(doc).read_text(encoding="utf-8"))
    problems = []
    for name in sorted(modules):
        if name not in rows:
            problems.append(f"src/{name}: no row in the folders' table")
        if name not in graph:
            problems.append(f"{name}: not in the dependency block")
        elif graph[name] != modules[name]:
            problems.append(f"{name}: the document says → {', '.join(sorted(graph[name])) or '-'}; "
                            f"CMake DEPENDS {', '.join(sorted(modules[name])) or '-'}")
    for name in sorted((rows | set(graph)) - set(modules)):
        problems.append(f"{name}: documented, but no src/{name} library is built")
    for problem in problems:
        print(f"{doc}: {problem}")
    print(f"{len(modules)} libraries checked, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
