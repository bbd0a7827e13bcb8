#!/usr/bin/env python3
"""Writes docs/performance/performance-collision.md and the two plots from globe-bench's results.

Inputs (--results): benchmarks.json (Google Benchmark, aggregates of repetitions) and
accuracy.json (globe-bench --accuracy); machine facts from the environment run-benchmarks.sh
exports. Outputs: the Markdown page (--doc), fig7-time-vs-tiles.png and pareto-time-vs-error.png
(--plots), results/timing.csv and results/machine.json.
"""
import argparse
import csv
import json
import os
import platform
import re
import subprocess
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SIZES = [10, 100, 1000, 10000, 100000]
METHODS = {  # benchmark name -> (label, colour, marker)
    "BM_SphereTree": ("sphere tree", "tab:red", "o"),
    "BM_SphereTreeBvh": ("sphere tree + BVH (fair baseline)", "tab:purple", "P"),
    "BM_QotcdLinear": ("QOTCD linear (paper)", "tab:orange", "s"),
    "BM_QotcdIndexed": ("QOTCD indexed", "tab:blue", "^"),
    "BM_FloorKernel": ("floor kernel", "tab:gray", "x"),
    "BM_ExactSurface": ("exact surface", "tab:green", "D"),
    "BM_QotcdIndexedRandom": ("QOTCD indexed, random positions", "tab:blue", "v"),
}
ACCURACY_METHODS = {
    "sphere_tree": ("sphere tree", "tab:red"),
    "qotcd_linear": ("QOTCD linear", "tab:orange"),
    "qotcd_indexed": ("QOTCD indexed", "tab:blue"),
    "exact_surface": ("exact surface", "tab:green"),
}
REGION_MARKERS = {"fuji": "o", "england": "s", "world": "^", "all": "*"}
TARGET_INDEXED_NS = 100.0
TARGET_FLATNESS = 1.5
TARGET_EXACT_NS = 150.0


def load_benchmarks(path):
    """{(name, tiles): {statistic: entry}} for the aggregate entries."""
    data = json.loads(path.read_text())
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "aggregate":
            continue
        name, _, arg = b["run_name"].partition("/")
        out.setdefault((name, int(arg)), {})[b["aggregate_name"]] = b
    return data.get("context", {}), out


def ns(entry, field="cpu_time"):
    unit = entry.get("time_unit", "ns")
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[unit]
    return entry[field] * scale


def fmt_ns(value):
    if value >= 1e6:
        return f"{value / 1e6:.2f} ms"
    if value >= 1e4:
        return f"{value / 1e3:.1f} µs"
    if value >= 1e3:
        return f"{value / 1e3:.2f} µs"
    return f"{value:.0f} ns"


def machine_facts(context):
    def run(cmd):
        try:
            return subprocess.run(cmd, capture_output=True, text=True, check=False).stdout.strip()
        except OSError:
            return ""

    model = ""
    for line in run(["lscpu"]).splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    debian = Path("/etc/debian_version").read_text().strip() if Path(
        "/etc/debian_version").exists() else ""
    memory = ""
    for line in Path("/proc/meminfo").read_text().splitlines():
        if line.startswith("MemTotal:"):
            memory = f"{int(line.split()[1]) / 1024 / 1024:.0f} GiB"
    return {
        "date_utc": os.environ.get("STARTED", ""),
        "os": f"Debian {debian}" if debian else platform.platform(),
        "kernel": platform.release(),
        "cpu": model,
        "cores": os.cpu_count(),
        "memory": memory,
        "gpu": "none",
        "load_average_before": os.environ.get("LOAD_BEFORE", ""),
        "load_average_after": os.environ.get("LOAD_AFTER", ""),
        "pinned": os.environ.get("PINNED", ""),
        "repetitions": os.environ.get("REPETITIONS", ""),
        "min_time_s": os.environ.get("MIN_TIME", ""),
        "commit": os.environ.get("COMMIT", "") + (" (with uncommitted changes)"
                                                 if os.environ.get("DIRTY") else ""),
        "benchmark_library_build_type": context.get("library_build_type", ""),
        "compiler_flags": "RelWithDebInfo (-O2 -g)",
    }


def write_timing_csv(path, bench):
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["benchmark", "tiles", "median_cpu_ns", "min_cpu_ns", "max_cpu_ns",
                    "median_real_ns", "stddev_cpu_ns", "collided", "Nv", "Np",
                    "build_ns_per_tile", "bytes_per_tile"])
        for (name, tiles), stats in sorted(bench.items()):
            m = stats["median"]
            w.writerow([name, tiles, f"{ns(m):.2f}", f"{ns(stats.get('min', m)):.2f}",
                        f"{ns(stats.get('max', m)):.2f}", f"{ns(m, 'real_time'):.2f}",
                        f"{ns(stats['stddev']):.2f}" if "stddev" in stats else "",
                        m.get("collided", ""), m.get("Nv", ""), m.get("Np", ""),
                        m.get("build_ns_per_tile", ""), m.get("bytes_per_tile", "")])


