#!/usr/bin/env python3
"""Writes the benchmarks' regression suite: 40 views of the bundled data at 480x270, 8 places
(the globe, Fuji, Zion, the poles, the antimeridian, Europe) x 5 variants (terrain alone, lit,
the Blue Marble layer, Blue Marble + Landsat over Zion, a coarser SSE). The views name
"pyramid" and the layers "blue-marble" and "zion", as tools/bench/tile_bundled.sh makes them.

    regress_bench_suite.py SUITE.json
"""
import json
import sys

PLACES = {
    "globe": "138,30,20000000", "fuji": "138.60,35.20,6000,30,-15,0",
    "fuji_top": "138.73,35.36,9000,0,-60,0", "zion": "-112.93,37.16,4500,330,-20,0",
    "zion_nadir": "-112.98,37.27,9000", "north_pole": "0,90,3000000",
    "bering": "180,58,1800000,0,-45,0", "europe": "2,54,2500000",
}
VARIANTS = {
    "terrain": [], "lit": ["--lighting"], "bm": ["--layer", "blue-marble"],
    "zion": ["--layer", "blue-marble", "--layer", "zion,0.7"], "sse8": ["--sse", "8"],
}

views = [{"name": f"{p}_{v}", "snapshot": ["pyramid", "--camera", c, "--size", "480x270", *a]}
         for p, c in PLACES.items() for v, a in VARIANTS.items()]
with open(sys.argv[1], "w") as out:
    json.dump({"views": views}, out, indent=1)
