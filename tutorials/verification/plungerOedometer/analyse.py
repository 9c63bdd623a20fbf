#!/usr/bin/env python3
"""Plunger oedometer (seed Case 4.5): stress path and plunger force against the closed form.

The sample (body 0) is in uniaxial strain d eps22 = V dt / L (seed eq. 4.5.1). Elastic:
    sigma22 = alpha1 eps22,  alpha1 = K + 4G/3.
Mohr-Coulomb (seed H.5.4), with N = (1 + sin)/(1 - sin) of phi and psi:
    yield at eps_y = -2 c sqrt(N_phi) / (alpha1 - alpha2 N_phi), alpha2 = K - 2G/3,
    then d sigma22 / d eps22 = alpha1 - 2 lam (alpha1 - alpha2 N_psi),
    lam = (alpha1 - alpha2 N_phi) / ((alpha1 + alpha2) N_phi N_psi - 2 alpha2 (N_phi + N_psi) + 2 alpha1).
The plunger force F (forces function object: the material's force on the plunger) is
compared with -sigma22 x 1 m (seed Fig. 4.26) and with -sigma22 (1 + eps22) x 1 m, the
nodal force of a sample that fills (1 + eps22) of its fixed 1 m cell.

Usage: analyse.py <case> [-series]. Prints three numbers:
    stress-path error   max |sigma22 - closed form| / |closed form| over t >= 0.1 ms
    force error         max |F + sigma22| / |sigma22| over 0.2 ms <= t <= 0.8 ms (|eps22| <= 0.8 %)
    consistent error    max |F + sigma22 (1 + eps22)| / |sigma22| over t >= 0.2 ms
-series writes series.dat in the case: time, -eps22, -sigma22, closed form, F, -sigma22 x 1 m.
"""
import math
import os
import re
import struct
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402


def read_vtp(path):
    """Float64/Int32 point arrays of a particles.vtp (raw appended data, UInt64 headers)."""
    data = open(path, 'rb').read()
    start = data.index(b'<AppendedData')
    base = data.index(b'_', start) + 1
    arrays = {}
    for m in re.finditer(r'<DataArray ([^>]*)/>', data[:start].decode('latin-1')):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        kind = {'Float64': 'd', 'Int32': 'i'}.get(attrs.get('type'))
        if kind is None or 'offset' not in attrs:
            continue
        offset = base + int(attrs['offset'])
        count = struct.unpack_from('<Q', data, offset)[0] // struct.calcsize(kind)
        values = struct.unpack_from('<%d%s' % (count, kind), data, offset + 8)
        k = int(attrs.get('NumberOfComponents', '1'))
        arrays[attrs['Name']] = [values[i:i + k] for i in range(0, count, k)] if k > 1 else list(values)
    return arrays


def sample_material(case):
    """Keywords of the material `sample` in constant/materials (numbers and the type)."""
    text = re.sub(r'//[^\n]*', '', open(os.path.join(case, 'constant/materials')).read())
    body = re.search(r'\bsample\s*\{([^}]*)\}', text).group(1)
    entries = dict(re.findall(r'(\w+)\s+([^;\s]+)\s*;', body))
    return {k: (v if k == 'type' else float(v)) for k, v in entries.items()}


def closed_form(mat):
    """sigma22(eps22) of seed H.5.4 for the sample's material (eps22 < 0, tension positive)."""
    if 'K' in mat:
        K, G = mat['K'], mat['G']
    else:
        K, G = mat['E'] / (3 * (1 - 2 * mat['nu'])), mat['E'] / (2 * (1 + mat['nu']))
    a1, a2 = K + 4 * G / 3, K - 2 * G / 3
    if mat['type'] != 'mohrCoulomb':
        return lambda e: a1 * e
    n_phi = (1 + math.sin(math.radians(mat['phi']))) / (1 - math.sin(math.radians(mat['phi'])))
    n_psi = (1 + math.sin(math.radians(mat.get('psi', 0)))) / (1 - math.sin(math.radians(mat.get('psi', 0))))
    eps_y = -2 * mat['c'] * math.sqrt(n_phi) / (a1 - a2 * n_phi)
    lam = (a1 - a2 * n_phi) / ((a1 + a2) * n_phi * n_psi - 2 * a2 * (n_phi + n_psi) + 2 * a1)
    slope = a1 - 2 * lam * (a1 - a2 * n_psi)
    return lambda e: a1 * e if e >= eps_y else a1 * eps_y + slope * (e - eps_y)


def time_directories(case):
    names = []
    for name in os.listdir(case):
        try:
            names.append((float(name), name))
        except ValueError:
            pass
    return sorted(names)


def main():
    case = sys.argv[1]
    sigma_cf = closed_form(sample_material(case))
    forces = read_columns(os.path.join(case, 'postProcessing/forces/0/forces.dat'))
    force_at = {round(t, 12): f for t, f in zip(forces['time'], forces['plunger:Fy'])}
    rows = []
    for t, name in time_directories(case):
        p = read_vtp(os.path.join(case, name, 'particles.vtp'))
        sample = [i for i, b in enumerate(p['body']) if b == 0]
        s22 = sum(p['stress'][i][4] for i in sample) / len(sample)
        e22 = sum(p['strain'][i][4] for i in sample) / len(sample)
        rows.append((t, e22, s22, sigma_cf(e22), force_at.get(round(t, 12))))
    stress_error = max(abs(s - c) / abs(c) for t, e, s, c, f in rows if t >= 1e-4 - 1e-12)
    force_error = max(abs(f + s) / abs(s) for t, e, s, c, f in rows
                      if f is not None and 2e-4 - 1e-12 <= t <= 8e-4 + 1e-12)
    consistent_error = max(abs(f + s * (1 + e)) / abs(s) for t, e, s, c, f in rows
                           if f is not None and t >= 2e-4 - 1e-12)
    print('%.3e %.3e %.3e' % (stress_error, force_error, consistent_error))
    if '-series' in sys.argv:
        with open(os.path.join(case, 'series.dat'), 'w') as out:
            out.write('# time -eps22 -sigma22 -sigma22_closed_form F -sigma22*1m\n')
            for t, e, s, c, f in rows:
                out.write('%.9g %.9g %.9g %.9g %s %.9g\n' % (t, -e, -s, -c, 'NaN' if f is None else '%.9g' % f, -s))


if __name__ == '__main__':
    main()
