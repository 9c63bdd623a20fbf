"""Closed triangulated surfaces for the tutorials' STL files, as CAD would export them: a
sphere refined from an icosahedron, and the ASCII and binary STL writers."""
import math
import struct


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


def write_ascii(path, corners, facets, name='box'):
    with open(path, 'w') as f:
        f.write('solid %s\n' % name)
        for t in facets:
            p = [corners[k] for k in t]
            f.write(' facet normal %.17g %.17g %.17g\n  outer loop\n' % normal(*p))
            for c in p:
                f.write('   vertex %.17g %.17g %.17g\n' % c)
            f.write('  endloop\n endfacet\n')
        f.write('endsolid %s\n' % name)
