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
import struct
import sys


def sphere(level, centre=(0.15, 0.15, 0.15), radius=0.1):
    g = (1 + math.sqrt(5)) / 2
    corners = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
               (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    unit = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)  # noqa: E731
    corners = [unit(p) for p in corners]
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
    return [tuple(centre[k] + radius * p[k] for k in range(3)) for p in corners], facets


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


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return tuple(x / length for x in n)


def write_binary(path, corners, facets):
    with open(path, 'wb') as f:
        f.write(b' ' * 80 + struct.pack('<I', len(facets)))
        for t in facets:
            p = [corners[k] for k in t]
            f.write(struct.pack('<12fH', *normal(*p), *p[0], *p[1], *p[2], 0))


def write_ascii(path, corners, facets):
    with open(path, 'w') as f:
        f.write('solid box\n')
        for t in facets:
            p = [corners[k] for k in t]
            f.write(' facet normal %.17g %.17g %.17g\n  outer loop\n' % normal(*p))
            for c in p:
                f.write('   vertex %.17g %.17g %.17g\n' % c)
            f.write('  endloop\n endfacet\n')
        f.write('endsolid box\n')


level, n = int(sys.argv[1]), int(sys.argv[2])
os.makedirs('constant/triSurface', exist_ok=True)
write_binary('constant/triSurface/sphere.stl', *sphere(level))
write_ascii('constant/triSurface/box.stl', *box())
write_binary('constant/triSurface/torus.stl', *torus(n))
