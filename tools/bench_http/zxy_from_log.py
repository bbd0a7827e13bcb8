#!/usr/bin/env python3
"""Cuts the blocks a cold run fetched (nginx access log lines "GET URI 206 "bytes=A-B" SENT")
out of their packs into one file per block under WWW/PREFIX/<pack path>/<first byte>.bin, and
prints a curl config that fetches each of them from BASE_URL: the z/x/y layout's transport, for
the same blocks. Pack headers and indexes are left out (a z/x/y tree has none). A range that
read several adjacent blocks at once (a version-6 pack's neighbours) is cut into its blocks, each
its own file; blocks a reader took from the bytes it read with a pack's index (an older pack's
first read held its first blocks) are cut from those bytes, as many as LOADED (the run's tile
loads) says there were.

    zxy_from_log.py ACCESS_LOG WWW PREFIX BASE_URL [LOADED] > curl.cfg
"""
import os
import re
import struct
import sys
import zlib

log, www, prefix, base = sys.argv[1:5]
loaded = int(sys.argv[5]) if len(sys.argv) > 5 else None
pattern = re.compile(r'^GET (\S+\.pack) 206 "bytes=(\d+)-(\d+)"')
HEADER = 40


def block_bytes(header):
    version, _, _, _, tiles, n, _, index_bytes = struct.unpack('>8I', header[8:40])
    side = n + 4 if version >= 3 else n
    return side * side * 2


def index_end(header):
    version, _, _, _, tiles, _, _, index_bytes = struct.unpack('>8I', header[8:40])
    entry = 24 if version >= 4 else 20 if version >= 3 else 16
    return HEADER + (index_bytes if version >= 5 else tiles * tiles * entry)


def block_ranges(pack, header):
    """Where each block of a version-6 pack lies: a sorted list of (offset, bytes)."""
    version, _, _, _, tiles, _, present, index_bytes = struct.unpack('>8I', header[8:40])
    pack.seek(HEADER)
    columns = zlib.decompress(pack.read(index_bytes))
    bitmap = (tiles * tiles + 7) // 8
    sizes = struct.unpack(f'>{present}I', columns[bitmap:bitmap + 4 * present])
    ranges, offset = [], HEADER + index_bytes
    for size in sizes:
        ranges.append((offset, size))
        offset += size
    return ranges


blocks = []      # (uri, first byte, bytes) fetched by their own range
in_heads = []    # the same for blocks that came with an index read
for line in open(log):
    m = pattern.match(line)
    if not m:
        continue
    uri, first, last = m.group(1), int(m.group(2)), int(m.group(3))
    with open(os.path.join(www, uri.lstrip('/')), 'rb') as pack:
        header = pack.read(HEADER)
        version = struct.unpack('>I', header[8:12])[0]
        if first != 0 and version >= 6:
            for offset, size in block_ranges(pack, header):
                if first <= offset and offset + size <= last + 1:
                    pack.seek(offset)
                    blocks.append((uri, offset, pack.read(size)))
            continue
        if first != 0:
            pack.seek(first)
            blocks.append((uri, first, pack.read(last - first + 1)))
            continue
        size, start = block_bytes(header), index_end(header)
        offset = start
        while offset + size <= last + 1:
            pack.seek(offset)
            in_heads.append((uri, offset, pack.read(size)))
            offset += size
extra = max(0, (loaded - len(blocks)) if loaded is not None else 0)
for uri, first, data in blocks + in_heads[:extra]:
    name = os.path.join(prefix, uri.lstrip('/').replace('.pack', ''), f'{first}.bin')
    os.makedirs(os.path.join(www, os.path.dirname(name)), exist_ok=True)
    with open(os.path.join(www, name), 'wb') as out:
        out.write(data)
    print(f'url = "{base}/{name}"\noutput = "/dev/null"')
print(f'{len(blocks)} blocks by range, {min(extra, len(in_heads))} read with an index', file=sys.stderr)
