#!/usr/bin/env python3
"""Plane silo discharge (seed 6.3): mass in the silo against time and the mean flow rate
against Beverloo et al. (1961).

The massFlow function object (factor 2 x 0.73: the whole 0.73 m deep glass silo of the half
model) writes the mass in the silo [kg]. The flow rate is the least-squares slope of that
mass against time from 0.2 s after the opening (the flow has built up; the seed's curves
are straight from there) until the mass falls to 30 % of the initial mass or the run ends.

Beverloo's rate through a slot of width w per metre of silo depth (seed eq. 4.6.1, the
constant 45 in kg/min), times the silo's depth:
    W = 45 rho sqrt(2 g) (w - 0.7 d)^1.5 / 60 x 0.73   [kg/s]
with rho the (constant) bulk density and d the grain size (corn d50 = 10 mm, sand 1 mm).
The outlet opens nodes of the grid's bottom side, so the orifice the grid sees ends on the
last open node: w_h = 2 x (that node's x1); Allrun puts the opening's end on the node
nearest w/2. The reference is W(w_h); W(w) is printed beside it.

Usage: analyse.py <case> -rho R -d D -w W [-series]
Prints: rate [kg/s], W(w_h), error against W(w_h) [%], W(w), w_h [m], initial mass [kg],
opening time [s], discharge time run [s], wall time of the discharge [s], particles at the
start, steps and wall time of the run, 1 when the discharge stage finished (0: the run
stopped inside it; the rate is then from the samples before the stop), and the mass left at
the end in % of the fill (etc/python/silodischarge.py). -series writes series.dat in the case: time after the opening [s], mass in the silo
[kg], the Beverloo line m(0.2 s) - W(w_h) (t - 0.2 s) [kg] (NaN before 0.2 s).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from silodischarge import analyse  # noqa: E402

G, DEPTH = 9.81, 0.73


def beverloo(rho, w, d):
    return 45 * rho * math.sqrt(2 * G) * max(w - 0.7 * d, 0.0) ** 1.5 / 60 * DEPTH


analyse(sys.argv, beverloo)
