#!/usr/bin/python3
"""Turn GMT's binned GSHHG shorelines into land polygons (an OGR land/water mask).

    /usr/bin/python3 tools/coastline/gshhg_land_polygons.py --resolution f|h|i|l|c \
        [--bounds W,S,E,N ...] [--decimals N] -o OUT.{fgb,gpkg,geojson,geojson.gz}

Writes one polygon layer `land` (EPSG:4326, lon/lat) with one MultiPolygon per GMT bin: GSHHG
levels 1 (land) and 3 (island in lake) are land; 0, 2 and 4 (ocean, lake, pond) are water.
Antarctica follows GMT's default shoreline (the ice front).

How: `gmt coast -M -W` dumps the shoreline pieces of every bin; each piece is a closed ring
inside the bin or an open line whose ends lie on the bin's edge. Closing each open line along
the bin's edge (always counter-clockwise) and XOR-ing all rings gives the land of the bin up to
the complement of the whole bin (each crossing of a shoreline flips land/water exactly once),
so one `gmt select` point query per bin, at a point far from any shoreline, settles which.
Bins with no shoreline are all land or all water: same query at their centre.

--bounds may be repeated (all boxes go into one file); E may exceed 180 to cross the
antimeridian (170,-25,190,-10); output longitudes always stay within [-180, 180].
Needs the Debian packages gmt and gmt-gshhg-* and the GDAL Python bindings (/usr/bin/python3).
"""
import argparse
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal, ogr, osr

# Bin size in degrees per resolution: the `Bin_size_in_minutes` variable of
# /usr/share/gmt-gshhg/binned_GSHHS_<res>.nc (1200, 600, 300, 120, 60 minutes). Bins are numbered
# row by row from the north pole, columns eastwards from 0°E; parse_coast() checks every point
# against its bin, so a wrong size here fails loudly instead of producing a bad mask.
BIN_DEG = {"c": 20, "l": 10, "i": 5, "h": 2, "f": 1}
DRIVERS = {".gpkg": "GPKG", ".fgb": "FlatGeobuf", ".geojson": "GeoJSON", ".geojson.gz": "GeoJSON"}
SNAP = 1e-7  # degrees: GMT prints edge points as e.g. 59.99999999999; its own quantum is >= 1.5e-5°
HEADER = re.compile(r"Bin # (\d+), Level (\d+)")
# Pin the output formats a gmt.conf could change.
GMT_OPTS = ["--FORMAT_FLOAT_OUT=%.12g", "--FORMAT_GEO_OUT=D", "--IO_SEGMENT_MARKER=>"]


class Failure(Exception):
    pass


def run_gmt(args, stdin=None):
    # In a scratch folder: classic-mode gmt writes gmt.history into its working directory.
    with tempfile.TemporaryDirectory(prefix="gshhg-land-") as scratch:
        proc = subprocess.run(["gmt", *args, *GMT_OPTS], input=stdin, capture_output=True,
                              text=True, cwd=scratch)
    if proc.returncode != 0:
        raise Failure(f"`gmt {' '.join(args)}` failed (exit {proc.returncode}): {proc.stderr.strip()}")
    return proc.stdout


def parse_bounds(text):
    try:
        w, s, e, n = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"bounds must be W,S,E,N numbers, got {text!r}")
    if not (-180 <= w < e <= w + 360 and e <= 540 and -90 <= s < n <= 90):
        raise argparse.ArgumentTypeError(f"bounds {text!r}: need -180<=W<E<=W+360, -90<=S<N<=90")
    # A box crossing +180 becomes two boxes, so nothing downstream ever sees lon > 180.
    return [(w, s, min(e, 180.0), n)] + ([(-180.0, s, e - 360, n)] if e > 180 else [])


