#!/usr/bin/env python3
"""Heights of Terrarium / Terrain-RGB Web-Mercator tiles at points, decoded independently of globe.

Standard library only: a PNG reader (zlib + the five scanline filters; 8-bit grey, RGB, RGBA and
palette), the encodings' formulas, and bilinear interpolation between pixel centres at one zoom.
Usage: xyz_elevation_reference.py DIR terrarium|terrain-rgb ZOOM < lon,lat lines
       -> lon,lat,height lines (nan where a needed tile is missing or transparent)
DIR holds ZOOM/X/Y.png.
"""
import math
import os
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, palette, alpha = 8, b"", None, None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and interlace == 0, (path, depth, interlace)
        elif kind == b"PLTE":
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b"tRNS":
            alpha = list(body)
        elif kind == b"IDAT":
            idat += body
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[color]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        kind = raw[at]
        line = bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    pixels = []
    for line in rows:
        out = []
        for x in range(width):
            px = line[x * channels:(x + 1) * channels]
            if color == 3:
                rgb = palette[px[0]]
                out.append(rgb + ((alpha[px[0]] if alpha and px[0] < len(alpha) else 255),))
            elif color == 0:
                out.append((px[0], px[0], px[0], 255))
            elif color == 4:
                out.append((px[0], px[0], px[0], px[1]))
            elif color == 2:
                out.append((px[0], px[1], px[2], 255))
            else:
                out.append(tuple(px))
        pixels.append(out)
    return width, pixels


def height(encoding, rgba):
    r, g, b, a = rgba
    if a == 0:
        return None
    if encoding == "terrarium":
        return r * 256 + g + b / 256.0 - 32768
    return -10000 + (r * 65536 + g * 256 + b) * 0.1


def main():
    folder, encoding, zoom = sys.argv[1], sys.argv[2], int(sys.argv[3])
    tiles = {}
    size = 256

    def pixel(gx, gy):
        world = size << zoom
        gx %= world
        gy = min(max(gy, 0), world - 1)
        key = (gx // size, gy // size)
        if key not in tiles:
            path = os.path.join(folder, str(zoom), str(key[0]), "%d.png" % key[1])
            tiles[key] = read_png(path)[1] if os.path.exists(path) else None
        t = tiles[key]
        return None if t is None else height(encoding, t[gy % size][gx % size])

    for line in sys.stdin:
        if not line.strip():
            continue
        lon, lat = (float(s) for s in line.split(","))
        x = (lon + 180) / 360 * (size << zoom) - 0.5
        s = math.sin(math.radians(lat))
        y = (0.5 - math.log((1 + s) / (1 - s)) / (4 * math.pi)) * (size << zoom) - 0.5
        fx, fy = math.floor(x), math.floor(y)
        tx, ty = x - fx, y - fy
        total = weights = 0.0
        for dy in (0, 1):
            for dx in (0, 1):
                h = pixel(fx + dx, fy + dy)
                if h is None:
                    continue
                w = (tx if dx else 1 - tx) * (ty if dy else 1 - ty)
                total += w * h
                weights += w
        print("%.9g,%.9g,%s" % (lon, lat, "%.3f" % (total / weights) if weights > 0 else "nan"))


if __name__ == "__main__":
    main()
