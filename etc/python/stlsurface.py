"""Closed triangulated surfaces for the tutorials' STL files, as CAD would export them: a
sphere refined from an icosahedron, a plane profile extruded across a width, and the ASCII
(one solid, or one solid per named part) and binary STL writers."""
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
    write_ascii_parts(path, corners, {name: facets})


def triangulate(polygon):
    """Ear clipping of a simple polygon [(u, v), ...], counter-clockwise: triangles as index
    triples, each counter-clockwise."""
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def inside(p, a, b, c):
        return cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0

    left, triangles = list(range(len(polygon))), []
    while len(left) > 3:
        for k in range(len(left)):
            i, j, m = left[k - 1], left[k], left[(k + 1) % len(left)]
            a, b, c = polygon[i], polygon[j], polygon[m]
            if cross(a, b, c) <= 0:
                continue   # a reflex (or straight) corner is no ear
            if any(inside(polygon[q], a, b, c) for q in left if q not in (i, j, m)):
                continue
            triangles.append((i, j, m))
            del left[k]
            break
        else:
            raise ValueError('triangulate: the polygon is not simple or not counter-clockwise')
    triangles.append(tuple(left))
    return triangles


class Extrusion:
    """A solid built from plane profiles in (x1, x3), each extruded along x2 over a range, as
    named parts of one closed surface. Corners are shared by their exact coordinates, so faces
    that meet edge to edge make a closed, manifold surface; each facet is turned so that its
    normal points along the outward direction the caller gives."""

    def __init__(self):
        self.corners, self.index, self.parts = [], {}, {}

    def corner(self, p):
        key = tuple(round(x, 12) for x in p)
        if key not in self.index:
            self.index[key] = len(self.corners)
            self.corners.append(key)
        return self.index[key]

    def facet(self, part, a, b, c, outward):
        n = normal(a, b, c)
        if sum(n[k] * outward[k] for k in range(3)) < 0:
            b, c = c, b
        self.parts.setdefault(part, []).append((self.corner(a), self.corner(b), self.corner(c)))

    def wall(self, part, a, b, y0, y1):
        """The band over y0 <= x2 <= y1 along the profile's edge a -> b (u = x1, v = x3), the
        solid on the edge's left."""
        outward = (b[1] - a[1], 0.0, -(b[0] - a[0]))
        p = [(a[0], y0, a[1]), (b[0], y0, b[1]), (b[0], y1, b[1]), (a[0], y1, a[1])]
        self.facet(part, p[0], p[1], p[2], outward)
        self.facet(part, p[0], p[2], p[3], outward)

    def cap(self, part, polygon, y, side):
        """The profile (counter-clockwise in (x1, x3)) as a face at x2 = y, facing side (+-1)."""
        for i, j, k in triangulate(polygon):
            self.facet(part, *[(polygon[q][0], y, polygon[q][1]) for q in (i, j, k)], (0.0, side, 0.0))

    def volume(self):
        v = 0.0
        for facets in self.parts.values():
            for i, j, k in facets:
                a, b, c = self.corners[i], self.corners[j], self.corners[k]
                v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                      + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
        return v


def write_ascii_parts(path, corners, parts):
    """One ASCII STL holding a solid per named part: `solid tooth` ... `endsolid tooth`."""
    with open(path, 'w') as f:
        for name, facets in parts.items():
            f.write('solid %s\n' % name)
            for t in facets:
                p = [corners[k] for k in t]
                f.write(' facet normal %.17g %.17g %.17g\n  outer loop\n' % normal(*p))
                for c in p:
                    f.write('   vertex %.17g %.17g %.17g\n' % c)
                f.write('  endloop\n endfacet\n')
            f.write('endsolid %s\n' % name)
