#!/usr/bin/env python3
"""The dragline bucket of seed fig. 6.3 at the rig's width as CAD would export it, and the corn
bed around its tooth, as STL files for a half model (the mid-plane x2 = 0 a symmetry side).

The profile is tutorials/earthmoving/bucket's reconstruction of fig. 6.3 (bucketProfile.py,
walls t thick, grown outwards from the inside as drawn), in the plane (x1, x3): x1 the drag,
x3 up. Across the width x2 the half bucket is:
  - 0 <= x2 <= B - t: the profile (floor, tooth, back corner, back wall, hood), open at the
    mouth;
  - B - t <= x2 <= B: the side plate, t thick, whose outline is the profile with its mouth
    closed by the straight edge from the lip to the hood's front (the tooth included); its
    outer face lies on the rig's glass side x2 = B.
The parts, written as the solids of one ASCII STL (what the forces and toolWear function
objects report per part): tooth (the plate bent down beyond the lip), floor, back (the
corner and the back wall, inside and out), hood, side (the side plate's inner face, its front
edge and its outer face) and mid (the face on the mid-plane, where the mirrored half joins:
no material pushes on it).

Files written into CASE/constant/triSurface/:
  bucket.stl  the half bucket, the outside back-bottom corner of its profile at (X0, 0, Z0);
  inside.stl  what the bucket carries: its inside, from the lip on, closed by the mouth,
              0 <= x2 <= B - t (toolFill's region);
  corn.stl    the bed 0 <= x1 <= L, 0 <= x2 <= B, 0 <= x3 <= DEPTH less the tooth's notch.

Usage: makeBucket.py CASE t X0 Z0 B L DEPTH     (metres)
       makeBucket.py -rho t B                   the steel density [kg/m^3] that gives the bucket
                                                with walls t thick the mass of the 15 mm one
                                                in steel of 7850 kg/m^3
"""
import os
import sys

GPIC_DIR = os.environ.get('GPIC_DIR', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'))
sys.path.insert(0, os.path.join(GPIC_DIR, 'tutorials', 'earthmoving', 'bucket'))
sys.path.insert(0, os.path.join(GPIC_DIR, 'etc', 'python'))
import bucketProfile as profile  # noqa: E402
from stlsurface import Extrusion, write_ascii, write_ascii_parts  # noqa: E402


def part_of_edges(t):
    """The part each edge of the outline (bucketProfile.outline: k -> k + 1) belongs to."""
    pts = profile.outline(t)[0]
    arc = (len(pts) - 12) // 2 + 1     # the outline's arcs have arc - 1 points each
    names = ['floor', 'tooth', 'tooth', 'tooth', 'floor']          # bottom, tooth (3), inside floor
    names += ['back'] * arc                                          # inside corner, to (0, R)
    names += ['back', 'hood', 'hood', 'hood', 'back', 'back']        # back wall .. outside back
    names += ['back'] * (len(pts) - len(names))                      # outside corner
    return pts, names


def bucket(t, x0, z0, B):
    """The half bucket [m] as an Extrusion; the profile's frame (mm) placed by bucketProfile."""
    pts, names = part_of_edges(t * 1e3)
    pts = profile.place(pts, t * 1e3, x0, z0)
    n = len(pts)
    lip, hood_front = 4, 5 + (n - 12) // 2 + 3          # the lip; the hood's lower front corner
    # inner chain lip -> ... -> hood front is reversed: the inside lies on its right
    inside = [pts[k] for k in range(hood_front, lip - 1, -1)]
    silhouette = pts[:lip + 1] + pts[hood_front:]
    s = Extrusion()
    y = B - t
    for k in range(n):
        a, b = pts[k], pts[(k + 1) % n]
        s.wall(names[k], a, b, 0.0, y)
        if not lip <= k < hood_front:
            s.wall(names[k], a, b, y, B)               # the side plate's rim carries the profile's part
    s.wall('side', pts[lip], pts[hood_front], y, B)    # the side plate's front edge, across the mouth
    s.cap('mid', pts, 0.0, -1)
    s.cap('side', inside, y, -1)
    s.cap('side', silhouette, B, +1)
    return s, inside


def main(argv):
    if argv[1:2] == ['-rho']:
        t, B = float(argv[2]), float(argv[3])
        print(f'{7850 * bucket(0.015, 0, 0, B)[0].volume() / bucket(t, 0, 0, B)[0].volume():.1f}')
        return
    case, t, x0, z0, B, L, depth = argv[1], *map(float, argv[2:8])
    out = os.path.join(case, 'constant', 'triSurface')
    os.makedirs(out, exist_ok=True)
    s, inside = bucket(t, x0, z0, B)
    write_ascii_parts(os.path.join(out, 'bucket.stl'), s.corners, s.parts)
    carried = Extrusion()
    carried.cap('inside', inside, 0.0, -1)
    carried.cap('inside', inside, B - t, +1)
    for a, b in zip(inside, inside[1:] + inside[:1]):
        carried.wall('inside', a, b, 0.0, B - t)
    write_ascii(os.path.join(out, 'inside.stl'), carried.corners, carried.parts['inside'], 'inside')
    # the bed with the tooth's notch, as bucketProfile.py -corn draws it in the plane
    bed = profile.corn_bed(t * 1e3, x0, z0, L, depth)
    corn = Extrusion()
    corn.cap('corn', bed, 0.0, -1)
    corn.cap('corn', bed, B, +1)
    for a, b in zip(bed, bed[1:] + bed[:1]):
        corn.wall('corn', a, b, 0.0, B)
    write_ascii(os.path.join(out, 'corn.stl'), corn.corners, corn.parts['corn'], 'corn')
    for name, e in (('bucket', s), ('inside', carried), ('corn', corn)):
        print(f'{name}.stl: {sum(map(len, e.parts.values()))} facets, volume {e.volume():.6e} m^3')


if __name__ == '__main__':
    main(sys.argv)
