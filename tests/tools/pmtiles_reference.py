#!/usr/bin/env python3
"""An independent PMTiles v3 reader (stdlib only), after the spec at
github.com/protomaps/PMTiles/blob/main/spec/v3/spec.md, to check the archives globe-tiler writes.

    pmtiles_reference.py ARCHIVE OUTDIR
    pmtiles_reference.py ARCHIVE -

Writes every tile the archive addresses as OUTDIR/{z}/{x}/{y}.{ext} (the extension from the
header's tile type), or with "-" lists each tile's CRC-32 as "crc32": {"z/x/y": crc}, and prints
the header, the metadata and counts as one JSON object. Walks
every directory (root and leaves), so a tile the directories address twice, or a directory
that is not in tile-id order, is an error.
"""
import gzip
import json
import os
import struct
import sys
import zlib

TILE_TYPES = {1: "mvt", 2: "png", 3: "jpg", 4: "webp", 5: "avif"}


def read_header(data):
    if data[:7] != b"PMTiles" or data[7] != 3:
        raise SystemExit("not a PMTiles v3 archive")
    (root_off, root_len, meta_off, meta_len, leaf_off, leaf_len, data_off, data_len,
     addressed, entries, contents) = struct.unpack_from("<11Q", data, 8)
    clustered, internal, tile_comp, tile_type, min_z, max_z = struct.unpack_from("<6B", data, 96)
    w, s, e, n = (v / 1e7 for v in struct.unpack_from("<4i", data, 102))
    center_z = data[118]
    center_lon, center_lat = (v / 1e7 for v in struct.unpack_from("<2i", data, 119))
    return dict(root_offset=root_off, root_length=root_len, metadata_offset=meta_off,
                metadata_length=meta_len, leaves_offset=leaf_off, leaves_length=leaf_len,
                tile_data_offset=data_off, tile_data_length=data_len, addressed_tiles=addressed,
                tile_entries=entries, tile_contents=contents, clustered=clustered,
                internal_compression=internal, tile_compression=tile_comp, tile_type=tile_type,
                min_zoom=min_z, max_zoom=max_z, bounds=[w, s, e, n], center_zoom=center_z,
                center=[center_lon, center_lat])


def decompress(blob, compression):
    if compression == 1:
        return blob
    if compression == 2:
        return gzip.decompress(blob)
    raise SystemExit(f"compression {compression} not read here")


def varints(blob):
    pos = 0
    while pos < len(blob):
        value, shift = 0, 0
        while True:
            byte = blob[pos]
            pos += 1
            value |= (byte & 0x7F) << shift
            shift += 7
            if not byte & 0x80:
                break
        yield value


def read_directory(blob):
    it = varints(blob)
    count = next(it)
    ids, last = [], 0
    for _ in range(count):
        last += next(it)
        ids.append(last)
    runs = [next(it) for _ in range(count)]
    lengths = [next(it) for _ in range(count)]
    offsets = []
    for i in range(count):
        value = next(it)
        if value == 0:
            if i == 0:
                raise SystemExit("first offset 0")
            offsets.append(offsets[-1] + lengths[i - 1])
        else:
            offsets.append(value - 1)
    if list(it):
        raise SystemExit("bytes after a directory's entries")
    return list(zip(ids, runs, lengths, offsets))


def zxy_of_tile_id(tile_id):
    """The spec's inverse: zoom from the counts of the zooms before, then the Hilbert curve."""
    acc, z = 0, 0
    while True:
        tiles = 1 << (2 * z)
        if acc + tiles > tile_id:
            break
        acc += tiles
        z += 1
    position = tile_id - acc
    n = 1 << z
    x = y = 0
    s, t = 1, position
    while s < n:
        rx = 1 & (t // 2)
        ry = 1 & (t ^ rx)
        if ry == 0:
            if rx == 1:
                x, y = s - 1 - x, s - 1 - y
            x, y = y, x
        x += s * rx
        y += s * ry
        t //= 4
        s *= 2
    return z, x, y


def main():
    archive, out = sys.argv[1], sys.argv[2]
    with open(archive, "rb") as f:
        data = f.read()
    h = read_header(data)
    if h["root_offset"] + h["root_length"] > 16384:
        raise SystemExit("the root directory ends beyond the first 16 KiB")
    internal = h["internal_compression"]
    meta_blob = data[h["metadata_offset"]:h["metadata_offset"] + h["metadata_length"]]
    metadata = json.loads(decompress(meta_blob, internal)) if meta_blob else {}
    ext = TILE_TYPES.get(h["tile_type"], "bin")
    seen, entries, leaves, written, previous_id = set(), 0, 0, 0, -1
    crcs = {}

    def walk(offset, length, depth):
        nonlocal entries, leaves, written, previous_id
        if depth > 3:
            raise SystemExit("directories nested too deep")
        blob = decompress(data[offset:offset + length], internal)
        for tile_id, run, size, tile_offset in read_directory(blob):
            if run == 0:
                leaves += 1
                walk(h["leaves_offset"] + tile_offset, size, depth + 1)
                continue
            if tile_id <= previous_id:
                raise SystemExit(f"tile id {tile_id} out of order")
            previous_id = tile_id + run - 1
            entries += 1
            start = h["tile_data_offset"] + tile_offset
            if tile_offset + size > h["tile_data_length"]:
                raise SystemExit(f"tile {tile_id} beyond the tile data")
            tile = decompress(data[start:start + size], h["tile_compression"])
            for i in range(run):
                z, x, y = zxy_of_tile_id(tile_id + i)
                if (z, x, y) in seen:
                    raise SystemExit(f"tile {z}/{x}/{y} addressed twice")
                seen.add((z, x, y))
                written += 1
                if out == "-":
                    crcs[f"{z}/{x}/{y}"] = zlib.crc32(tile)
                    continue
                path = os.path.join(out, str(z), str(x), f"{y}.{ext}")
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "wb") as f:
                    f.write(tile)

    walk(h["root_offset"], h["root_length"], 0)
    summary = dict(header=h, metadata=metadata, tiles=written, entries=entries,
                   leaf_directories=leaves)
    if out == "-":
        summary["crc32"] = crcs
    print(json.dumps(summary, sort_keys=True))


if __name__ == "__main__":
    main()
