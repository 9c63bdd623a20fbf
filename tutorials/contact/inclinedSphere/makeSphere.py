#!/usr/bin/env python3
"""Writes constant/triSurface/sphere.stl (binary, as CAD exports it): a sphere of radius 0.5 m
about the origin, an icosahedron whose facets are split LEVEL times (20 x 4^LEVEL facets),
corners on the sphere. The case moves it into place (constant/bodies, translation).

Usage: makeSphere.py [LEVEL]   (default 4: 5120 facets, the volume 0.1 % short of the ball's)
"""
import math
import os
import struct
import sys


def icosphere(level):
    g = (1 + math.sqrt(5)) / 2
    unit = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)  # noqa: E731
    corners = [unit(p) for p in [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
                                 (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]]
    facets = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
              (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
              (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                corners.append(unit(tuple(corners[a][k] + corners[b][k] for k in range(3))))
                middle[key] = len(corners) - 1
            return middle[key]
        finer = []
        for a, b, c in facets:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        facets = finer
    return corners, facets


def write_binary_stl(path, corners, facets, radius):
    with open(path, 'wb') as f:
        f.write(b'sphere of radius 0.5 m'.ljust(80, b' '))
        f.write(struct.pack('<I', len(facets)))
        for facet in facets:
            p = [tuple(radius * c for c in corners[i]) for i in facet]
            u = [p[1][k] - p[0][k] for k in range(3)]
            v = [p[2][k] - p[0][k] for k in range(3)]
            n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            length = math.sqrt(sum(c * c for c in n))
            f.write(struct.pack('<12fH', *(c / length for c in n), *p[0], *p[1], *p[2], 0))


level = int(sys.argv[1]) if len(sys.argv) > 1 else 4
corners, facets = icosphere(level)
here = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(here, 'constant', 'triSurface'), exist_ok=True)
write_binary_stl(os.path.join(here, 'constant', 'triSurface', 'sphere.stl'), corners, facets, 0.5)
