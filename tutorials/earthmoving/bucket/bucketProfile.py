#!/usr/bin/env python3
"""The dragline bucket of seed fig. 6.3 as a polygon, and the corn bed around its tooth.

Reconstruction of fig. 6.3 (labels 75, 140, 93, R_i 100, 190, 200, 40 deg, 15, 40 mm; the
figure is a drawing, the text gives no coordinates). The bucket moves in +x1, its mouth
facing the motion. In the bucket's own frame (mm), the inside of the floor is y = 0 and the
inside of the back wall x = 0:
  - floor: inside length 200 (back wall to lip); plates t thick (fig.: 15 mm, so that the
    outside length is 200 + 15 = 215 = 75 + 140, the two labels along the top);
  - back corner: inside radius R_i = 100, centre (100, 100);
  - back wall: inside face x = 0 up to the hood; outside height 190 (floor bottom to hood top,
    with t = 15: hood underside at y = 160);
  - hood: a plate along the top at the back, 75 long from the outside of the back wall, so the
    mouth between the hood's front and the lip is 140 wide;
  - tooth: the floor plate continued 40 mm beyond the lip, bent 40 deg down, t thick.
  The label 93 is not placed (perhaps the side plates' arch, which a plane section does not
  cut). The moment centre O_m is not dimensioned; the moment is taken about the outside
  back-bottom corner. A thicker wall (t > 15 mm, at least one cell) grows outwards: the inside
  of the bucket stays as drawn.

Usage: bucketProfile.py t x0 y0 [-corn width depth]
  t       wall thickness [m]; x0, y0: where the floor's outside bottom at the back wall's
          outside face goes [m] (the bucket rests with its floor on the corn: y0 = depth);
  prints  the bucket polygon `((x y) ...)` [m], counter-clockwise;
  -corn   prints instead the corn bed 0 <= x1 <= width, 0 <= x2 <= depth with the tooth cut out.
  -faces  prints the inside faces (tooth tip, floor, corner in 6 chords, back wall, hood
          underside) as `x0 y0 x1 y1` rows, the material on the right (for picForces -surface).
  -rho M  prints instead the density [kg/m^3] that gives the bucket M kg per metre of width.
  -inside prints instead the bucket's inside (the faces of -faces from the lip on, closed by
          the mouth from the hood's front to the lip) as a polygon: what it carries (toolFill's
          region).
  -tooth L A  a tooth L mm long bent A degrees down (fig. 6.3: 40 mm, 40 deg), for a study of
          the bucket's geometry (tutorials/studies/bucketGeometry).
  -dat F  also writes the polygon (mm, bucket frame, t = 15 mm) to F for the bucket.png picture.
"""
import math
import sys

FLOOR, RADIUS, HOOD_Y, HOOD, TOOTH, ANGLE = 200.0, 100.0, 160.0, 75.0, 40.0, 40.0


def outline(t, arc=12):
    """Polygon of the bucket [mm] in its frame, counter-clockwise, and the tooth's corners."""
    a = math.radians(ANGLE)
    d = (math.cos(a), -math.sin(a))     # along the tooth, forward and down
    n = (-math.sin(a), -math.cos(a))    # across the tooth, its underside
    root = (FLOOR, 0.0)                 # the lip: the floor's inside front corner
    tip_top = (root[0] + TOOTH * d[0], root[1] + TOOTH * d[1])
    tip_bot = (tip_top[0] + t * n[0], tip_top[1] + t * n[1])
    # the tooth's underside meets the floor's underside y = -t
    b0 = (root[0] + t * n[0], root[1] + t * n[1])
    s = (b0[1] + t) / math.sin(a)
    under = (b0[0] + s * d[0], b0[1] + s * d[1])
    c = (RADIUS, RADIUS)
    pts = [(c[0], -t), under, tip_bot, tip_top, root, (c[0], 0.0)]
    for k in range(1, arc):             # inside corner, from the floor up to the back wall
        th = math.radians(270 - 90 * k / arc)
        pts.append((c[0] + RADIUS * math.cos(th), c[1] + RADIUS * math.sin(th)))
    pts += [(0.0, c[1]), (0.0, HOOD_Y), (HOOD - t, HOOD_Y), (HOOD - t, HOOD_Y + t), (-t, HOOD_Y + t),
            (-t, c[1])]
    for k in range(1, arc):             # outside corner, back down to the floor
        th = math.radians(180 + 90 * k / arc)
        pts.append((c[0] + (RADIUS + t) * math.cos(th), c[1] + (RADIUS + t) * math.sin(th)))
    return pts, tip_top, tip_bot, under


