#!/usr/bin/env python3
"""Checks docs/cli.md against the programs: every subcommand `globe --help` lists (its
"Subcommands:" table, made from the program's own list) and every `globe-tiler NAME` line of
`globe-tiler --help` has its entry in the reference (a line starting "globe NAME" or
"globe-tiler NAME"). A subcommand added without its documentation fails here.

    tools/docs/check_cli_doc.py GLOBE GLOBE_TILER [--doc docs/cli.md]

Exit status 1 on a subcommand the document lacks (each printed), 0 otherwise.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def subcommands(program, pattern):
    text = subprocess.run([program, "--help"], capture_output=True, text=True, check=True).stdout
    return sorted(set(re.findall(pattern, text, re.M)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("globe")
    parser.add_argument("globe_tiler")
    parser.add_argument("--doc", default=str(ROOT / "docs" / "cli.md"))
    arguments = parser.parse_args()
    doc = Path(arguments.doc).read_text(encoding="utf-8")
    globe_help = subprocess.run([arguments.globe, "--help"], capture_output=True, text=True,
                                check=True).stdout
    table = globe_help.split("Subcommands:", 1)[-1] if "Subcommands:" in globe_help else ""
    wanted = [("globe", name) for name in re.findall(r"^  ([a-z][a-z-]*) ", table, re.M)]
    wanted += [("globe-tiler", name) for name in
               subcommands(arguments.globe_tiler, r"^(?:Also:)? +globe-tiler ([a-z][a-z-]*) ")]
    missing = [f"{program} {name}" for program, name in wanted
               if not re.search(rf"^{re.escape(program)} {re.escape(name)}\b", doc, re.M)]
    for entry in missing:
        print(f"{arguments.doc}: no entry for `{entry}`")
    print(f"{len(wanted)} subcommands checked, {len(missing)} undocumented")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
