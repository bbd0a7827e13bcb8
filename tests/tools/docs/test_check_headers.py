#!/usr/bin/env python3
"""tools/docs/check_headers.py on a made-up tree of two libraries: passes when a program includes
only public headers, fails naming the file when it includes a private one, when PUBLIC_HEADERS
names a header that does not exist, and when a public header is used by nothing outside."""
import subprocess
import sys
import tempfile
from pathlib import Path

checker = sys.argv[1]


def tree(root, program_includes, listed):
    files = {
        "src/a/CMakeLists.txt":
            f"globe_module(globe_a\n  SOURCES a.cpp\n  PUBLIC_HEADERS {' '.join(listed)}\n"
            "  DEPENDS globe_core)\n",
        "src/a/a.hpp": "#pragma once\n",
        "src/a/detail.hpp": "#pragma once\n",
        "src/a/a.cpp": '#include "a/a.hpp"\n#include "a/detail.hpp"\n',
        "apps/p/main.cpp": "".join(f'#include "a/{h}"\n' for h in program_includes),
        "tests/a/test_a.cpp": '#include "a/detail.hpp"\n',  # tests may include anything
    }
    for name, text in files.items():
        path = Path(root) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def run(program_includes, listed):
    with tempfile.TemporaryDirectory() as root:
        tree(root, program_includes, listed)
        return subprocess.run([sys.executable, checker, "--root", root], capture_output=True,
                              text=True)


ok = run(["a.hpp"], ["a.hpp"])
assert ok.returncode == 0, ok.stdout + ok.stderr
for includes, listed, expected in [
    (["a.hpp", "detail.hpp"], ["a.hpp"], "apps/p/main.cpp: includes a/detail.hpp, private"),
    (["a.hpp"], ["a.hpp", "gone.hpp"], "names gone.hpp, which does not exist"),
    (["a.hpp"], ["a.hpp", "detail.hpp"], "detail.hpp is public, but nothing outside"),
]:
    failed = run(includes, listed)
    assert failed.returncode == 1, failed.stdout + failed.stderr
    assert expected in failed.stdout, failed.stdout
print("ok")
