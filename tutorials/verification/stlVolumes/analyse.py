#!/usr/bin/env python3
"""The volume picInit filled in CASE (the particles' volumes summed) and the volume the STL surface
of SOLID encloses, against the solid's exact volume.

Usage: analyse.py CASE SOLID
Prints: particles, filled volume [m^3], exact volume [m^3], error [%], surface's error [%].
"""
import math
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_particles  # noqa: E402

EXACT = {'sphere': 4 / 3 * math.pi * 0.1 ** 3, 'box': 0.2 * 0.1 * 0.08, 'torus': 2 * math.pi ** 2 * 0.08 * 0.03 ** 2}


def stl_volume(path):
    """Volume a closed STL surface encloses (binary or ASCII), by the divergence theorem."""
    data = open(path, 'rb').read()
    triangles = []
    if data[:5] == b'solid' and b'facet' in data[:1000]:
        corners = [tuple(float(x) for x in line.split()[1:4])
                   for line in data.decode().splitlines() if line.strip().startswith('vertex')]
        triangles = [corners[k:k + 3] for k in range(0, len(corners), 3)]
    else:
        count = struct.unpack_from('<I', data, 80)[0]
        for f in range(count):
            v = struct.unpack_from('<12f', data, 84 + 50 * f)
            triangles.append([v[3:6], v[6:9], v[9:12]])
    six = 0.0
    for a, b, c in triangles:
        six += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2])
                + a[2] * (b[0] * c[1] - b[1] * c[0]))
    return six / 6


case, solid = sys.argv[1], sys.argv[2]
arrays = read_particles(os.path.join(case, '0', 'particles.vtp'))
volume = sum(arrays['volume'])
exact = EXACT[solid]
enclosed = stl_volume(os.path.join(case, 'constant', 'triSurface', solid + '.stl'))
if solid == 'box':
    enclosed *= 1e-9  # the file is in millimetres
print(len(arrays['volume']), '%.6g' % volume, '%.6g' % exact,
      '%.4f' % (100 * abs(volume - exact) / exact), '%.4f' % (100 * abs(enclosed - exact) / exact))
