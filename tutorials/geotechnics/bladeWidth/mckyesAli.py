#!/usr/bin/env python3
"""Draft force of a finite-width blade by McKyes & Ali (1977), J. Terramechanics 14(2) 43-58,
in the form of McKyes (1985), Soil Cutting and Tillage, Elsevier.

A blade of width w and rake angle alpha (from the horizontal; 90 deg: vertical) reaching d
below the surface fails a central wedge, bounded by a plane from the blade's tip rising at
beta to the surface a distance r = d (cot alpha + cot beta) ahead, and two side crescents,
circular sectors of radius r in plan over the angle rho = arccos(cot alpha / (cot alpha +
cot beta)) either side, whose failure surfaces run from the tip's corners to the arcs. For a
cohesionless soil without surcharge or adhesion (c = q = c_a = 0) the force on the blade,
at delta to its normal, is

    P = gamma d^2 w N_gamma,
    N_gamma = (r / 2d) [1 + (2 r / 3 w) sin rho] / [cos(alpha + delta) + sin(alpha + delta) cot(beta + phi)],

its draft (horizontal) part H = P sin(alpha + delta) and its vertical part V = P cos(alpha +
delta) (< 0 for a vertical blade: the soil lifts it). beta is the angle that makes N_gamma
least (the rupture the soil takes is the weakest of the family): golden-section search on
0 < beta < 90 - phi deg. As w grows the crescents' share vanishes and H/w is Coulomb's plane
passive wedge.

Usage: mckyesAli.py -phi 35 -delta D -rho 1500 -d 0.21 [-alpha 90] [-w 0.2 0.5 1.0 ...]
Prints per width: w [m], beta [deg], r [m], H/w and V/w [N/m] and their plane-strain values
(w -> infinity) and the ratio (H/w) / (H/w)_plane, the three-dimensional factor.
"""
import math
import sys


def n_gamma(beta, alpha, delta, phi, d, w):
    r = d * (1 / math.tan(alpha) + 1 / math.tan(beta))
    rho = math.acos(max(-1.0, min(1.0, (1 / math.tan(alpha)) * d / r)))
    side = 0.0 if w == math.inf else 2 * r / (3 * w) * math.sin(rho)
    return r / (2 * d) * (1 + side) / (math.cos(alpha + delta) + math.sin(alpha + delta) / math.tan(beta + phi))


def least(alpha, delta, phi, d, w):
    """beta that makes N_gamma least (golden section: N_gamma is unimodal in beta)."""
    a, b = math.radians(1e-3), math.pi / 2 - phi - math.radians(1e-3)
    g = (math.sqrt(5) - 1) / 2
    while b - a > 1e-12:
        c, e = b - g * (b - a), a + g * (b - a)
        if n_gamma(c, alpha, delta, phi, d, w) < n_gamma(e, alpha, delta, phi, d, w):
            b = e
        else:
            a = c
    beta = (a + b) / 2
    return beta, n_gamma(beta, alpha, delta, phi, d, w)


def forces(phi_deg, delta_deg, rho, d, w, alpha_deg=90.0, g=9.81):
    """(beta [deg], r [m], H/w, V/w [N/m]) of a blade of width w (math.inf: plane strain)."""
    phi, delta, alpha = (math.radians(x) for x in (phi_deg, delta_deg, alpha_deg))
    beta, n = least(alpha, delta, phi, d, w)
    p = rho * g * d * d * n
    r = d * (1 / math.tan(alpha) + 1 / math.tan(beta))
    return math.degrees(beta), r, p * math.sin(alpha + delta), p * math.cos(alpha + delta)


def main(argv):
    def value(name, default=None):
        if name in argv:
            return float(argv[argv.index(name) + 1])
        if default is None:
            sys.exit('mckyesAli.py: %s is required (see the docstring)' % name)
        return default
    phi, delta, rho, d = value('-phi'), value('-delta'), value('-rho'), value('-d')
    alpha = value('-alpha', 90.0)
    widths = [float(x) for x in argv[argv.index('-w') + 1:]] if '-w' in argv else [0.2, 0.5, 1.0]
    _, _, h2, v2 = forces(phi, delta, rho, d, math.inf, alpha)
    print('# w_m beta_deg r_m H_per_w V_per_w H_plane V_plane factor  (McKyes & Ali 1977; '
          'phi %g delta %g rho %g d %g alpha %g)' % (phi, delta, rho, d, alpha))
    for w in widths:
        beta, r, h, v = forces(phi, delta, rho, d, w, alpha)
        print('%g %.3f %.4f %.2f %.2f %.2f %.2f %.4f' % (w, beta, r, h, v, h2, v2, h / h2))


if __name__ == '__main__':
    main(sys.argv[1:])
