#!/usr/bin/env python3
"""Builds the bundled gazetteer data/places/places.tsv.gz from real open data (stdlib only):

* GeoNames cities1000 (every place of 1,000 people or more; CC BY 4.0, geonames.org): name, ASCII
  name, Latin-script alternate names of places of 100,000 or more (at most 12; 40 for a million:
  "Wien", "Munchen"),
  position, feature code, country, first-level division, population;
* Natural Earth 1:110m admin-0 countries (public domain): name, ISO code, label point, population;
* Natural Earth 1:110m elevation points (public domain): named peaks, depressions and passes;
* the bundled data's own landmarks (tools/places/landmarks.tsv: the peaks and parks the bundled
  DEMs show, positions from GNIS, GSI Japan and Ordnance Survey);
* first-level division names (tools/places/divisions.tsv: "Texas" for US TX, "Ontario" for CA 08)
  for "NAME, DIVISION" queries, each checked against GeoNames: the division's largest place must
  be the one the table names, or the build stops.

One place a line, tab-separated: name, ASCII names (|-separated: the name folded, its
alternates), latitude, longitude, kind (city, country, peak, park, depression, pass, landmark),
country code, division code, population, elevation (m, or empty), importance (what ranking
sorts by: population; a peak's elevation × 2,000, so Everest outranks a village named after it).
A division is a line of kind "division" (importance 0, at the population-weighted mean of its
places): what "NAME, DIVISION" names, never a search result itself.

    build_places.py GEONAMES_CITIES1000 NE_COUNTRIES NE_ELEVATION_POINTS LANDMARKS DIVISIONS \
        OUT.tsv.gz
    build_places.py --check-divisions GEONAMES_CITIES1000 DIVISIONS   (only the check)
"""
import gzip
import io
import json
import sys
import unicodedata


# ASCII for U+00C0..U+017F, as src/places/name_fold.cpp folds them ("" : a separator).
LATIN = ['a', 'a', 'a', 'a', 'a', 'a', 'ae', 'c', 'e', 'e', 'e', 'e', 'i', 'i', 'i', 'i', 'd', 'n', 'o', 'o', 'o', 'o', 'o', '', 'o', 'u', 'u', 'u', 'u', 'y', 'th', 'ss', 'a', 'a', 'a', 'a', 'a', 'a', 'ae', 'c', 'e', 'e', 'e', 'e', 'i', 'i', 'i', 'i', 'd', 'n', 'o', 'o', 'o', 'o', 'o', '', 'o', 'u', 'u', 'u', 'u', 'y', 'th', 'y', 'a', 'a', 'a', 'a', 'a', 'a', 'c', 'c', 'c', 'c', 'c', 'c', 'c', 'c', 'd', 'd', 'd', 'd', 'e', 'e', 'e', 'e', 'e', 'e', 'e', 'e', 'e', 'e', 'g', 'g', 'g', 'g', 'g', 'g', 'g', 'g', 'h', 'h', 'h', 'h', 'i', 'i', 'i', 'i', 'i', 'i', 'i', 'i', 'i', 'i', 'ij', 'ij', 'j', 'j', 'k', 'k', 'k', 'l', 'l', 'l', 'l', 'l', 'l', 'l', 'l', 'l', 'l', 'n', 'n', 'n', 'n', 'n', 'n', 'n', 'n', 'n', 'o', 'o', 'o', 'o', 'o', 'o', 'oe', 'oe', 'r', 'r', 'r', 'r', 'r', 'r', 's', 's', 's', 's', 's', 's', 's', 's', 't', 't', 't', 't', 't', 't', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'u', 'w', 'w', 'y', 'y', 'y', 'z', 'z', 'z', 'z', 'z', 'z', 's']


# Natural Earth 1:110m says -99 for these countries' ISO code (a dispute over overseas parts):
# without one "Paris, France" would find nothing.
MISSING_ISO_A2 = {'France': 'FR', 'Norway': 'NO'}


