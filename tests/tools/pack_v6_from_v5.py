#!/usr/bin/env python3
"""Rewrites a version-5 pack as version 6 from the format's description alone (src/formats/pack_format.hpp,
pack_index_codec.hpp, pack_block_codec.hpp), stdlib only: an independent encoder whose output the
C++ reader must take (the version-6 seeds of tests/fuzz/corpus/pack were made with it).

    pack_v6_from_v5.py IN.pack OUT.pack
"""
import struct, sys, zlib
def morton(x, y):
    k = 0
    for b in range(16):
        k |= ((x >> b) & 1) << (2 * b) | ((y >> b) & 1) << (2 * b + 1)
    return k
def zz(r):
    r = ((r + 32768) % 65536) - 32768
    return ((r << 1) ^ (r >> 15)) & 0xFFFF
def block6(raw, side):
    s = struct.unpack(f'>{side*side}h', raw)
    def pred(r, c):
        if r == 0: return 0 if c == 0 else s[c-1]
        if c == 0: return s[(r-1)*side]
        return s[r*side+c-1] + s[(r-1)*side+c] - s[(r-1)*side+c-1]
    z = [zz(s[r*side+c] - pred(r, c)) for r in range(side) for c in range(side)]
    planes = bytes(v >> 8 for v in z) + bytes(v & 255 for v in z)
    co = zlib.compressobj(6, zlib.DEFLATED, -15)
    body = co.compress(planes) + co.flush()
    return body + struct.pack('>I', zlib.crc32(body))
src, dst = sys.argv[1:3]
b = open(src, 'rb').read()
magic, ver, lvl, px, py, P, N, cnt, ib = struct.unpack('>8s8I', b[:40])
assert ver == 5
idx = zlib.decompress(b[40:40+ib])
side = N + 4; bb = side * side * 2
ents = [struct.unpack('>Q4hfI', idx[i*24:i*24+24]) for i in range(P*P)]
order = sorted([s for s in range(P*P) if ents[s][0]], key=lambda s: morton(s % P, s // P))
bitmap = bytearray((P*P+7)//8)
for s in order: bitmap[s//8] |= 1 << (s % 8)
blocks = []
for s in order:
    off = 40 + ib + ents[s][0] - 1
    blocks.append(block6(b[off:off+bb], side))
cols = bytes(bitmap) + b''.join(struct.pack('>I', len(x)) for x in blocks)
for c in range(1, 5):
    prev = 0
    for s in order:
        cols += struct.pack('>H', (ents[s][c] - prev) % 65536); prev = ents[s][c]
cols += b''.join(struct.pack('>f', ents[s][5]) for s in order)
index = zlib.compress(cols, 9)
out = b[:8] + struct.pack('>8I', 6, lvl, px, py, P, N, len(order), len(index)) + index + b''.join(blocks)
out += struct.pack('>I', zlib.crc32(out))
open(dst, 'wb').write(out)
