#!/usr/bin/env python3
"""tools/docs/check_numbers.py on a made-up README and document: numbers that the cited document
holds pass (thousands separators and ranges included), one it lacks fails naming the line, and
a block that cites nothing is not failed."""
import subprocess
import sys
import tempfile
from pathlib import Path

checker = sys.argv[1]
with tempfile.TemporaryDirectory() as tmp:
    root = Path(tmp)
    (root / "docs").mkdir()
    (root / "docs" / "bench.md").write_text(
        "| view | ms |\n|---|---|\n| fuji | 19.2 |\n| zion | 20.4 |\n183168 triangles\n")
    good = ("# T\n\nFuji **19.2–20.4 ms** a frame, 183,168 triangles "
            "([docs/bench.md](docs/bench.md)).\n\nA tile is 17 m wide (no source).\n")
    bad = good + "\nZion 21.5 ms ([docs/bench.md](docs/bench.md)).\n"
    (root / "README.md").write_text(good)
    ok = subprocess.run([sys.executable, checker, "--readme", str(root / "README.md")],
                        capture_output=True, text=True)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    (root / "README.md").write_text(bad)
    failed = subprocess.run([sys.executable, checker, "--readme", str(root / "README.md")],
                            capture_output=True, text=True)
    assert failed.returncode == 1, failed.stdout + failed.stderr
    assert "README.md:7" in failed.stdout and "21.5" in failed.stdout, failed.stdout
print("ok")
