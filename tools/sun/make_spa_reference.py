#!/usr/bin/env python3
"""Writes tests/data/sun/spa_pvlib.csv: the Sun's topocentric azimuth and geometric elevation (no
refraction) by pvlib's implementation of NREL's SPA, at 400 random instants of 1900-2100 and
random places, for tests/sun/test_solar_position.cpp to compare against. pvlib is not a Debian
package: give the path of its pvlib/spa.py (pvlib-python, BSD-3-Clause; it needs python3-numpy).

    /usr/bin/python3 tools/sun/make_spa_reference.py PATH/TO/pvlib/spa.py > tests/data/sun/spa_pvlib.csv
"""
import importlib.util
import random
import sys

spec = importlib.util.spec_from_file_location("spa", sys.argv[1])
spa = importlib.util.module_from_spec(spec)
spec.loader.exec_module(spa)
import numpy as np  # noqa: E402  (after spa, which imports it)

START, END = -2208988800, 4133980800  # 1900-01-01 and 2101-01-01, UTC
rng = random.Random(20261207)
print("unix_seconds,lon_deg,lat_deg,height_m,delta_t_s,azimuth_deg,elevation_deg")
for _ in range(400):
    t = float(rng.randrange(START, END))
    lon, lat = rng.uniform(-180, 180), rng.uniform(-89.9, 89.9)
    height = rng.choice([0.0, rng.uniform(0, 8000)])
    year = 1970 + t / 31556952
    delta_t = -20 + 32 * ((year - 1820) / 100) ** 2 - 0.5628 * (2150 - year)  # any ΔT: both sides use it
    _, _, _, e0, azimuth, _ = spa.solar_position_numpy(
        np.array([t]), lat, lon, height, 1010.0, 10.0, delta_t, 0.5667, 1)
    print(f"{t:.0f},{lon:.6f},{lat:.6f},{height:.2f},{delta_t:.3f},{azimuth[0]:.9f},{e0[0]:.9f}")
