#!/usr/bin/env python3
"""One silo run: the discharge rate against Beverloo et al. (1961) with the model's
parameters (rho_b the bulk density of the fill, d the grain diameter of muI).

Beverloo's rate through an orifice of width (plane, per metre of slot) or diameter
(axisymmetric) D, for grains of diameter d in a packing of bulk density rho_b:
    slot (plane):     W = C rho_b sqrt(g) (D - k d)^(3/2),  C = 45 sqrt(2) / 60 = 1.061, k = 0.7
                      [kg/s per m] (Beverloo, Leniger & van de Velde 1961 as the seed's
                      eq. 4.6.1 writes it, 45 rho sqrt(2 g) (D - 0.7 d)^1.5 in kg/min)
    circle (axisym.): W = C rho_b sqrt(g) (D - k d)^(5/2),  C = 0.58, k = 1.5   [kg/s]
                      (Beverloo, Leniger & van de Velde 1961; C and k as Nedderman 1992,
                      Statics and Kinematics of Granular Materials, ch. 10, recommends them)
taken at the width the grid opens, D_h (etc/python/silodischarge.py). The rate is the
least-squares slope of the mass in the silo (massFlow) from 0.2 s after the opening to the
end of the discharge (or until 30 % of the fill is left).

Usage: analyse.py <case> plane|axisymmetric -rho R -d D -w W [-series]
Prints the line of etc/python/silodischarge.py: rate [kg/s(/m)], W(D_h), error [%], W(D), D_h,
initial mass, opening time, discharge time, its wall time, particles, steps, wall, finished,
mass left [%].
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from silodischarge import analyse  # noqa: E402

G = 9.81
FORMS = {'plane': (45 * math.sqrt(2) / 60, 0.7, 1.5), 'axisymmetric': (0.58, 1.5, 2.5)}

if len(sys.argv) < 3 or sys.argv[2] not in FORMS:
    sys.exit('usage: analyse.py <case> plane|axisymmetric -rho R -d D -w W [-series]')
C, K, EXPONENT = FORMS[sys.argv.pop(2)]


def beverloo(rho, D, d):
    return C * rho * math.sqrt(G) * max(D - K * d, 0.0) ** EXPONENT


analyse(sys.argv, beverloo, width='D')
