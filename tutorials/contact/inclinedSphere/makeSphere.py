#!/usr/bin/env python3
"""Writes constant/triSurface/sphere.stl (binary, as CAD exports it): a sphere of radius 0.5 m
about the origin, an icosahedron whose facets are split LEVEL times (20 x 4^LEVEL facets),
corners on the sphere. The case moves it into place (constant/bodies, translation).

Usage: makeSphere.py [LEVEL]   (default 4: 5120 facets, the volume 0.1 % short of the ball's)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from stlsurface import sphere, write_binary  # noqa: E402

level = int(sys.argv[1]) if len(sys.argv) > 1 else 4
here = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(here, 'constant', 'triSurface'), exist_ok=True)
write_binary(os.path.join(here, 'constant', 'triSurface', 'sphere.stl'), *sphere(level, (0, 0, 0), 0.5))