def fold(text):
    """Lower-case ASCII as src/places/name_fold.cpp makes it: letters and digits, the Latin-1 and
    Latin Extended-A letters as their ASCII, combining accents dropped, anything else one space."""
    pieces, space = [], False
    for c in text:
        o = ord(c)
        if o < 0x80 and c.isalnum():
            piece = c.lower()
        elif 0xC0 <= o <= 0x17F:
            piece = LATIN[o - 0xC0]
        elif 0x300 <= o <= 0x36F:
            continue
        else:
            piece = ''
        if not piece:
            space = bool(pieces)
            continue
        if space:
            pieces.append(' ')
        space = False
        pieces.append(piece)
    return ''.join(pieces)


def latin(text):
    return all(c.isascii() or unicodedata.category(c).startswith('M') or
               'LATIN' in unicodedata.name(c, '') for c in text)


def largest_polygon_centroid(geometry):
    """(lat, lon) of the area centroid of a (multi)polygon's largest outer ring."""
    polygons = geometry['coordinates'] if geometry['type'] == 'MultiPolygon' else [
        geometry['coordinates']]
    best = None
    for polygon in polygons:
        ring = polygon[0]
        area = cx = cy = 0.0
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            cross = x0 * y1 - x1 * y0
            area += cross
            cx += (x0 + x1) * cross
            cy += (y0 + y1) * cross
        if area and (best is None or abs(area) > best[0]):
            best = (abs(area), cy / (3 * area), cx / (3 * area))
    return best[1], best[2]


def read_divisions(path):
    """(country, code, name, alternates, largest place) for each line of divisions.tsv."""
    divisions = []
    for line in open(path, encoding='utf-8'):
        if line.startswith('#') or not line.strip():
            continue
        country, code, name, alternates, largest = line.rstrip('\n').split('\t')
        divisions.append((country, code, name, [a for a in alternates.split('|') if a], largest))
    return divisions


def check_divisions(cities, divisions):
    """The mismatches: each division's largest GeoNames place must be the one the table names
    (a code matched to the wrong division's name shows up there)."""
    largest = {}
    for line in open(cities, encoding='utf-8'):
        f = line.rstrip('\n').split('\t')
        key, population = (f[8], f[10]), int(f[14] or 0)
        if key not in largest or population > largest[key][0]:
            largest[key] = (population, f[1])
    wrong = []
    for country, code, name, _, expected in divisions:
        found = largest.get((country, code), (0, None))[1]
        if found != expected:
            wrong.append(f'{country} {code} {name}: the largest place is {found}, not {expected}')
    return wrong


def division_rows(cities, divisions):
    """Gazetteer lines for the divisions, at the population-weighted mean of their places."""
    sums = {}
    for line in open(cities, encoding='utf-8'):
        f = line.rstrip('\n').split('\t')
        weight = max(int(f[14] or 0), 1)
        s = sums.setdefault((f[8], f[10]), [0.0, 0.0, 0])
        s[0] += float(f[4]) * weight
        s[1] += float(f[5]) * weight
        s[2] += weight
    rows = []
    for country, code, name, alternates, _ in divisions:
        lat, lon, weight = sums[(country, code)]
        keys = []
        for n in [name] + alternates:
            if fold(n) and fold(n) not in keys:
                keys.append(fold(n))
        rows.append((name, keys, lat / weight, lon / weight, 'division', country, code, 0, '', 0))
    return rows