def plot_fig7(path, bench):
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for name, (label, colour, marker) in METHODS.items():
        xs = [t for t in SIZES if (name, t) in bench]
        if not xs:
            continue
        med = [ns(bench[(name, t)]["median"]) for t in xs]
        lo = [ns(bench[(name, t)].get("min", bench[(name, t)]["median"])) for t in xs]
        hi = [ns(bench[(name, t)].get("max", bench[(name, t)]["median"])) for t in xs]
        err = [[m - l for m, l in zip(med, lo)], [h - m for m, h in zip(med, hi)]]
        ax.errorbar(xs, med, yerr=err, label=label, color=colour, marker=marker, capsize=3,
                    linestyle="--" if name.endswith("Random") else "-")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("rendering tiles in the array (17×17 blocks)")
    ax.set_ylabel("time per query (ns, median of repetitions; bars: min–max)")
    ax.set_title("Collision query time against tile count (cf. the paper's Fig. 7)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_pareto(path, rows):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharex=True)
    for ax, key, title in ((axes[0], "drawn", "(a) against the drawn surface"),
                           (axes[1], "source", "(b) against the finest source data")):
        for r in rows:
            label, colour = ACCURACY_METHODS[r["method"]]
            marker = REGION_MARKERS.get(r["region"], "x")
            size = 150 if r["region"] == "all" else 50
            ax.scatter(r["median_ns"], r[key]["p99_m"], color=colour, marker=marker, s=size,
                       edgecolors="black" if r["region"] == "all" else "none")
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_xlabel("time per query (ns, median over the queries)")
        ax.set_ylabel("p99 height overestimate (m, linear below 1 m)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        lowest = min(r[key]["p99_m"] for r in rows)
        highest = max(r[key]["p99_m"] for r in rows)
        ax.set_ylim(min(0.0, lowest * 1.5), max(10.0, highest * 2.0))
    handles = [plt.Line2D([], [], color=c, marker="o", linestyle="", label=l)
               for l, c in ACCURACY_METHODS.values()]
    handles += [plt.Line2D([], [], color="gray", marker=m, linestyle="", label=reg)
                for reg, m in REGION_MARKERS.items()]
    fig.legend(handles=handles, fontsize=8, loc="lower center", ncol=len(handles))
    fig.suptitle("Run time against error (lower left is better; large stars: all regions)")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def span(values):
    low, high = min(values), max(values)
    if low != low or high != high:
        return "n/a"
    return f"{low:.0f}" if round(low) == round(high) else f"{low:.0f}–{high:.0f}"


def median_of(bench, name, sizes=SIZES):
    values = [ns(bench[(name, t)]["median"]) for t in sizes if (name, t) in bench]
    return values


def ratio_span(numerators, denominators):
    """'1.06–1.15×': the range of per-size ratios, or 'n/a' when a series is missing."""
    if not numerators or len(numerators) != len(denominators):
        return "n/a"
    ratios = [a / b for a, b in zip(numerators, denominators)]
    return f"{min(ratios):.2f}–{max(ratios):.2f}×"


README_BEGIN = "<!-- collision-summary: written by tools/bench/make_report.py -->"
README_END = "<!-- /collision-summary -->"


def write_readme_summary(readme, bench, machine):
    """Replaces the README's collision bullet (between the markers) with this run's numbers."""
    text = readme.read_text()
    begin, end = text.find(README_BEGIN), text.find(README_END)
    if begin < 0 or end < begin:
        raise SystemExit(f"{readme}: no {README_BEGIN} ... {README_END} block")
    idx = median_of(bench, "BM_QotcdIndexed")
    sphere = median_of(bench, "BM_SphereTree")
    bvh = median_of(bench, "BM_SphereTreeBvh") or [float("nan")]
    on_sphere = median_of(bench, "BM_QotcdIndexedOnSphere") or [float("nan")]
    floor = median_of(bench, "BM_FloorKernel")
    exact = median_of(bench, "BM_ExactSurface")
    ratio = sphere[-1] / idx[-1] if sphere and idx else float("nan")
    fair = bvh[-1] / idx[-1] if idx else float("nan")
    block = (
        "* **Collision** ([docs/performance/performance-collision.md]"
        "(docs/performance/performance-collision.md), "
        "regenerate with\n  `tools/bench/run-benchmarks.sh`, which also rewrites this bullet): "
        "the paper's Fig. 7 measured\n  here over 10 to 100,000 real 17×17 tiles "
        f"(commit {machine['commit']}, {machine['cpu']},\n  {machine['date_utc'][:10]}). "
        f"QOTCD indexed: {span(idx)} ns per query at every size. Against a fair\n  baseline, "
        "a sphere tree whose tiles are found through a BVH, QOTCD is "
        f"**{fair:.2f}×** faster at\n  100,000 tiles ({fmt_ns(bvh[-1])} a query) and needs no "
        "per-tile trees (~18 kB a tile); the paper's\n  sphere tree, which scans every tile's "
        f"root, grows to {fmt_ns(sphere[-1])} ({ratio:.0f}× QOTCD).\n  In the same run "
        f"QOTCD indexed is {ratio_span(idx, floor)} the floor kernel (the same geodetic\n  "
        "conversion, one hash probe, four loads, a compare; goal ≤ 1.2×) and the exact\n  "
        f"drawn surface {ratio_span(exact, idx)} QOTCD (goal ≤ 1.5×); the ellipsoidal "
        "conversion is most of\n  every query (the whole query on the paper's sphere: "
        f"{span(on_sphere)} ns). Run time against error is in\n  the document.\n")
    readme.write_text(text[:begin + len(README_BEGIN)] + "\n" + block + text[end:])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--results", type=Path, required=True)
    parser.add_argument("--doc", type=Path, required=True)
    parser.add_argument("--plots", type=Path, required=True)
    parser.add_argument("--readme", type=Path, help="README.md whose collision bullet to rewrite")
    args = parser.parse_args()
    context, bench = load_benchmarks(args.results / "benchmarks.json")
    accuracy = json.loads((args.results / "accuracy.json").read_text())
    rows = accuracy["rows"]
    machine_file = args.results / "machine.json"
    if not os.environ.get("STARTED") and machine_file.exists():
        machine = json.loads(machine_file.read_text())  # re-rendering earlier results
    else:
        machine = machine_facts(context)
        machine_file.write_text(json.dumps(machine, indent=1) + "\n")
    write_timing_csv(args.results / "timing.csv", bench)
    fig7 = args.plots / "fig7-time-vs-tiles.png"
    pareto = args.plots / "pareto-time-vs-error.png"
    plot_fig7(fig7, bench)
    plot_pareto(pareto, rows)
    doc_dir = args.doc.parent
    rel = lambda p: os.path.relpath(p, doc_dir)  # noqa: E731

    def med(name, tiles):
        return ns(bench[(name, tiles)]["median"]) if (name, tiles) in bench else float("nan")

    out = []
    w = out.append
    w("# Collision performance: QOTCD against the sphere-tree baseline\n")
    w(f"Measured {machine['date_utc']} on {machine['os']} ({machine['cpu']}, "
      f"{machine['cores']} cores, {machine['memory']}, no GPU), a machine shared with other "
      f"jobs (load average {machine['load_average_before']} before, "
      f"{machine['load_average_after']} after); pinned with `{machine['pinned'] or 'none'}`; "
      f"commit {machine['commit']}; build RelWithDebInfo (-O2). Times are the median CPU time "
      f"per query over {machine['repetitions']} repetitions of at least {machine['min_time_s']} s "
      "each (wall times and min/max are in [results/timing.csv]"
      f"({rel(args.results / 'timing.csv')})). Regenerate everything with "
      "`tools/bench/run-benchmarks.sh` (about 2 minutes).\n")

    w("## What is compared\n")
    w("All four methods decide one camera position against the **rendering tile array** "
      "(the tiles drawn this frame, 17×17 real height blocks, WGS84) with the paper's 50 m:\n")
    w("| method | collision when | precomputation |\n|---|---|---|")
    w("| sphere tree (the paper's baseline, after its ref. [21]) | some drawn triangle is "
      "within 50 m of the camera (3-D distance; the camera sphere of radius 50 m meets the "
      "mesh) | per tile: the mesh's vertices in ECEF and a quadtree of bounding spheres "
      "16×16 → 8×8 → 4×4 → 2×2 → 1 quad (341 spheres), two triangles per leaf |")
    w("| sphere tree + BVH (a fair baseline) | the same | the same trees, and a bounding volume "
      "hierarchy over the tiles' root spheres (boxes, median split, ≤ 4 tiles a leaf): the "
      "roots are found in O(log n) instead of scanned |")
    w("| QOTCD linear (the paper's method) | D ≤ H + 50 m: D the camera's height along the "
      "Oriented Ray (geodetic normal), H the paper's height (the highest of the 2–4 vertices "
      "around the Intersecting Point) | none; the tile is found by testing every tile's "
      "bounds |")
    w("| QOTCD indexed | the same, the same tile | a hash of the tile ids |")
    w("| exact surface | D ≤ E + 50 m: E the height of the drawn triangle under the camera "
      "(its plane along the normal) | as indexed |")
    w("| floor kernel (not a method: the least any vertical test does) | D ≤ the highest of "
      "the quad's 4 heights + 50 m: the same geodetic conversion, the tile at the array's one "
      "level, one hash probe, four loads, a compare; no edge rules, poles or no-data | as "
      "indexed |\n")
    w("So QOTCD and the exact test use a **vertical clearance of 50 m**, the sphere tree a "
      "**distance of 50 m**. The sphere tree has no inside: a camera more than 50 m below the "
      "surface is not a collision for it (in a flight the camera comes within 50 m first; a "
      "single query cannot know). The sphere tree is written to be competitive: the roots are "
      "a struct-of-arrays scan, the nodes are packed level by level without pointers, the "
      "triangles' vertices are precomputed, and the query stops at the first triangle within "
      "reach (Ericson's closest point on a triangle).\n")

    w("## Fig. 7: time per query against the number of tiles\n")
    w("Arrays of 10, 100, 1,000, 10,000 and 100,000 level-14 tiles (~1 km, 3″ SRTM data of "
      "Mount Fuji): the rectangle of that many tiles (5×2, 10×10, 40×25, 100×100, 400×250) "
      "around the summit tile. Every tile holds its own copy of a real block: the pyramid's "
      "block of that tile within the 94×94 Fuji tiles (all of them up to 1,000 tiles, 8,836 of "
      "10,000), beyond them the Fuji block at the same position modulo 94×94 (real heights, "
      "periodically repeated). Each query is one frame (60 Hz) of a camera flying at 50 m/s "
      "over the central 5×2 tiles, 20–300 m above the drawn surface (fixed seed, 2,048 "
      "frames, the same path for every size); `BM_QotcdIndexedRandom` uses 65,536 independent "
      "positions over the whole array instead.\n")
    w(f"![Fig. 7]({rel(fig7)})\n")
    header = "| tiles | " + " | ".join(METHODS[n][0] for n in METHODS) + \
        " | sphere tree ÷ QOTCD indexed | sphere tree + BVH ÷ QOTCD indexed" \
        " | sphere tree Nv / Np per query | with the BVH |"
    w(header)
    w("|" + "---|" * (len(METHODS) + 5))
    for t in SIZES:
        cells = [fmt_ns(med(n, t)) if (n, t) in bench else "–" for n in METHODS]
        ratio = med("BM_SphereTree", t) / med("BM_QotcdIndexed", t)
        fair = med("BM_SphereTreeBvh", t) / med("BM_QotcdIndexed", t)
        st = bench.get(("BM_SphereTree", t), {}).get("median", {})
        bv = bench.get(("BM_SphereTreeBvh", t), {}).get("median", {})
        w(f"| {t:,} | " + " | ".join(cells) +
          f" | {ratio:.1f}× | {fair:.2f}× | {st.get('Nv', float('nan')):,.0f} / "
          f"{st.get('Np', float('nan')):.1f} | {bv.get('Nv', float('nan')):,.0f} / "
          f"{bv.get('Np', float('nan')):.1f} |")
    coll = bench.get(("BM_QotcdIndexed", 10), {}).get("median", {}).get("collided")
    coll_st = bench.get(("BM_SphereTree", 10), {}).get("median", {}).get("collided")
    if coll is not None and coll_st is not None:
        w(f"\nAlong the path QOTCD reports a collision in {100 * coll:.1f}% of the frames, the "
          f"sphere tree in {100 * coll_st:.1f}% (its early exit makes those frames cheaper).\n")

    # Targets.
    w("## Targets\n")
    idx = median_of(bench, "BM_QotcdIndexed")
    exact = median_of(bench, "BM_ExactSurface")
    sphere = median_of(bench, "BM_SphereTree")
    conv = med("BM_EcefToCartographic", 10)
    conv_sphere = med("BM_EcefToCartographicSphere", 10)
    own = median_of(bench, "BM_QotcdIndexedGeodetic")
    on_sphere = median_of(bench, "BM_QotcdIndexedOnSphere") or [float("nan")]
    exact_own = median_of(bench, "BM_ExactSurfaceGeodetic")
    w("| target | measured | met? |\n|---|---|---|")
    if idx:
        worst = max(idx)
        w(f"| QOTCD indexed median ≤ {TARGET_INDEXED_NS:.0f} ns per query | "
          f"{min(idx):.0f}–{worst:.0f} ns | "
          + ("yes |" if worst <= TARGET_INDEXED_NS else
             f"**no**, by {worst - TARGET_INDEXED_NS:.0f} ns ({worst / TARGET_INDEXED_NS:.1f}×) |"))
        flat = max(idx) / min(idx)
        w(f"| QOTCD indexed flat from 10 to 100,000 tiles (max/min ≤ {TARGET_FLATNESS}) | "
          f"{flat:.2f} | " + ("yes |" if flat <= TARGET_FLATNESS else "**no** |"))
    if exact:
        worst = max(exact)
        w(f"| exact surface ≤ {TARGET_EXACT_NS:.0f} ns | {min(exact):.0f}–{worst:.0f} ns | "
          + ("yes |" if worst <= TARGET_EXACT_NS else
             f"**no**, by {worst - TARGET_EXACT_NS:.0f} ns ({worst / TARGET_EXACT_NS:.1f}×) |"))
    floor = median_of(bench, "BM_FloorKernel")
    if floor and idx and len(floor) == len(idx):
        ratios = [i / f for i, f in zip(idx, floor)]
        w(f"| QOTCD indexed ≤ 1.2× the floor kernel | {min(ratios):.2f}–{max(ratios):.2f}× "
          f"({span(floor)} ns floor) | " + ("yes |" if max(ratios) <= 1.2 else "**no** |"))
    if exact and idx and len(exact) == len(idx):
        ratios = [e / i for e, i in zip(exact, idx)]
        w(f"| exact surface ≤ 1.5× QOTCD indexed | {min(ratios):.2f}–{max(ratios):.2f}× | "
          + ("yes |" if max(ratios) <= 1.5 else "**no** |"))
    if sphere and idx:
        grows = all(b > a for a, b in zip(sphere, sphere[1:]))
        ratios = [s / i for s, i in zip(sphere, idx)]
        w(f"| sphere tree growing with the tiles, \"dozens of times\" slower | "
          f"{fmt_ns(sphere[0])} → {fmt_ns(sphere[-1])}; "
          f"{ratios[0]:.1f}× → {ratios[-1]:.0f}× QOTCD indexed | "
          + ("grows at every size; " if grows else "not monotonic; ")
          + ("dozens of times from "
             + next((f"{t:,}" for t, r in zip(SIZES, ratios) if r >= 24), "no size")
             + " tiles |"))
    w("")
    if idx and own:
        floor_ns = median_of(bench, "BM_FloorKernel")
        w("**Where QOTCD's time goes.** A query starts with the camera's conversion from ECEF to "
          f"geodetic coordinates, `geo::ecefToCartographic` on WGS84: **{conv:.0f} ns** alone "
          "(`BM_EcefToCartographic`: Bowring's iteration, 2–3 steps normalised with "
          "`sqrt(x²+y²)`, plus two `atan2`; within 5e-8 m of the round trip on 10^7 points, "
          "`globe_geo_tests`). QOTCD's own steps — the tile (`positionToTile`, one hash probe, "
          "the edge tests) and H from the block — take "
          f"**{span(own)} ns** (`BM_QotcdIndexedGeodetic`, the camera given in geodetic "
          "coordinates). The floor kernel (`BM_FloorKernel`: the same conversion, the finest "
          "level's tile id, one hash probe, four loads and a compare, none of QOTCD's edge, pole "
          f"and grid-line rules) takes {span(floor_ns)} ns, so the conversion is most of both "
          "and the ratio is what a faster machine keeps. On the paper's sphere the conversion "
          f"is {conv_sphere:.0f} ns (`BM_EcefToCartographicSphere`) and the whole QOTCD "
          f"indexed query measures **{span(on_sphere)} ns** (`BM_QotcdIndexedOnSphere`). What "
          "was changed for speed in the collision module: the tile index is a flat "
          "open-addressing table (one probe, a mix and a mask); the indexed lookup returns at "
          "once when the finest owner is present and the point is not on its west/north edge "
          "or a pole, the rest out of line; tile edges come from per-level tables of the "
          "exact tile sizes (a multiply by the reciprocal guesses the index, a compare fixes "
          "it, so answers are bit-identical); the grid location is one division per axis "
          "and no libm call; H is read inline. The linear scan tests the latitude inline "
          "before the full containment test (the paper's 4 comparisons; answers unchanged, "
          "`globe_collision_tests` pass).\n")
    all_rows = {r["method"]: r for r in rows if r["region"] == "all"}
    acc_idx = all_rows.get("qotcd_indexed", {}).get("median_ns")
    acc_exact = all_rows.get("exact_surface", {}).get("median_ns")
    if exact and exact_own:
        w(f"**The exact surface** spends about the same {conv:.0f} ns on the conversion "
          "(`geo::ecefToGeodeticFrame`: the same iteration also returns the geodetic normal, "
          "from its own quantities, with no sines or cosines); the rest is the nadir point "
          "(camera − D·normal), the triangle under it and the plane through it "
          f"(`BM_ExactSurfaceGeodetic`, {span(exact_own)} ns, starts from geodetic "
          "coordinates and so pays the normal's sines and cosines instead). The quad's "
          "four ECEF corners are remembered per thread for the last quad asked (keyed by the "
          "ellipsoid, tile, row, column and the four heights, so a changed tile or block "
          "cannot reuse them; tested), and the rows' and columns' sines, cosines and radii "
          "of curvature come from a small per-thread table (`collision/mesh_vertex_cache`, "
          "bit for bit the mesh's vertices). Along a flight path consecutive frames mostly "
          "stay in one quad, which is what these timings measure; in random order (the "
          "accuracy table below, caches cold) the exact surface costs "
          + (f"{acc_exact / acc_idx:.1f}× QOTCD indexed.\n" if acc_idx else "more.\n"))
    lin = median_of(bench, "BM_QotcdLinear")
    rnd = median_of(bench, "BM_QotcdIndexedRandom")
    if all(len(v) == len(SIZES) for v in (sphere, idx, lin, rnd)):
        per_tile = (sphere[3] - sphere[0]) / (SIZES[3] - SIZES[0])
        per_tile_big = (sphere[4] - sphere[3]) / (SIZES[4] - SIZES[3])
        lin_tile = (lin[3] - lin[0]) / (SIZES[3] - SIZES[0])
        lin_tile_big = (lin[4] - lin[3]) / (SIZES[4] - SIZES[3])
        first = next((t for t, s_, i in zip(SIZES, sphere, idx) if s_ / i >= 24), None)
        w("**Against the paper.** The sphere tree tests every tile's root sphere, so its cost "
          f"grows linearly: {per_tile:.2f} ns per tile up to 10,000 tiles, "
          f"{per_tile_big:.2f} ns per tile from 10,000 to 100,000 (a struct-of-arrays scan "
          "of 32 B per tile); its descent near the camera (the same few nodes and 4–5 "
          "triangle tests per query) is the same at every size. QOTCD indexed does not grow "
          "at all, so the "
          "paper's \"dozens of times\" holds from "
          + (f"{first:,} tiles on" if first else "no size measured")
          + f" ({sphere[2] / idx[2]:.0f}× at 1,000, {sphere[3] / idx[3]:.0f}× at 10,000, "
          f"{sphere[4] / idx[4]:.0f}× at 100,000 tiles). With few tiles the sphere tree is as "
          f"fast as QOTCD ({sphere[0] / idx[0]:.1f}× at 10 tiles): it needs no geodetic "
          "conversion (it works in ECEF) and along a coherent path its few nodes stay in "
          "cache. The paper's own QOTCD, the linear scan, is O(n) too: "
          f"{lin_tile:.2f} ns per tile up to 10,000 tiles and {lin_tile_big:.2f} ns beyond "
          "(it reads the 64 B tile records, 6.4 MB at 100,000 tiles, beyond the 2 MB L2 "
          "cache): the same order as the sphere tree's root scan, as the paper's O(n) "
          "predicts; it cannot stop early, since the finest of several containing tiles wins. "
          "With random "
          "positions (`BM_QotcdIndexedRandom`) the indexed lookup pays cache misses for the "
          "table, the tile record and the block once the array outgrows the caches: "
          f"{fmt_ns(rnd[0])} at 10 tiles, {fmt_ns(rnd[-1])} at 100,000 (≈ 60 MB of blocks).\n")

    bvh = median_of(bench, "BM_SphereTreeBvh")
    if len(bvh) == len(SIZES) and len(idx) == len(SIZES):
        w("**Against a fair baseline.** The paper's \"dozens of times\" compares an indexed "
          "QOTCD with a sphere tree that scans every root. Given a hierarchy over the roots "
          "(`BM_SphereTreeBvh`), the sphere tree stops growing too: "
          f"{fmt_ns(bvh[0])} at 10 tiles, {fmt_ns(bvh[2])} at 1,000, {fmt_ns(bvh[-1])} at "
          f"100,000, against QOTCD indexed's {span(idx)} ns: QOTCD is "
          f"{bvh[2] / idx[2]:.2f}× faster at 1,000 tiles and {bvh[-1] / idx[-1]:.2f}× at "
          "100,000, not hundreds of times. What QOTCD keeps: no precomputation beyond the "
          "tile hash (the trees take ~18 kB a tile, 1.8 GB at 100,000 tiles, and must be "
          "rebuilt for every tile that streams in), a cost that does not depend on the "
          "terrain's shape, and no triangle tests.\n")

    # Accuracy.
    w("## Run time against error\n")
    regs = {r["name"]: r for r in accuracy["regions"]}
    w("A fixed set of queries (seeded) over real terrain in three regions, each array every "
      "tile of the region's finest level: " + "; ".join(
          f"**{name}**: level {r['level']}, {r['tiles']:,} tiles, {r['queries']:,} queries, "
          f"source {r['source']}" for name, r in regs.items()) +
      ". World queries are uniform by area on land (source > 0 m) outside the two finer "
      "sources. Each camera is at the drawn surface plus a uniform "
      f"{accuracy['camera_offset_range_m'][0]:.0f}…+{accuracy['camera_offset_range_m'][1]:.0f} m "
      "along the normal. Times are measured per query (time-stamp counter, its own "
      f"{accuracy['timer_overhead_ns']:.0f} ns subtracted), the queries in random order, so "
      "caches are colder than along a flight path.\n")
    w("Each method's **effective height** h is the terrain height it acts on: collision iff "
      "D ≤ h + 50 m. QOTCD: H; exact: E; sphere tree: the highest camera height at which its "
      "sphere still meets a triangle, minus 50 m (by bisection). **Overestimate** = h − S for "
      "the reference surface S: (a) the drawn surface, found by the tests' brute-force ray "
      "cast onto every triangle of the tile (`tests/collision/mesh_ray_cast`, written apart "
      "from the exact method, which is therefore measured against it, not equal to it by "
      "construction), (b) the finest source, bilinear (no data = sea = 0 m), read from the "
      "original `.DEM` files through GDAL (not the project's reader; the two give identical "
      "statistics). **FN** (false negative): "
      "the camera is at or below S (a penetration) and the method reports no collision. "
      "**FP**: a collision reported with the camera more than 50 m above S.\n")
    w("| region | method | tiles | median | p99 | max | (a) mean | (a) p99 | (a) max | (a) FN | "
      "(a) FP | (b) mean | (b) p99 | (b) max | (b) min | (b) FN | (b) FP | bytes/tile |")
    w("|" + "---|" * 18)
    for r in rows:
        a, b = r["drawn"], r["source"]
        name = ACCURACY_METHODS[r["method"]][0]
        region = f"**{r['region']}**" if r["region"] == "all" else r["region"]
        w(f"| {region} | {name} | {r['tiles']:,} | {fmt_ns(r['median_ns'])} | "
          f"{fmt_ns(r['p99_ns'])} | {fmt_ns(r['max_ns'])} | {a['mean_m']:.2f} | "
          f"{a['p99_m']:.2f} | {a['max_m']:.1f} | {a['false_negatives']} | "
          f"{a['false_positives']} | {b['mean_m']:.2f} | {b['p99_m']:.2f} | {b['max_m']:.1f} | "
          f"{b['min_m']:.1f} | {b['false_negatives']} | {b['false_positives']} | "
          f"{r['bytes_per_tile']:,.0f} |")
    all_rows = {r["method"]: r for r in rows if r["region"] == "all"}
    st = all_rows.get("sphere_tree")
    qi = all_rows.get("qotcd_indexed")
    ex = all_rows.get("exact_surface")
    w("")
    if st and qi and ex:
        pen = st["drawn"]["penetrations"]
        pen_b = qi["source"]["penetrations"]
        by_region = [r for r in rows if r["method"] == "qotcd_indexed" and r["region"] != "all"]
        fn_regions = [f"{r['region']} {r['source']['false_negatives']}" for r in by_region
                      if r["source"]["false_negatives"]]
        w(f"- **QOTCD is conservative against what is drawn**: it misses "
          f"{qi['drawn']['false_negatives']} of {pen:,} penetrations of the drawn surface "
          f"(H − E ≥ {qi['drawn']['min_m']:.2f} m on every query: H is the highest of the "
          "vertices around the point and the drawn triangle under it does not rise above "
          "its vertices, up to row slivers of millimetres). Against "
          f"the source data it misses {qi['source']['false_negatives']} of {pen_b:,}"
          + (f" ({', '.join(fn_regions)}): the mesh's vertices resample the source on "
             "another grid (level 6 every 10.5′ over ETOPO20's 20′ samples), so a source peak "
             "between vertices can stand more than the 50 m clearance above all four of them "
             f"(lowest (b) overestimate {qi['source']['min_m']:.0f} m)." if fn_regions else
             "."))
        w(f"- **The exact test** is exact for (a) by definition; against the source it misses "
          f"{ex['source']['false_negatives']} penetrations, where the source rises between "
          "the mesh's vertices more than 50 m above the drawn triangle.")
        w(f"- **The sphere tree** misses {st['drawn']['false_negatives']:,} of {pen:,} "
          "penetrations of the drawn surface, "
          + ("all of them deeper than its 50 m radius"
             if st["drawn"]["false_negatives_within_radius"] == 0 else
             f"{st['drawn']['false_negatives_within_radius']} of them within its radius")
          + " (it has no inside). Its FPs are cameras more than 50 m above the surface but "
          "within 50 m of a slope beside it.")
        w("- **QOTCD's price** is its overestimate: the highest of four vertices instead of "
          "the triangle, largest on steep ground and in coarse tiles (the world's level-6 "
          "cells are ~20 km), hence its false positives. The largest errors (the maxima over all "
          "regions) come from SRTM voids on Fuji's flanks (no data, drawn at sea level inside "
          "a slope), where a vertex sits a kilometre or more below its neighbours.")
        for key, name in (("drawn", "(a)"), ("source", "(b)")):
            front, best = [], float("inf")
            for r in sorted(all_rows.values(), key=lambda r: r["median_ns"]):
                if r[key]["p99_m"] < best:
                    front.append(ACCURACY_METHODS[r["method"]][0])
                    best = r[key]["p99_m"]
            w(f"- Pareto front {name} (all regions, median time against p99 overestimate): "
              + ", ".join(front) + ".")
        w("")
    w(f"![time against error]({rel(pareto)})\n")

    # Memory.
    w("## Memory and preprocessing per tile\n")
    w("Bytes per tile beyond the 17×17 height block (578 B): the array's tile record "
      "(`ArrayTile`: bounds, id, block pointer, maximum) for QOTCD linear; plus its share of "
      "the tile index for QOTCD indexed and the exact surface; for the sphere tree its trees "
      "alone (341 spheres × 32 B, 289 vertices × 24 B, the root arrays).\n")
    w("| method | bytes per tile | preprocessing |\n|---|---|---|")
    build = [(t, bench[("BM_SphereTree", t)]["median"].get("build_ns_per_tile"))
             for t in SIZES if ("BM_SphereTree", t) in bench]
    build_text = ", ".join(f"{v / 1e3:.0f} µs ({t:,} tiles)" for t, v in build if v)
    for m, r in all_rows.items():
        pre = {"sphere_tree": f"build per tile: {build_text}",
               "qotcd_linear": "none (the array builds its index anyway; the scan ignores it)",
               "qotcd_indexed": "one table insert per tile in `RenderingTileArray::assign`",
               "exact_surface": "as QOTCD indexed"}[m]
        w(f"| {ACCURACY_METHODS[m][0]} | {r['bytes_per_tile']:,.0f} | {pre} |")
    w("\nThe sphere trees of 100,000 tiles take ≈ 1.8 GB (the 100,000 blocks: 58 MB); the "
      "build per tile, mostly the 289 vertices' trigonometry, is slower at that size, where "
      "the trees' memory is freshly faulted in.\n")

    w("## Files\n")
    w(f"- [results/benchmarks.json]({rel(args.results / 'benchmarks.json')}) (Google "
      f"Benchmark), [results/timing.csv]({rel(args.results / 'timing.csv')}), "
      f"[results/accuracy.csv]({rel(args.results / 'accuracy.csv')}), "
      f"[results/accuracy.json]({rel(args.results / 'accuracy.json')}), "
      f"[results/machine.json]({rel(args.results / 'machine.json')}).")
    w("- `globe-bench --benchmark_filter=BM_QotcdIndexed/ --benchmark_format=json` runs single "
      "cases; `globe-bench --accuracy --out DIR` the accuracy table; `--pyramid DIR` reuses a "
      "pyramid of the bundled data instead of tiling it (~1 s).")
    if machine.get("benchmark_library_build_type") == "debug":
        w("- Debian's Google Benchmark 1.7.1 reports itself as a debug build; that affects its "
          "own bookkeeping between batches, not the code timed.")
    args.doc.parent.mkdir(parents=True, exist_ok=True)
    args.doc.write_text("\n".join(out) + "\n")
    if args.readme:
        write_readme_summary(args.readme, bench, machine)
    print(f"wrote {args.doc}, {fig7}, {pareto}" + (f", {args.readme}" if args.readme else ""))


if __name__ == "__main__":
    main()
