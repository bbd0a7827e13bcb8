#!/usr/bin/env python3
"""Checks the libraries' public/private split: each src/<lib>/CMakeLists.txt names in its
globe_module's PUBLIC_HEADERS the headers other code may include; every other header of the
folder is private, beside its sources. Fails when a library, program or tool includes another
library's private header, when a listed header does not exist, and when a listed header is
included by nothing outside its library (then it is private: take it off the list). Tests are
white-box and may include any header.

    tools/docs/check_headers.py [--root DIR]

Exit status 1 on a problem (each printed), 0 otherwise.
"""
import argparse
import re
import sys
from pathlib import Path

MODULE = re.compile(r"globe_module\(\s*globe_(\w+)(.*?)\)", re.S)
INCLUDE = re.compile(r'^\s*#\s*include\s+"(\w+)/([\w/]+\.hpp)"', re.M)
CODE = (".cpp", ".hpp", ".h", ".cc")
KEYWORDS = ("SOURCES", "PUBLIC_HEADERS", "DEPENDS")


def public_headers(root):
    """{library: set of public header names} from src/*/CMakeLists.txt."""
    libraries = {}
    for cmake in sorted((root / "src").glob("*/CMakeLists.txt")):
        match = MODULE.search(cmake.read_text(encoding="utf-8"))
        if not match:
            continue
        words, listed, inside = match.group(2).split(), set(), False
        for word in words:
            if word in KEYWORDS:
                inside = word == "PUBLIC_HEADERS"
            elif inside:
                listed.add(word)
        libraries[match.group(1)] = listed
    return libraries


def includes(root):
    """(including file, library, header) for every project include outside tests/."""
    for folder in ("src", "apps", "tools"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in CODE and path.is_file():
                text = path.read_text(encoding="utf-8", errors="replace")
                for match in INCLUDE.finditer(text):
                    yield path.relative_to(root), match.group(1), match.group(2)


def problems(root):
    libraries = public_headers(root)
    used_outside = {name: set() for name in libraries}
    found = []
    for source, library, header in includes(root):
        if library not in libraries or source.parts[:2] == ("src", library):
            continue
        used_outside[library].add(header)
        if header not in libraries[library]:
            found.append(f"{source}: includes {library}/{header}, private to globe_{library} "
                         f"(not in its PUBLIC_HEADERS)")
    for library, listed in sorted(libraries.items()):
        for header in sorted(listed):
            if not (root / "src" / library / header).is_file():
                found.append(f"src/{library}/CMakeLists.txt: PUBLIC_HEADERS names {header}, "
                             f"which does not exist")
            elif header not in used_outside[library]:
                found.append(f"src/{library}/CMakeLists.txt: {header} is public, but nothing "
                             f"outside globe_{library} includes it (make it private)")
    return libraries, found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", default=str(Path(__file__).resolve().parents[2]))
    root = Path(parser.parse_args().root)
    libraries, found = problems(root)
    for problem in found:
        print(problem)
    headers = sum(1 for name in libraries for _ in (root / "src" / name).glob("*.hpp"))
    public = sum(len(listed) for listed in libraries.values())
    print(f"{len(libraries)} libraries, {headers} headers, {public} public, "
          f"{headers - public} private; {len(found)} problems")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
