#!/usr/bin/env python3
"""Checks that the code a document shows is the code the project compiles.

A fenced code block right after a line holding `<!-- excerpt: PATH -->` must appear in PATH
(relative to the repository): each of its non-blank lines, stripped of indentation, in the same
order among PATH's lines. A block edited by hand, or left behind when its source changed, fails
here.

    tools/docs/check_excerpts.py DOC.md [DOC.md ...]

Exit status 1 when an excerpt is not in its source (or names a missing file), 0 otherwise.
"""
import re
import sys
from pathlib import Path

MARK = re.compile(r"<!--\s*excerpt:\s*(\S+)\s*-->")


def excerpts(text):
    """(line number, source path, code lines) of each marked code block."""
    lines = text.splitlines()
    found = []
    for i, line in enumerate(lines):
        mark = MARK.search(line)
        if not mark:
            continue
        start = i + 1
        if start >= len(lines) or not lines[start].startswith("```"):
            found.append((i + 1, mark.group(1), None))
            continue
        end = start + 1
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        found.append((i + 1, mark.group(1), lines[start + 1:end]))
    return found


def in_order(code, source_lines):
    """True when every non-blank code line is a stripped source line, in order."""
    wanted = [c.strip() for c in code if c.strip() and c.strip() != "..."]
    at = 0
    for line in source_lines:
        if at < len(wanted) and line.strip() == wanted[at]:
            at += 1
    return at == len(wanted), wanted[at] if at < len(wanted) else None


def main(argv):
    root = Path(__file__).resolve().parents[2]
    failed = 0
    checked = 0
    for doc in argv[1:]:
        text = Path(doc).read_text(encoding="utf-8")
        for number, source, code in excerpts(text):
            where = f"{doc}:{number}"
            path = root / source
            if code is None:
                print(f"{where}: the excerpt mark is not followed by a code block")
                failed += 1
            elif not path.is_file():
                print(f"{where}: {source}: no such file")
                failed += 1
            else:
                ok, missing = in_order(code, path.read_text(encoding="utf-8").splitlines())
                checked += 1
                if not ok:
                    print(f"{where}: not in {source} (in this order): {missing}")
                    failed += 1
    print(f"{checked} excerpts checked, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