def inside_faces(arc=6):
    """Inside of the bucket [mm, bucket frame] from the tooth's tip to the hood's front, as
    straight faces with the material on their right."""
    a = math.radians(ANGLE)
    tip = (FLOOR + TOOTH * math.cos(a), -TOOTH * math.sin(a))
    pts = [tip, (FLOOR, 0.0), (RADIUS, 0.0)]
    for k in range(1, arc):
        th = math.radians(270 - 90 * k / arc)
        pts.append((RADIUS + RADIUS * math.cos(th), RADIUS + RADIUS * math.sin(th)))
    pts += [(0.0, RADIUS), (0.0, HOOD_Y), (HOOD - 15.0, HOOD_Y)]
    return pts


def place(pts, t, x0, y0):
    """Bucket frame [mm] to the case [m]: the outside back-bottom corner (-t, -t) at (x0, y0)."""
    return [((x + t) * 1e-3 + x0, (y + t) * 1e-3 + y0) for x, y in pts]


def corn_bed(t, x0, y0, width, depth):
    """The bed 0 <= x <= width, 0 <= y <= depth [m] with the tooth's notch cut out,
    counter-clockwise; t [mm], the bucket placed at (x0, y0) as by place()."""
    _, tip_top, tip_bot, under = outline(t)
    a = math.radians(ANGLE)
    # where the tooth's top face crosses the corn's surface (the floor's underside)
    s = t / math.sin(a)
    cross = (FLOOR + s * math.cos(a), -t)
    notch = place([cross, tip_top, tip_bot, under], t, x0, y0)
    notch = [(x, min(y, depth)) for x, y in notch]
    return [(0.0, 0.0), (width, 0.0), (width, depth)] + notch + [(0.0, depth)]


def fmt(pts):
    return '(' + ' '.join(f'({x:.6f} {y:.6f})' for x, y in pts) + ')'


def main(argv):
    global TOOTH, ANGLE
    if '-tooth' in argv:
        k = argv.index('-tooth')
        TOOTH, ANGLE = float(argv[k + 1]), float(argv[k + 2])
    t, x0, y0 = float(argv[1]) * 1e3, float(argv[2]), float(argv[3])
    pts, tip_top, tip_bot, under = outline(t)
    if '-dat' in argv:
        p15 = outline(15.0)[0]
        with open(argv[argv.index('-dat') + 1], 'w') as f:
            f.write('# bucket of seed fig. 6.3 as reconstructed: x, y [mm], t = 15 mm\n')
            for x, y in p15 + p15[:1]:
                f.write(f'{x:.2f} {y:.2f}\n')
            f.write('\n\n# inside faces (stresses on the bucket)\n')
            for x, y in inside_faces():
                f.write(f'{x:.2f} {y:.2f}\n')
    if '-corn' in argv:
        k = argv.index('-corn')
        print(fmt(corn_bed(t, x0, y0, float(argv[k + 1]), float(argv[k + 2]))))
    elif '-rho' in argv:
        m = float(argv[argv.index('-rho') + 1])
        q = place(pts, t, 0.0, 0.0)
        area = 0.5 * abs(sum(xa * yb - xb * ya for (xa, ya), (xb, yb) in zip(q, q[1:] + q[:1])))
        print(f'{m / area:.1f}')
    elif '-inside' in argv:
        print(fmt(place(inside_faces()[1:], t, x0, y0)))
    elif '-faces' in argv:
        f = place(inside_faces(), t, x0, y0)
        for (xa, ya), (xb, yb) in zip(f[:-1], f[1:]):
            print(f'{xa:.6f} {ya:.6f} {xb:.6f} {yb:.6f}')
    else:
        print(fmt(place(pts, t, x0, y0)))


if __name__ == '__main__':
    main(sys.argv)