def bin_box(b, deg):
    """(west, south, east, north) of bin b, west in [-180, 180)."""
    row, col = divmod(b, 360 // deg)
    west = col * deg - (360 if col * deg >= 180 else 0)
    return west, 90 - (row + 1) * deg, west + deg, 90 - row * deg


def bins_of_box(box, deg):
    w, s, e, n = box
    w0, e0 = math.floor(w / deg) * deg, math.ceil(e / deg) * deg
    # Bin rows count down from the pole, so for 20° bins the latitude edges are 90, 70, .., -90.
    n0, s0 = 90 - math.floor((90 - n) / deg) * deg, 90 - math.ceil((90 - s) / deg) * deg
    cols = 360 // deg
    bins = [((90 - lat) // deg) * cols + (lon % 360) // deg
            for lat in range(n0, s0, -deg) for lon in range(w0, e0, deg)]
    return (w0, s0, e0, n0), bins


def parse_coast(text, deg, wanted):
    """{bin: [Nx2 arrays]} from `gmt coast -M -W` output, lon shifted into the bin, edges snapped."""
    heads, rows = [], []
    for line in text.splitlines():
        if line.startswith(">"):
            m = HEADER.search(line)
            if not m:
                raise Failure(f"unexpected gmt coast segment header: {line!r}")
            heads.append((int(m[1]), len(rows)))
        elif line.strip():
            rows.append(line)
    xy = np.array(" ".join(rows).split(), dtype=float).reshape(-1, 2) if rows else np.zeros((0, 2))
    segs = {}
    for k, (b, start) in enumerate(heads):
        if b not in wanted:  # neighbour bins touching the region come back clipped to nothing
            continue
        p = xy[start:heads[k + 1][1] if k + 1 < len(heads) else len(xy)].copy()
        w, s, e, n = bin_box(b, deg)
        p[:, 0] -= 360 * np.round((p[:, 0] - (w + e) / 2) / 360)  # GMT may print 180..360 as -180..0
        for col, lo, hi in ((0, w, e), (1, s, n)):
            v = p[:, col]
            v[np.abs(v - lo) < SNAP], v[np.abs(v - hi) < SNAP] = lo, hi
            if v.min() < lo or v.max() > hi:
                raise Failure(f"bin {b}: points outside {w},{s},{e},{n}; is the bin size {deg}° right?")
        if len(p) >= 2:
            segs.setdefault(b, []).append(p)
    return segs


def perimeter_t(x, y, box):
    """Position of an edge point along the bin boundary, counter-clockwise from SW, in [0, 4)."""
    w, s, e, n = box
    d = e - w
    if y == s and x < e:
        return (x - w) / d
    if x == e and y < n:
        return 1 + (y - s) / d
    if y == n and x > w:
        return 2 + (e - x) / d
    if x == w:
        return (3 + (n - y) / d) % 4
    return None  # not on the edge


def close_segment(p, box):
    """A closed ring: p, then counter-clockwise along the bin edge from p's end back to its start."""
    if (p[0] == p[-1]).all():
        return p
    t0, t1 = perimeter_t(*p[0], box), perimeter_t(*p[-1], box)
    if t0 is None or t1 is None:
        raise Failure(f"open shoreline piece ending inside bin {box}: {p[0]} .. {p[-1]}")
    w, s, e, n = box
    corners = {1: (e, s), 2: (e, n), 3: (w, n), 4: (w, s)}
    span = (t0 - t1) % 4
    order = sorted(corners, key=lambda c: (c - t1) % 4)
    pts = [corners[c] for c in order if 0 < (c - t1) % 4 < span]
    return np.vstack([p, np.array(pts).reshape(-1, 2), p[:1]])


def polygon(rings):
    """OGR polygon from Nx2 arrays, built through WKB (far faster than AddPoint per vertex)."""
    wkb = [struct.pack("<BII", 1, 3, len(rings))]
    for r in rings:
        wkb += [struct.pack("<I", len(r)), np.ascontiguousarray(r, "<f8").tobytes()]
    return ogr.CreateGeometryFromWkb(b"".join(wkb))


def rectangle(w, s, e, n):
    return polygon([np.array([[w, s], [e, s], [e, n], [w, n], [w, s]], float)])


def lines(segs):
    wkb = [struct.pack("<BII", 1, 5, len(segs))]
    for p in segs:
        wkb += [struct.pack("<BII", 1, 2, len(p)), np.ascontiguousarray(p, "<f8").tobytes()]
    return ogr.CreateGeometryFromWkb(b"".join(wkb))


def polygons_only(g):
    """MultiPolygon of the polygon parts of g (overlays may also return lines or points)."""
    out = ogr.Geometry(ogr.wkbMultiPolygon)
    if g is None or g.IsEmpty():
        return out
    t = ogr.GT_Flatten(g.GetGeometryType())
    if t == ogr.wkbPolygon:
        if g.GetArea() > 0:
            out.AddGeometry(g)
    elif t in (ogr.wkbMultiPolygon, ogr.wkbGeometryCollection):
        for i in range(g.GetGeometryCount()):
            for part in polygons_only(g.GetGeometryRef(i)):
                out.AddGeometry(part)
    return out


def valid(g):
    return g if g.IsValid() else g.MakeValid()


def xor_all(geoms):
    """Even-odd union; pairwise in a balanced tree so big bins stay O(n log n)-ish."""
    while len(geoms) > 1:
        geoms = [geoms[i].SymDifference(geoms[i + 1]) if i + 1 < len(geoms) else geoms[i]
                 for i in range(0, len(geoms), 2)]
    return geoms[0]


def probe_point(shore, box):
    """A point of the bin well away from every shoreline, so GMT and GEOS cannot disagree on it."""
    w, s, e, n = box
    best, best_d = None, -1.0
    for fx, fy in [(0.5, 0.5)] + [((i + 0.5) / 5, (j + 0.5) / 5) for i in range(5) for j in range(5)]:
        pt = ogr.CreateGeometryFromWkt(f"POINT ({w + fx * (e - w)!r} {s + fy * (n - s)!r})")
        d = shore.Distance(pt)
        if d > best_d:
            best, best_d = pt, d
        if d > 0.05 * (e - w):
            break
    return best, best_d


def rounded(g, decimals):
    """g with coordinates rounded; made valid again if rounding collapsed or crossed an edge."""
    polys = []
    for poly in g:
        rings = []
        for ring in poly:
            r = np.round(np.array(ring.GetPoints())[:, :2], decimals)
            r = r[np.r_[True, (np.diff(r, axis=0) != 0).any(axis=1)]]
            rings.append(r)
        if len(rings[0]) >= 4:  # a shell collapsed to a sliver drops with its holes
            polys.append(polygon([r for r in rings if len(r) >= 4]))
    out = ogr.Geometry(ogr.wkbMultiPolygon)
    for p in polys:
        for part in polygons_only(valid(p)):
            out.AddGeometry(part)
    return out if out.IsValid() else polygons_only(out.MakeValid())


def build(res, boxes, decimals, log):
    deg = BIN_DEG[res]
    segs, all_bins, seen = {}, [], set()
    for box in boxes:
        (w0, s0, e0, n0), bins = bins_of_box(box, deg)
        new = [b for b in bins if b not in seen]
        if not new:
            continue
        all_bins += new
        seen.update(new)
        text = run_gmt(["coast", f"-R{w0}/{e0}/{s0}/{n0}", f"-D{res}", "-M", "-W"])
        for b, pieces in parse_coast(text, deg, set(new)).items():
            segs[b] = pieces
    log(f"{len(all_bins)} bins, {len(segs)} with shoreline, "
        f"{sum(len(p) for v in segs.values() for p in v)} points")

    xors, probes = {}, []
    for b in all_bins:
        box = bin_box(b, deg)
        if b in segs:
            rings = [valid(polygon([close_segment(p, box)])) for p in segs[b]]
            xors[b] = xor_all(rings)
            pt, dist = probe_point(lines(segs[b]), box)
            if dist < 1e-4:
                log(f"warning: bin {b}: probe point only {dist:.2g}° from the shoreline")
        else:
            pt = ogr.CreateGeometryFromWkt(f"POINT ({(box[0] + box[2]) / 2} {(box[1] + box[3]) / 2})")
        probes.append((b, pt))
    # One batched query: gmt select keeps the points on land (ocean/land/lake/island/pond).
    query = "".join(f"{pt.GetX()!r} {pt.GetY()!r} {i}\n" for i, (_, pt) in enumerate(probes))
    kept = run_gmt(["select", f"-D{res}", "-Ns/k/s/k/s", "-fg"], stdin=query)
    on_land = {int(float(line.split()[2])) for line in kept.splitlines() if line and line[0] != ">"}

    clip = ogr.Geometry(ogr.wkbMultiPolygon)
    for box in boxes:
        clip.AddGeometry(rectangle(*box))
    clip = clip.UnionCascaded()
    out = {}
    for i, (b, pt) in enumerate(probes):
        rect = rectangle(*bin_box(b, deg))
        land = xors.get(b, ogr.Geometry(ogr.wkbPolygon))
        if land.Intersects(pt) != (i in on_land):  # XOR gave the water: take the complement
            land = rect.Difference(land)
        if not clip.Contains(rect):
            land = land.Intersection(clip)
        land = polygons_only(valid(land))
        if decimals is not None and not land.IsEmpty():
            land = rounded(land, decimals)
        if not land.IsEmpty():
            out[b] = land
    return out


def output_ext(path):
    ext = next((x for x in sorted(DRIVERS, key=len, reverse=True) if path.endswith(x)), None)
    if ext is None:
        raise Failure(f"unsupported output extension in {path!r}; use one of {', '.join(DRIVERS)}")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.access(folder, os.W_OK):
        raise Failure(f"cannot write to the output folder {folder!r}")
    return ext


def write(out, path, decimals):
    ext = output_ext(path)
    folder, name = os.path.split(os.path.abspath(path))
    tmp = os.path.join(folder, f".{name[:-len(ext)]}.tmp{os.getpid()}{ext}")
    gdal_path = "/vsigzip/" + tmp if ext.endswith(".gz") else tmp
    opts = [f"COORDINATE_PRECISION={decimals}"] if DRIVERS[ext] == "GeoJSON" and decimals is not None else []
    try:
        ds = ogr.GetDriverByName(DRIVERS[ext]).CreateDataSource(gdal_path)
        srs = osr.SpatialReference()
        srs.ImportFromEPSG(4326)
        srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
        layer = ds.CreateLayer("land", srs, ogr.wkbMultiPolygon, options=opts)
        layer.CreateField(ogr.FieldDefn("bin", ogr.OFTInteger))
        layer.StartTransaction()
        for b in sorted(out):
            f = ogr.Feature(layer.GetLayerDefn())
            f.SetField("bin", b)
            f.SetGeometry(out[b])
            if layer.CreateFeature(f) != 0:
                raise Failure(f"writing bin {b} to {tmp} failed")
        layer.CommitTransaction()
        ds = layer = None  # closes (and for FlatGeobuf, builds the spatial index)
        os.replace(tmp, path)
    except BaseException:
        for leftover in (tmp, tmp + "-journal", tmp + "-wal", tmp + "-shm"):
            if os.path.exists(leftover):
                os.remove(leftover)
        raise


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--resolution", "-r", required=True, choices=list(BIN_DEG),
                    help="GSHHG resolution: f(ull), h(igh), i(ntermediate), l(ow), c(rude)")
    ap.add_argument("--bounds", "-b", type=parse_bounds, action="append",
                    help="W,S,E,N in degrees (repeatable; default the whole world)")
    ap.add_argument("--decimals", "-d", type=int, default=6,
                    help="round output coordinates to N decimals (default 6, ~0.1 m; negative: keep all)")
    ap.add_argument("-o", "--output", required=True, help="OUT.fgb, .gpkg, .geojson or .geojson.gz")
    ap.add_argument("-q", "--quiet", action="store_true")
    # argparse takes "-77,36.5,..." for an option; glue such values to their flag first.
    argv, i = sys.argv[1:], 0
    while i < len(argv) - 1:
        if argv[i] in ("--bounds", "-b"):
            argv[i:i + 2] = [f"--bounds={argv[i + 1]}"]
        i += 1
    args = ap.parse_args(argv)
    decimals = None if args.decimals < 0 else args.decimals
    boxes = [b for pair in (args.bounds or [parse_bounds("-180,-90,180,90")]) for b in pair]

    def log(msg):
        if not args.quiet:
            print(msg, file=sys.stderr)

    gdal.UseExceptions()
    ogr.UseExceptions()
    gdal.PushErrorHandler("CPLQuietErrorHandler")  # GEOS validity chatter; real errors raise
    try:
        if shutil.which("gmt") is None:
            raise Failure("'gmt' not found on PATH (Debian: apt install gmt gmt-gshhg)")
        output_ext(args.output)  # fail before the slow part
        out = build(args.resolution, boxes, decimals, log)
        write(out, args.output, decimals)
    except (Failure, RuntimeError, OSError) as err:
        print(f"{os.path.basename(sys.argv[0])}: error: {err}", file=sys.stderr)
        return 1
    log(f"wrote {len(out)} features to {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
