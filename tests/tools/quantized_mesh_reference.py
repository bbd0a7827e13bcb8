#!/usr/bin/env python3
"""Heights of a Cesium quantized-mesh-1.0 tile set at points, decoded independently of globe.

Written from the spec (github.com/CesiumGS/quantized-mesh) with the standard library only: reads
layer.json from a folder, finds the finest tile its "available" lists at each point, decodes the
tile (zig-zag deltas, high-water-mark indices) and interpolates the triangle that holds the point.
Usage: quantized_mesh_reference.py FOLDER < lon,lat lines  ->  lon,lat,level,height lines
"""
import gzip
import json
import os
import struct
import sys


def zigzag(n):
    return (n >> 1) ^ -(n & 1)


def decode(data):
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    header = struct.unpack_from("<3d2f4d3d", data, 0)
    min_h, max_h = header[3], header[4]
    pos = 88
    (count,) = struct.unpack_from("<I", data, pos)
    pos += 4
    arrays = []
    for _ in range(3):
        raw = struct.unpack_from("<%dH" % count, data, pos)
        pos += 2 * count
        value, out = 0, []
        for r in raw:
            value += zigzag(r)
            out.append(value)
        arrays.append(out)
    u, v, h = arrays
    wide = count > 65536
    size = 4 if wide else 2
    if pos % size:
        pos += size - pos % size
    (tri_count,) = struct.unpack_from("<I", data, pos)
    pos += 4
    codes = struct.unpack_from("<%d%s" % (tri_count * 3, "I" if wide else "H"), data, pos)
    highest, indices = 0, []
    for c in codes:
        indices.append(highest - c)
        if c == 0:
            highest += 1
    heights = [min_h + (max_h - min_h) * x / 32767.0 for x in h]
    return u, v, heights, indices


def available(layer, z, x, tms_y):
    levels = layer.get("available", [])
    if z >= len(levels):
        return False
    return any(r["startX"] <= x <= r["endX"] and r["startY"] <= tms_y <= r["endY"] for r in levels[z])


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
        u, v, heights, indices = decode(open(path, "rb").read())
        pu = (lon - (-180 + x * size)) / size * 32767
        pv = (lat - (-90 + tms_y * size)) / size * 32767
        for t in range(0, len(indices), 3):
            a, b, c = indices[t:t + 3]
            det = (v[b] - v[c]) * (u[a] - u[c]) + (u[c] - u[b]) * (v[a] - v[c])
            if det == 0:
                continue
            wa = ((v[b] - v[c]) * (pu - u[c]) + (u[c] - u[b]) * (pv - v[c])) / det
            wb = ((v[c] - v[a]) * (pu - u[c]) + (u[a] - u[c]) * (pv - v[c])) / det
            wc = 1 - wa - wb
            if min(wa, wb, wc) >= -1e-9:
                return z, wa * heights[a] + wb * heights[b] + wc * heights[c]
    return None


def main():
    folder = sys.argv[1]
    layer = json.load(open(os.path.join(folder, "layer.json")))
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
