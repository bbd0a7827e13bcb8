#!/usr/bin/env python3
"""Writes fuji_footprints.geojson: synthetic building footprints (no real buildings) around
Fujiyoshida and on Mount Fuji's northern slope, inside the bundled Fuji DEM's square. Rectangles
given by centre and size in metres, a courtyard with a hole, an L shape, a pentagon, a
multi-polygon, one footprint across the pyramid's tile edge at 138.8671875° E (a level-10 edge of
the 2x1 geographic quadtree and of every finer level), one with building:levels only, one with no
height at all. Run: python3 make_footprints.py > fuji_footprints.geojson"""
import json
import math

M_PER_DEG_LAT = 110574.0


def rect(lon, lat, east_m, north_m):
    dlon = east_m / 2 / (111320.0 * math.cos(math.radians(lat)))
    dlat = north_m / 2 / M_PER_DEG_LAT
    return [[round(lon - dlon, 8), round(lat - dlat, 8)], [round(lon + dlon, 8), round(lat - dlat, 8)],
            [round(lon + dlon, 8), round(lat + dlat, 8)], [round(lon - dlon, 8), round(lat + dlat, 8)],
            [round(lon - dlon, 8), round(lat - dlat, 8)]]


def offsets(lon, lat, points_m):
    k = 111320.0 * math.cos(math.radians(lat))
    ring = [[round(lon + x / k, 8), round(lat + y / M_PER_DEG_LAT, 8)] for x, y in points_m]
    return ring + [ring[0]]


def feature(name, geometry, **props):
    return {"type": "Feature", "properties": {"name": name, **props}, "geometry": geometry}


def polygon(*rings):
    return {"type": "Polygon", "coordinates": list(rings)}


courtyard_hole = list(reversed(rect(138.8050, 35.4790, 30, 30)))
features = [
    feature("A", polygon(rect(138.8000, 35.4800, 30, 20)), height="12", roof_m=31),
    feature("B", polygon(rect(138.8020, 35.4810, 15, 15)), height="25.5 m"),
    feature("C courtyard", polygon(rect(138.8050, 35.4790, 60, 60), courtyard_hole), height=9),
    feature("D levels only", polygon(rect(138.8100, 35.4850, 20, 12)), **{"building:levels": "4"}),
    feature("E no height", polygon(rect(138.8120, 35.4860, 20, 20))),
    feature("F across a tile edge", polygon(rect(138.8671875, 35.4500, 40, 30)), height=18),
    feature("G on the slope", polygon(rect(138.7400, 35.4000, 80, 60)), height=10),
    feature("H L-shape", polygon(offsets(138.7450, 35.4050,
            [(0, 0), (40, 0), (40, 12), (12, 12), (12, 30), (0, 30)])), height=6),
    feature("I", polygon(rect(138.8800, 35.4950, 25, 25)), height=40),
    feature("J height and levels", polygon(rect(138.8300, 35.4600, 18, 30)), height=7,
            **{"building:levels": "2"}),
    feature("K", polygon(rect(138.8700, 35.4700, 50, 10)), height=15, roof_m=33),
    feature("L pentagon", polygon(offsets(138.7800, 35.4300,
            [(0, 0), (20, -5), (30, 10), (15, 25), (-5, 15)])), height=20),
    feature("M two parts", {"type": "MultiPolygon", "coordinates": [
        [rect(138.8500, 35.4900, 12, 12)], [rect(138.8503, 35.4900, 12, 12)]]}, height=8),
]
print(json.dumps({"type": "FeatureCollection", "features": features}, indent=1))
