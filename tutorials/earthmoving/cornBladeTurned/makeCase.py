#!/usr/bin/env python3
"""Write the blade-in-corn case of ../cornBlade (seed 6.2.5) turned on the grid.

The seed turns its 80 x 50 mesh through 35 degrees anticlockwise (fig. 6.19) to show that the
polar continuum's shear band does not follow the mesh. A structured grid cannot turn, so the
scene turns the other way instead: corn, blade and rig by -angle about the rig's lower left
corner, gravity with them. The rig's sides and floor, grid sides in ../cornBlade, become fixed
rigid bodies: the sides smooth (mu 0, as the grid's slip sides), the floor rough (mu 1, for
the grid's fixed floor; the corn's own friction is tan 26 = 0.49). Rigid bodies hold the
Cosserat rotation (the rigidBodies default), as ../cornBlade's grid sides do in polar runs.
With angle 0 the same generator gives the upright rig with the same walls: the reference.

Geometry in the rig's frame (s along the floor, n up), as ../cornBlade, on the grid's lines
when angle = 0: floor n = 0, corn to n = foot + h, blade 20 mm thick from s = 0.1 m, its foot
0.1 m above the floor, 0.35 m high; walls two cells thick.

Usage: makeCase.py <dir> <nonpolar|polar> <angle deg> <dx m> <h m> <v mm/s> <travel m>
Writes <dir>/system, <dir>/constant (materials and schemes from ../cornBlade) and <dir>/turn.dat (angle,
the offset of the rig's corner, the blade's front s and foot n) for analyse.py.
"""
import math
import os
import shutil
import sys

HEADER = 'FoamFile {{ version 2.0; format ascii; class dictionary; location "{}"; object {}; }}\n\n'


def write(case, path, text):
    location, name = os.path.split(path)
    with open(os.path.join(case, path), 'w') as f:
        f.write(HEADER.format(location, name) + text)


def main():
    case, model, angle, dx, h, v, travel = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:8])
    # The corn, its materials and schemes are ../cornBlade's (found through GPIC_DIR, so a copy
    # of this tutorial elsewhere still finds them).
    blade_case = os.path.join(os.environ.get('GPIC_DIR', os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                      '..', '..', '..')),
                              'tutorials', 'earthmoving', 'cornBlade')
    snap = lambda x: round(round(x / dx) * dx, 9)  # noqa: E731
    length = round(math.ceil(1.2 / dx - 1e-6) * dx, 9)
    foot, back = snap(0.1), snap(0.1)
    surface = round(foot + round(h / dx) * dx, 9)
    front = round(back + max(1, round(0.02 / dx)) * dx, 9)
    top = round(foot + 0.35, 9)
    wall = 2 * dx
    height = round(surface + 4 * dx, 9)

    phi = -math.radians(angle)  # the scene turns against the mesh
    c, s = math.cos(phi), math.sin(phi)
    polygons = {
        'corn': [(0, 0), (length, 0), (length, surface), (front, surface), (front, foot), (0, foot)],
        'blade': [(back, foot), (front, foot), (front, top), (back, top)],
        'floor': [(-wall, -wall), (length + wall, -wall), (length + wall, 0), (-wall, 0)],
        'left': [(-wall, 0), (0, 0), (0, height), (-wall, height)],
        'right': [(length, 0), (length + wall, 0), (length + wall, height), (length, height)],
    }
    turned = {k: [(c * a - s * b, s * a + c * b) for a, b in p] for k, p in polygons.items()}
    corners = [x for p in turned.values() for x in p]
    # The rig's corner on a grid node, one cell in from the grid's lower left.
    offset = tuple(math.ceil((dx - min(x[k] for x in corners)) / dx - 1e-9) * dx for k in (0, 1))
    n = [math.ceil((max(x[k] for x in corners) + offset[k] + dx) / dx - 1e-9) for k in (0, 1)]

    for d in ('system', 'constant'):
        os.makedirs(os.path.join(case, d), exist_ok=True)
    shutil.copy(os.path.join(blade_case, 'constant', 'materials'), os.path.join(case, 'constant', 'materials'))
    shutil.copy(os.path.join(blade_case, 'system', 'mpmSchemes'), os.path.join(case, 'system', 'mpmSchemes'))

    def points(name):
        return ' '.join(f'({x + offset[0]:.9g} {y + offset[1]:.9g})' for x, y in turned[name])

    material = 'cornPolar' if model == 'polar' else 'corn'
    write(case, 'constant/bodies', '// The rig of ../cornBlade turned by %g deg on the grid (makeCase.py).\n' % -angle + ''.join(
        f'{name} {{ material {material if name == "corn" else "steel"}; particlesPerCell 2; '
        f'shape {{ type polygon; points ({points(name)}); }} }}\n' for name in polygons))
    write(case, 'constant/grid',
          f'// Cells of {dx:g} m around the turned rig; nothing reaches the grid sides.\n'
          f'origin (0 0);\ncellSize {dx:g};\nnCells ({n[0]} {n[1]});\n'
          'boundaries { left { type free; } right { type free; } bottom { type free; } top { type free; } }\n')
    write(case, 'constant/g', f'value ({9.81 * s:.9g} {-9.81 * c:.9g});   // (0 -9.81) turned with the rig\n')
    speed = v * 1e-3
    write(case, 'constant/rigidBodies',
          f'blade {{ type prescribedVelocity; velocity ({speed * c:.9g} {speed * s:.9g}); }}   // {v:g} mm/s along the floor\n'
          'floor { type fixed; }\nleft  { type fixed; }\nright { type fixed; }\n')
    write(case, 'constant/contactProperties',
          '// Corn on steel: mu = tan 14 = 0.249 (seed table 6.1); the sides smooth, the floor rough.\n'
          'law coulombFriction;\nnormals rigidSurface;\nmu 0.249;\ncorrectRemapped no;   // as the upright run (doc/contact.md)\n'
          'pairs\n{\n    left  { bodies (corn left); mu 0; }\n    right { bodies (corn right); mu 0; }\n'
          '    floor { bodies (corn floor); mu 1; }\n}\n')
    write(case, 'system/controlDict',
          'application picSolver;\nstartFrom latestTime;\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n'
          f'writeControl adjustableRunTime;\nwriteInterval {0.0025 / speed:.6g};   // every 2.5 mm of travel\n'
          'timePrecision 6;\n\nstages\n{\n'
          f'    fill {{ type geostaticFill; fill (corn); phi 26; layerThickness {snap(0.15):g}; '
          'drivers { blade { type fixed; } } until { equilibrium 1e-4; maxTime 0.5; } }\n'
          f'    push {{ type moveTool; body blade; until {{ displacement {travel:g}; }} }}\n}}\n\n'
          'functions\n{\n    forces { type forces; bodies (blade); writeInterval 20; }\n}\n')
    with open(os.path.join(case, 'turn.dat'), 'w') as f:
        f.write('# angle_deg offset_x offset_y front_s foot_n surface_n\n')
        f.write(f'{angle:g} {offset[0]:.9g} {offset[1]:.9g} {front:.9g} {foot:.9g} {surface:.9g}\n')


if __name__ == '__main__':
    main()
