#!/usr/bin/env python3
"""tools/docs/check_excerpts.py on made-up documents quoting the checker's own source: an
excerpt it holds (lines in order, indentation and "..." aside) passes; one with a changed line,
lines out of order, a missing file or a mark without a block fails naming the line."""
import subprocess
import sys
import tempfile
from pathlib import Path

checker = sys.argv[1]
SOURCE = "tools/docs/check_excerpts.py"


def run(doc_text):
    with tempfile.TemporaryDirectory() as tmp:
        doc = Path(tmp) / "doc.md"
        doc.write_text(doc_text)
        return subprocess.run([sys.executable, checker, str(doc)], capture_output=True, text=True)


good = ("# T\n\n<!-- excerpt: " + SOURCE + " -->\n```python\ndef in_order(code, source_lines):\n"
        "    ...\n    at = 0\n        return 1 if failed else 0\n```\n")
ok = run(good)
assert ok.returncode == 0 and "1 excerpts checked, 0 failed" in ok.stdout, ok.stdout + ok.stderr
for bad, expected in [
    (good.replace("at = 0", "at = 1"), "at = 1"),
    (good.replace("def in_order(code, source_lines):\n    ...\n    at = 0",
                  "at = 0\ndef in_order(code, source_lines):"), "def in_order"),
    (good.replace(SOURCE, "tools/docs/no_such_file.py"), "no such file"),
    ("<!-- excerpt: " + SOURCE + " -->\ntext, not code\n", "not followed by a code block"),
]:
    failed = run(bad)
    assert failed.returncode == 1, failed.stdout + failed.stderr
    assert "doc.md:" in failed.stdout and expected in failed.stdout, failed.stdout
print("ok")
