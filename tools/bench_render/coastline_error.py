#!/usr/bin/python3
"""Coastline position in a rendered view against a reference land/water raster of the same frame.

  coastline_error.py nearest POLYGONS LON LAT   the nearest shoreline vertex (lon,lat) to a point
  coastline_error.py compare VIEW.png REFERENCE.tif VALID.tif METRES_PER_PIXEL
      prints: the fraction of pixels whose class (sea: blue well above red and green, as the
      terrain's sea colour; else land) differs from the reference's (1 = land), the mean and the
      90th percentile distance in metres from each coast pixel of the view to the reference's
      nearest coast pixel, and the same from the reference's to the view's (tab-separated; "-"
      where the view draws no coast). Only pixels where VALID is non-zero count (the reference's
      polygons cover only their box).
Needs Debian's python3-gdal and python3-numpy (/usr/bin/python3).
"""
import sys

import numpy as np
from osgeo import gdal, ogr


def nearest(path, lon, lat):
    best = None
    source = ogr.Open(path)
    if source is None:
        sys.exit(f"{path}: not a vector file OGR can open")
    for layer in source:
        for feature in layer:
            geometry = feature.GetGeometryRef()
            for polygon in (geometry if geometry.GetGeometryName() == "MULTIPOLYGON" else [geometry]):
                for ring in polygon:
                    points = np.array(ring.GetPoints())[:, :2]
                    d = (points[:, 0] - lon) ** 2 * np.cos(np.radians(lat)) ** 2 + (points[:, 1] - lat) ** 2
                    i = int(np.argmin(d))
                    if best is None or d[i] < best[0]:
                        best = (d[i], points[i])
    print(f"{best[1][0]:.6f},{best[1][1]:.6f}")


def coast(land):
    """Pixels of either class with a 4-neighbour of the other."""
    edge = np.zeros_like(land, dtype=bool)
    edge[:-1, :] |= land[:-1, :] != land[1:, :]
    edge[1:, :] |= land[:-1, :] != land[1:, :]
    edge[:, :-1] |= land[:, :-1] != land[:, 1:]
    edge[:, 1:] |= land[:, :-1] != land[:, 1:]
    return np.argwhere(edge)


def distances(points, to):
    """Each point's distance (pixels) to the nearest of `to`, in chunks."""
    if len(points) == 0 or len(to) == 0:
        return np.array([np.inf])
    out = []
    for start in range(0, len(points), 512):
        chunk = points[start:start + 512, None, :] - to[None, :, :]
        out.append(np.sqrt((chunk ** 2).sum(axis=2).min(axis=1)))
    return np.concatenate(out)


def compare(view_path, reference_path, valid_path, metres):
    view = gdal.Open(view_path).ReadAsArray().astype(int)[:3]
    r, g, b = view
    view_land = ~((b > g + 20) & (b > r + 20))
    reference_land = gdal.Open(reference_path).ReadAsArray() > 0
    valid = gdal.Open(valid_path).ReadAsArray() > 0
    mismatch = float((view_land != reference_land)[valid].mean())
    # Coast pixels count away from the box's edge, where the reference's polygons are cut.
    inner = valid.copy()
    for _ in range(3):
        shrunk = inner.copy()
        shrunk[1:, :] &= inner[:-1, :]
        shrunk[:-1, :] &= inner[1:, :]
        shrunk[:, 1:] &= inner[:, :-1]
        shrunk[:, :-1] &= inner[:, 1:]
        inner = shrunk
    inside = lambda points: points[inner[points[:, 0], points[:, 1]]] if len(points) else points
    v, ref = inside(coast(view_land)), inside(coast(reference_land))
    if len(v) == 0:
        print(f"{mismatch:.4f}\t-\t-\t-\t-")
        return
    there = distances(v, ref) * metres
    back = distances(ref, v) * metres
    print(f"{mismatch:.4f}\t{there.mean():.0f}\t{np.percentile(there, 90):.0f}\t"
          f"{back.mean():.0f}\t{np.percentile(back, 90):.0f}")


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "nearest":
        nearest(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
    elif len(sys.argv) == 6 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3], sys.argv[4], float(sys.argv[5]))
    else:
        sys.exit(__doc__)
