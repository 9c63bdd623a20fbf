#!/usr/bin/env python3
"""Writes CASE/constant/triSurface/tube.stl (binary, as CAD exports it): the silo's glass wall, a
closed tube about the x3 axis from x3 = 0 to HEIGHT, inner radius 0.155 m and wall THICKNESS,
each circle a polygon of N sides with its corners on the circle (the facets' mid-chords lie
0.155 (1 - cos(pi / N)) inside it: 47 um for N = 128).

Usage: makeTube.py CASE THICKNESS HEIGHT [N]   (metres; default N 128: 8 N facets)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from stlsurface import write_binary  # noqa: E402

R = 0.155
if len(sys.argv) < 4:
    sys.exit('usage: makeTube.py CASE THICKNESS HEIGHT [N]')
case, thickness, height = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
n = int(sys.argv[4]) if len(sys.argv) > 4 else 128
corners = []
for k in range(n):   # per angle: inner bottom, inner top, outer bottom, outer top
    c, s = math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)
    for r in (R, R + thickness):
        corners += [(r * c, r * s, 0.0), (r * c, r * s, height)]
facets = []
for k in range(n):
    ib, it, ob, ot = 4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3
    jb, jt, pb, pt = [4 * ((k + 1) % n) + i for i in range(4)]
    # each facet's corners counter-clockwise seen from outside the solid
    facets += [(ob, pb, pt), (ob, pt, ot)]   # outer wall, normal away from the axis
    facets += [(ib, jt, jb), (ib, it, jt)]   # inner wall, normal towards the axis
    facets += [(it, ot, pt), (it, pt, jt)]   # top, normal +x3
    facets += [(ib, pb, ob), (ib, jb, pb)]   # bottom, normal -x3
os.makedirs(os.path.join(case, 'constant', 'triSurface'), exist_ok=True)
write_binary(os.path.join(case, 'constant', 'triSurface', 'tube.stl'), corners, facets)
