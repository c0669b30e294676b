#!/usr/bin/env python3
"""Writes the CAM-style chord circle of KRN-6 (docs/CONTOURING.md): a circle
of radius R as N G01 chords of C mm at F6000, counter-clockwise from (R, 0),
with #CONTOUR MODE [DEV PATH_DEV=..] and G261 unless --plain, or with
#HSC ON [BSPLINE PATH_DEV=.. MERGE=1] (KRN-9) with --hsc; the points with
--decimals decimals (9; CAM posts write 4).
Usage: chord_circle.py [--chords 10000] [--radius 15.9] [--chord 0.1]
                       [--path-dev 0.01] [--decimals 9] [--plain | --hsc] > part.nc"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("--chords", type=int, default=10000)
ap.add_argument("--radius", type=float, default=15.9)
ap.add_argument("--chord", type=float, default=0.1)
ap.add_argument("--path-dev", type=float, default=0.01)
ap.add_argument("--decimals", type=int, default=9)
ap.add_argument("--plain", action="store_true")
ap.add_argument("--hsc", action="store_true")
a = ap.parse_args()
step = 2 * math.asin(a.chord / (2 * a.radius))
print(f"%chord_circle ; {a.chords} chords of {a.chord} mm on R {a.radius} mm")
print(f"N1 G90 G00 X{a.radius:.6f} Y0 Z0")
if a.hsc:
    print(f"N2 #HSC ON [BSPLINE PATH_DEV={a.path_dev:g} MERGE=1]")
elif not a.plain:
    print(f"N2 #CONTOUR MODE [DEV PATH_DEV={a.path_dev:g}]")
for c in range(1, a.chords + 1):
    x, y = a.radius * math.cos(c * step), a.radius * math.sin(c * step)
    head = ("G01 G261 " if not (a.plain or a.hsc) else "G01 ") if c == 1 else ""
    tail = " F6000" if c == 1 else ""
    print(f"{head}X{x:.{a.decimals}f} Y{y:.{a.decimals}f}{tail}")
print("M30")
