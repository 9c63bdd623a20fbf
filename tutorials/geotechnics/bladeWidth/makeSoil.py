#!/usr/bin/env python3
"""The sand of the half model as a closed STL: the bin's block less the blade's slot.

The soil fills 0 <= x1 <= L, 0 <= x2 <= B, 0 <= x3 <= H, except the slot the blade stands in,
back <= x1 <= front, 0 <= x2 <= b (the blade's half-width, from the mid-plane x2 = 0, a
symmetry side), foot <= x3 <= H. No extruded polygon gives that solid, so it is written as
the boundary of a union of boxes: the lattice of the planes that bound the block and the
slot, every lattice box but the slot's filled, and each face between a filled box and an
empty one (or the outside) written as two triangles turned away from the filled box. Faces
on one lattice meet edge to edge, so the surface is closed, manifold and outward by
construction.

Usage: makeSoil.py <file.stl> L B H back front b foot
"""
import itertools
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from stlsurface import write_ascii  # noqa: E402


def soil(L, B, H, back, front, b, foot):
    planes = [sorted({0.0, back, front, L}), sorted({0.0, b, B}), sorted({0.0, foot, H})]
    size = [len(p) - 1 for p in planes]

    def filled(i, j, k):
        if not all(0 <= n < s for n, s in zip((i, j, k), size)):
            return False
        centre = [(planes[a][n] + planes[a][n + 1]) / 2 for a, n in enumerate((i, j, k))]
        in_slot = back < centre[0] < front and centre[1] < b and centre[2] > foot
        return not in_slot

    corners, index, facets = [], {}, []

    def corner(i, j, k):
        key = (i, j, k)
        if key not in index:
            index[key] = len(corners)
            corners.append((planes[0][i], planes[1][j], planes[2][k]))
        return index[key]

    for cell in itertools.product(*(range(s) for s in size)):
        if not filled(*cell):
            continue
        for axis, step in itertools.product(range(3), (-1, 1)):
            beside = list(cell)
            beside[axis] += step
            if filled(*beside):
                continue
            # the face's four corners, counter-clockwise seen from outside (normal along step)
            u, v = (axis + 1) % 3, (axis + 2) % 3
            level = cell[axis] + (1 if step > 0 else 0)
            quad = []
            for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                n = [0, 0, 0]
                n[axis], n[u], n[v] = level, cell[u] + du, cell[v] + dv
                quad.append(corner(*n))
            if step < 0:
                quad.reverse()
            facets += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
    return corners, facets


if __name__ == '__main__':
    if len(sys.argv) != 9:
        sys.exit(__doc__)
    path = sys.argv[1]
    L, B, H, back, front, b, foot = (float(x) for x in sys.argv[2:])
    os.makedirs(os.path.dirname(path) or '.', exist_ok=True)
    write_ascii(path, *soil(L, B, H, back, front, b, foot), name='soil')
