#!/usr/bin/env python3
"""Writes the closed surfaces of the tutorial into constant/triSurface, as CAD would export them:
sphere.stl (binary: an icosahedron split LEVEL times, corners on a sphere of 0.1 m),
box.stl (ASCII, in millimetres as CAD often writes: 200 x 100 x 80 about the origin; the case
scales, turns and moves it) and
torus.stl (binary: tube 0.03 m at 0.08 m from the axis, N x N/2 quadrilaterals, two facets each).

Usage: makeSurfaces.py LEVEL N
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from stlsurface import sphere, write_ascii, write_binary  # noqa: E402


def box(lo=(-100, -50, -40), hi=(100, 50, 40)):
    corners = [(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]) for k in range(8)]
    facets = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
              (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    return corners, facets


def torus(n, centre=(0.15, 0.15, 0.1), R=0.08, r=0.03):
    m = n // 2
    corners = []
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            corners.append((centre[0] + (R + r * math.cos(v)) * math.cos(u),
                            centre[1] + (R + r * math.cos(v)) * math.sin(u), centre[2] + r * math.sin(v)))
    at = lambda i, j: (i % n) * m + (j % m)  # noqa: E731
    facets = []
    for i in range(n):
        for j in range(m):
            facets += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
    return corners, facets


level, n = int(sys.argv[1]), int(sys.argv[2])
os.makedirs('constant/triSurface', exist_ok=True)
write_binary('constant/triSurface/sphere.stl', *sphere(level))
write_ascii('constant/triSurface/box.stl', *box())
write_binary('constant/triSurface/torus.stl', *torus(n))
