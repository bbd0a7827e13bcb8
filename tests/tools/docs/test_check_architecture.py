#!/usr/bin/env python3
"""tools/docs/check_architecture.py on docs/architecture.md passes, and on copies of it with a
folder's row removed, a dependency dropped, or a library that is not built added, fails naming
the library."""
import subprocess
import sys
import tempfile
from pathlib import Path

checker, doc = sys.argv[1], Path(sys.argv[2])
text = doc.read_text(encoding="utf-8")


def run(doc_text):
    with tempfile.TemporaryDirectory() as tmp:
        copy = Path(tmp) / "architecture.md"
        copy.write_text(doc_text, encoding="utf-8")
        return subprocess.run([sys.executable, checker, "--doc", str(copy)],
                              capture_output=True, text=True)


ok = run(text)
assert ok.returncode == 0, ok.stdout + ok.stderr
row = next(line for line in text.splitlines() if line.startswith("| `src/places` |"))
edge = next(line for line in text.splitlines() if line.strip().startswith("places "))
for bad, expected in [
    (text.replace(row + "\n", ""), "src/places: no row"),
    (text.replace(edge, edge.replace("compression, ", "")), "places: the document says"),
    (text.replace(edge, edge + "\n atlantis         → core"), "atlantis: documented"),
]:
    failed = run(bad)
    assert failed.returncode == 1, failed.stdout + failed.stderr
    assert expected in failed.stdout, failed.stdout
print("ok")
