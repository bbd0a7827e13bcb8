#!/usr/bin/env python3
"""tools/docs/check_cli_doc.py passes on docs/cli.md and fails, naming the subcommand, on a copy
whose `globe sun` entry was removed."""
import subprocess
import sys
import tempfile
from pathlib import Path

checker, globe, tiler, doc = sys.argv[1], sys.argv[2], sys.argv[3], Path(sys.argv[4])
text = doc.read_text(encoding="utf-8")


def run(doc_text):
    with tempfile.TemporaryDirectory() as tmp:
        copy = Path(tmp) / "cli.md"
        copy.write_text(doc_text, encoding="utf-8")
        return subprocess.run([sys.executable, checker, globe, tiler, "--doc", str(copy)],
                              capture_output=True, text=True)


ok = run(text)
assert ok.returncode == 0, ok.stdout + ok.stderr
without = "\n".join(line for line in text.splitlines() if not line.startswith("globe sun"))
failed = run(without)
assert failed.returncode == 1, failed.stdout + failed.stderr
assert "no entry for `globe sun`" in failed.stdout, failed.stdout
print("ok")
