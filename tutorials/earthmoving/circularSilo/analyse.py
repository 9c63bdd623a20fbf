#!/usr/bin/env python3
"""Cylindrical silo discharge through a central circular orifice: the mass in the silo
against time and the mean flow rate against Beverloo et al. (1961).

The massFlow function object writes the mass in the whole silo [kg] (axisymmetric: 2 pi
times the mass per radian). The flow rate is the least-squares slope of that mass against
time from 0.2 s after the opening (the flow has built up) until the mass falls to 30 % of
the initial mass or the run ends.

Beverloo's rate through a circular orifice of diameter D (Beverloo, Leniger & van de Velde
1961, Chem. Eng. Sci. 15, 260-269; C and k as Nedderman 1992, Statics and Kinematics of
Granular Materials, ch. 10, recommends them):
    W = C rho sqrt(g) (D - k d)^2.5,   C = 0.58, k = 1.5   [kg/s]
with rho the bulk density of the fill and d the grain size (corn d50 = 10 mm, as the plane
silo tutorial takes it). The orifice opens nodes of the grid's bottom side, so the orifice
the grid sees ends on the last open node: D_h = 2 x (that node's r); Allrun puts the
opening's end on the node nearest D/2. The reference is W(D_h); W(D) is printed beside it.

Usage: analyse.py <case> -rho R -d D -w W [-series]   (W: the nominal orifice diameter [m])
Prints: rate [kg/s], W(D_h), error against W(D_h) [%], W(D), D_h [m], initial mass [kg],
opening time [s], discharge time run [s], wall time of the discharge [s], particles at the
start, steps and wall time of the run, 1 when the discharge stage finished (0: the run
stopped inside it; the rate is then from the samples before the stop), and the mass left at
the end in % of the fill (etc/python/silodischarge.py). -series writes series.dat in the case: time after the opening [s],
mass in the silo [kg], the Beverloo line m(0.2 s) - W(D_h) (t - 0.2 s) [kg] (NaN before 0.2 s).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from silodischarge import analyse  # noqa: E402

G, C, K = 9.81, 0.58, 1.5


def beverloo(rho, D, d):
    return C * rho * math.sqrt(G) * max(D - K * d, 0.0) ** 2.5


analyse(sys.argv, beverloo, width='D')