def main():
    if sys.argv[1] == '--check-divisions':
        wrong = check_divisions(sys.argv[2], read_divisions(sys.argv[3]))
        print('\n'.join(wrong) or f'{sys.argv[3]}: every division checked', file=sys.stderr)
        sys.exit(1 if wrong else 0)
    cities, countries, points, landmarks, divisions_file, out = sys.argv[1:7]
    divisions = read_divisions(divisions_file)
    wrong = check_divisions(cities, divisions)
    if wrong:
        sys.exit(f'{divisions_file}: divisions that GeoNames does not confirm:\n' + '\n'.join(wrong))
    rows = []
    for line in open(cities, encoding='utf-8'):
        f = line.rstrip('\n').split('\t')
        name, ascii_name, alternates = f[1], f[2], f[3]
        population = int(f[14] or 0)
        keys = [fold(name)]
        if fold(ascii_name) not in keys:
            keys.append(fold(ascii_name))
        if population >= 100000:
            cap = 40 if population >= 1000000 else 12
            for alternate in alternates.split(','):
                key = fold(alternate)
                if alternate and latin(alternate) and key and key not in keys and len(keys) < cap:
                    keys.append(key)
        rows.append((name, keys, float(f[4]), float(f[5]), 'city', f[8], f[10], population,
                     f[15] or f[16], population))
    for feature in json.load(open(countries, encoding='utf-8'))['features']:
        p = feature['properties']
        code = next((c for c in (p['ISO_A2'], p.get('ISO_A2_EH'), MISSING_ISO_A2.get(p['NAME']))
                     if c and c != '-99'), '')
        keys = []
        for n in (p['NAME'], p['NAME_LONG'], p['ADMIN'], p['FORMAL_EN'] or '', p['ABBREV'] or ''):
            if n and fold(n) and fold(n) not in keys:
                keys.append(fold(n))
        population = int(p['POP_EST'] or 0)
        lat, lon = largest_polygon_centroid(feature['geometry'])
        rows.append((p['NAME'], keys, lat, lon, 'country', code, '', population, '', population))
    landmark_keys = set()
    for line in open(landmarks, encoding='utf-8'):
        if not line.startswith('#') and line.strip():
            fields = line.rstrip('\n').split('\t')
            landmark_keys.update([fold(fields[0])] + [fold(a) for a in fields[6].split('|') if a])
    for feature in json.load(open(points, encoding='utf-8'))['features']:
        p = feature['properties']
        if not p['name']:
            continue
        lon, lat = feature['geometry']['coordinates']
        kind = {'mountain': 'peak'}.get(p['featurecla'], p['featurecla'])
        elevation = p['elevation']
        keys = [fold(p['name'])]
        for prefix in ('mt ', 'mount ', 'gora ', 'cerro ', 'cero '):
            if keys[0].startswith(prefix):
                keys.append(keys[0][len(prefix):])
        if landmark_keys.intersection(keys):
            continue  # the landmark list has it, with its country
        rows.append((p['name'], keys, lat, lon, kind, '', '', 0, f'{elevation:g}',
                     int(max(elevation, 0) * 2000)))
    for line in open(landmarks, encoding='utf-8'):
        if line.startswith('#') or not line.strip():
            continue
        name, lat, lon, kind, country, elevation, aliases = line.rstrip('\n').split('\t')
        keys = [fold(name)] + [fold(a) for a in aliases.split('|') if a]
        importance = int(float(elevation) * 2000) if elevation else 1_000_000
        rows.append((name, keys, float(lat), float(lon), kind, country, '', 0, elevation,
                     importance))
    rows += division_rows(cities, divisions)
    rows.sort(key=lambda r: -r[9])  # stable: divisions (importance 0) last, in the table's order
    # mtime 0 and no name in the gzip header: the same inputs give the same bytes.
    with open(out + '.tmp', 'wb') as raw, \
            gzip.GzipFile(filename='', fileobj=raw, mode='wb', compresslevel=9, mtime=0) as z, \
            io.TextIOWrapper(z, encoding='utf-8', newline='\n') as o:
        for name, keys, lat, lon, kind, country, division, population, elevation, importance in rows:
            o.write(f'{name}\t{"|".join(keys)}\t{lat:.5f}\t{lon:.5f}\t{kind}\t{country}\t{division}'
                    f'\t{population}\t{elevation}\t{importance}\n')
    import os
    os.replace(out + '.tmp', out)
    print(f'{out}: {len(rows)} places', file=sys.stderr)


main()
