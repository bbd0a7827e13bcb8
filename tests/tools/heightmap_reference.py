#!/usr/bin/env python3
"""Heights of a Cesium heightmap-1.0 tile set at points, decoded independently of globe.

Written from the format's description (CesiumJS's HeightmapTerrainData: 65x65 little-endian
uint16 heights, h / 5 - 1000 metres, rows from the north, then a child mask and a water mask)
with the standard library only: reads layer.json from a folder, finds the finest tile its
"available" lists at each point and interpolates the grid cell's triangle that holds the point
(cells split from north-west to south-east, as globe's renderer splits them).
Usage: heightmap_reference.py FOLDER < lon,lat lines  ->  lon,lat,level,height lines
"""
import gzip
import json
import math
import os
import struct
import sys

SIDE = 65


def decode(data):
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    raw = struct.unpack_from("<%dH" % (SIDE * SIDE), data, 0)
    heights = [r / 5.0 - 1000.0 for r in raw]
    child_mask = data[SIDE * SIDE * 2]
    water = data[SIDE * SIDE * 2 + 1:]
    if len(water) not in (0, 1, 256 * 256):
        raise ValueError("water mask of %d bytes" % len(water))
    return heights, child_mask, water


def available(layer, z, x, tms_y):
    levels = layer.get("available", [])
    if z >= len(levels):
        return False
    return any(r["startX"] <= x <= r["endX"] and r["startY"] <= tms_y <= r["endY"] for r in levels[z])


def interpolate(heights, fx, fy):
    """fx east, fy south, both 0..SIDE-1 across the tile."""
    j = min(int(math.floor(fx)), SIDE - 2)
    i = min(int(math.floor(fy)), SIDE - 2)
    s, t = fx - j, fy - i
    nw = heights[i * SIDE + j]
    ne = heights[i * SIDE + j + 1]
    sw = heights[(i + 1) * SIDE + j]
    se = heights[(i + 1) * SIDE + j + 1]
    if s >= t:  # north-east of the diagonal: nw, ne, se
        return nw + s * (ne - nw) + t * (se - ne)
    return nw + t * (sw - nw) + s * (se - sw)  # south-west: nw, sw, se


def height_at(folder, layer, lon, lat):
    for z in range(len(layer["available"]) - 1, -1, -1):
        size = 180.0 / (1 << z)
        x = int((lon + 180) // size)
        tms_y = int((lat + 90) // size)
        if not available(layer, z, x, tms_y):
            continue
        path = os.path.join(folder, str(z), str(x), "%d.terrain" % tms_y)
        if not os.path.exists(path):
            continue
        heights, _, _ = decode(open(path, "rb").read())
        fx = (lon - (-180 + x * size)) / size * (SIDE - 1)
        fy = ((-90 + (tms_y + 1) * size) - lat) / size * (SIDE - 1)
        return z, interpolate(heights, fx, fy)
    return None


def main():
    folder = sys.argv[1]
    layer = json.load(open(os.path.join(folder, "layer.json")))
    if layer.get("format") != "heightmap-1.0":
        sys.exit("%s: format %r, not heightmap-1.0" % (folder, layer.get("format")))
    for line in sys.stdin:
        if not line.strip():
            continue
        lon, lat = (float(s) for s in line.split(","))
        found = height_at(folder, layer, lon, lat)
        if found:
            print("%.9g,%.9g,%d,%.3f" % (lon, lat, found[0], found[1]))
        else:
            print("%.9g,%.9g,-1,nan" % (lon, lat))


if __name__ == "__main__":
    main()
