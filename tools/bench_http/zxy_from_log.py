#!/usr/bin/env python3
"""Cuts the blocks a cold run fetched (nginx access log lines "GET URI 206 "bytes=A-B" SENT")
out of their packs into one file per range under WWW/PREFIX/<pack path>/<first byte>.bin, and
prints a curl config that fetches each of them from BASE_URL: the z/x/y layout's transport, for
the same bytes. Pack headers and indexes (ranges starting at byte 0) are left out: a z/x/y tree
has none.

    zxy_from_log.py ACCESS_LOG WWW PREFIX BASE_URL > curl.cfg
"""
import os
import re
import sys

log, www, prefix, base = sys.argv[1:5]
pattern = re.compile(r'^GET (\S+\.pack) 206 "bytes=(\d+)-(\d+)"')
count = 0
for line in open(log):
    m = pattern.match(line)
    if not m:
        continue
    uri, first, last = m.group(1), int(m.group(2)), int(m.group(3))
    if first == 0:
        continue
    with open(os.path.join(www, uri.lstrip('/')), 'rb') as pack:
        pack.seek(first)
        data = pack.read(last - first + 1)
    name = os.path.join(prefix, uri.lstrip('/').replace('.pack', ''), f'{first}.bin')
    os.makedirs(os.path.join(www, os.path.dirname(name)), exist_ok=True)
    with open(os.path.join(www, name), 'wb') as out:
        out.write(data)
    print(f'url = "{base}/{name}"\noutput = "/dev/null"')
    count += 1
print(f'{count} files', file=sys.stderr)
