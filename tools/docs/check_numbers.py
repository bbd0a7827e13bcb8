#!/usr/bin/env python3
"""Checks that the measured numbers in README.md agree with the documents they cite.

A paragraph, list item or table row of the README that states numbers with units (times, sizes,
rates, ratios, percentages) and links to a document or results file of the repository (docs/*.md,
tools/**/results/*) must find each of those numbers in the files it links to (thousands
separators and the kind of minus sign aside). A number typed by hand, or left behind when its
document was regenerated, then fails here instead of going stale.

    tools/docs/check_numbers.py [--readme README.md] [--unsourced] [--report]

--unsourced also lists the blocks with such numbers that cite nothing (numbers from a test's
output, a command shown beside them, or an input's specification: not all are measurements, so
they are listed, not failed). --report lists the blocks that pass too. Exit status 1 when a
block's number is not in what it cites.
"""
import argparse
import re
import sys
from pathlib import Path

UNIT = r"(?:ms|µs|us|ns|s|min|h|%|×|x|MB|GB|kB|KB|MiB|GiB|KiB|B|tiles/s|fps|m)"
NUMBER = re.compile(
    r"(?<![\w./#-])(\d{1,3}(?:,\d{3})+|\d+)(\.\d+)?(?:\s?[–-]\s?(\d[\d,]*)(\.\d+)?)?\s?(" + UNIT +
    r")(?![\w])")
LINK = re.compile(r"\]\(([^)#\s]+)")


def blocks(text):
    """(heading, first line number, text) of each paragraph, list item and table row."""
    out, heading, current, start, fenced = [], "", [], 0, False
    for number, line in enumerate(text.splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        if line.startswith("#"):
            if current:
                out.append((heading, start, "\n".join(current)))
            heading, current = line.lstrip("# ").strip(), []
            continue
        new_block = (not line.strip() or line.startswith("|") or
                     re.match(r"\s*[*-] ", line) is not None)
        if new_block and current:
            out.append((heading, start, "\n".join(current)))
            current = []
        if line.strip():
            if not current:
                start = number
            current.append(line)
            if line.startswith("|"):
                out.append((heading, start, line))
                current = []
    if current:
        out.append((heading, start, "\n".join(current)))
    return out


def normalise(token):
    return token.replace(",", "").replace("−", "-")


def numbers_in(block):
    found = []
    for m in NUMBER.finditer(block):
        for whole, fraction in ((m.group(1), m.group(2)), (m.group(3), m.group(4))):
            if whole:
                found.append(normalise(whole + (fraction or "")))
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--readme", type=Path, default=Path(__file__).resolve().parents[2] /
                        "README.md")
    parser.add_argument("--report", action="store_true")
    parser.add_argument("--unsourced", action="store_true")
    args = parser.parse_args()
    root = args.readme.parent
    failures = 0
    for heading, line, block in blocks(args.readme.read_text()):
        values = numbers_in(block)
        if not values:
            continue
        sources = []
        for target in LINK.findall(block):
            path = (root / target).resolve()
            if path.is_file() and path.suffix in (".md", ".json", ".csv", ".txt"):
                sources.append(path)
        if not sources:
            if args.unsourced:
                print(f"README.md:{line} ({heading}): cites no document for "
                      f"{', '.join(values)}")
            continue
        corpus = normalise("\n".join(p.read_text() for p in sources))
        missing = [v for v in values if not re.search(r"(?<![\d.])" + re.escape(v) + r"(?![\d])",
                                                       corpus)]
        if missing:
            failures += 1
            print(f"README.md:{line} ({heading}): {', '.join(missing)} not in "
                  f"{', '.join(str(p.relative_to(root)) for p in sources)}")
        elif args.report:
            print(f"README.md:{line} ({heading}): ok {', '.join(values)}")
    print(f"{failures} block(s) with numbers not in what they cite", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
