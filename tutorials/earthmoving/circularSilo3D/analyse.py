#!/usr/bin/env python3
"""Cylindrical silo discharge through a central circular orifice, in 3D (a quarter) or
axisymmetric: the mass in the silo against time and the mean flow rate against Beverloo et
al. (1961).

The massFlow function object writes the mass in the whole silo [kg] (the quarter times 4 in
3D, 2 pi times the mass per radian axisymmetric). The rate is the least-squares slope of
that mass from 0.2 s after the opening (etc/python/silodischarge.py).

Beverloo's rate through a circular orifice of diameter D (Beverloo, Leniger & van de Velde
1961, Chem. Eng. Sci. 15, 260-269; C and k as Nedderman 1992, Statics and Kinematics of
Granular Materials, ch. 10, recommends them):
    W = C rho sqrt(g) (D - k d)^2.5,   C = 0.58, k = 1.5   [kg/s]

The orifice the grid opens, D_h: the floor's open nodes, each with the floor area it stands
for (its tributary area: h1 h2 inside, half of it on a symmetry side, a quarter on the axis;
axisymmetric, the ring from r - h/2 to r + h/2, the disc of h/2 on the axis), add up to
A_open = pi D_h^2 / 4. The mass flux through the floor is the sum over these nodes of
rho v3 times that area (linear shape functions), so A_open is the opening the flow sees.
The nominal D (-w) gives W(D) beside it.

Usage: analyse.py <case> -rho R -d D -w W [-series]   (the output: silodischarge.py)
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from silodischarge import analyse  # noqa: E402

G, C, K = 9.81, 0.58, 1.5


def beverloo(rho, D, d):
    return C * rho * math.sqrt(G) * max(D - K * d, 0.0) ** 2.5


def numbers(text, key):
    return [float(v) for v in re.search(key + r'\s+\(([^)]*)\)', text).group(1).split()]


def opened_diameter(case):
    """D_h = sqrt(4 A_open / pi), A_open the open nodes' tributary floor area (above)."""
    text = re.sub(r'//[^\n]*', '', open(os.path.join(case, 'constant', 'grid')).read())
    h = numbers(text, 'cellSize')
    if len(numbers(text, 'nCells')) == 3:   # the quarter: a disc about (0 0) on the back side
        back = re.search(r'back\s*\{[^}]*opening\s*\{([^}]*)\}', text).group(1)
        radius = float(re.search(r'radius\s+([^;\s]+)', back).group(1))
        area = 0.0
        for i in range(int(radius / h[0]) + 1):
            for j in range(int(radius / h[1]) + 1):
                if (i * h[0]) ** 2 + (j * h[1]) ** 2 <= radius ** 2:
                    area += h[0] * h[1] * (0.5 if i == 0 else 1.0) * (0.5 if j == 0 else 1.0)
        return math.sqrt(4 * 4 * area / math.pi)
    end = numbers(text, 'opening')[1]   # axisymmetric: the bottom from the axis to `end`
    last = math.floor(end / h[0] + 1e-9) * h[0]
    return 2 * (last + 0.5 * h[0])


if __name__ == '__main__':
    if len(sys.argv) == 3 and sys.argv[2] == '-opened':
        print('%.6g' % opened_diameter(sys.argv[1]))
    else:
        analyse(sys.argv, beverloo, width='D', opened=opened_diameter)
