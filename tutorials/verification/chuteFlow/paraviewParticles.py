# ParaView: this tutorial's particles drawn as their areas, coloured by the velocity.
#     pvbatch paraviewParticles.py [CASE] [--png picture.png] [--time T]   (CASE: this directory's
#                                                    .pvd, or its first ladder/<run>)
#     paraview --script=paraviewParticles.py                   (in the GUI, from this directory)
# Options and the other fields: $GPIC_DIR/etc/paraview/particles.py.
import os
import sys

here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
sys.path.insert(0, os.path.join(os.environ.get("GPIC_DIR", os.path.join(here, "..", "..", "..")), "etc", "paraview"))
import particles  # noqa: E402

particles.main(field="velocity", default_case=here)
