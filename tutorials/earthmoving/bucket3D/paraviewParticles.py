# ParaView: the dragline bucket in the corn, seen from in front of its mouth, from the glass
# side and above: the corn particles as spheres of their radius coloured by their speed, the
# bucket's surface in grey, both mirrored about the mid-plane x2 = 0 so that the whole bucket
# of the half model is seen; the camera follows the bucket.
#     pvbatch paraviewParticles.py [CASE] [--png picture.png] [--time T]   (CASE: a run's .pvd or
#                                    its directory; default this directory's first ladder/<run>)
#     paraview --script=paraviewParticles.py                      (in the GUI, from this directory)
# More: --field displacement --component X (the corn dragged along [m]), --range LO HI,
# --size 1200x700. The index of a case: find_index in $GPIC_DIR/etc/paraview/particles.py.
import argparse
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
sys.path.insert(0, os.path.join(os.environ.get("GPIC_DIR", os.path.join(here, "..", "..", "..")), "etc", "paraview"))
import particles  # noqa: E402

from paraview.simple import (ColorBy, ExtractBlock, GetActiveViewOrCreate,  # noqa: E402
                             GetAnimationScene, GetColorTransferFunction, GetScalarBar, Hide,
                             PVDReader, Reflect, Render, SaveScreenshot, SetActiveSource, Show,
                             Text, Threshold)

CORN = 0        # constant/bodies: corn is body 0, the bucket body 1 (drawn by its surface instead)
SPEED = 0.1     # the drag speed [m/s]: the top of the default colour range
# the view from the mouth: degrees from +x1 towards the glass (+x2), degrees above the
# horizontal, metres from the point looked at (about x1 = 0.2 ... 1 m in the picture)
AZIMUTH, ELEVATION, DISTANCE = 55.0, 30.0, 1.05


def parts(index):
    """The block of each part of the index: the reader numbers the parts it finds in order
    (0 particles, 1 the grid with `writeGrid yes`, 2... the rigid bodies' surfaces)."""
    with open(index) as f:
        found = sorted({int(p) for p in re.findall(r'part="(\d+)"', f.read())})
    return {p: k for k, p in enumerate(found)}


def mirrored(source):
    """`source` and its image in the mid-plane x2 = 0: the run is the half model x2 >= 0."""
    return Reflect(Input=source, Plane="Y", Center=0.0, CopyInput=1)


def show(index, field="velocity", component=None, time="last", data_range=None):
    reader = PVDReader(FileName=index)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    t = times[-1] if time == "last" else times[0] if time == "first" else float(time)
    block = parts(index)
    view = GetActiveViewOrCreate("RenderView")
    Hide(reader, view)

    # The corn: part 0 less the bucket's own particles (its surface shows it better).
    cloud = ExtractBlock(Input=reader, Selectors=["/Root/Block%d" % block[0]])
    corn = Threshold(Input=cloud, Scalars=["POINTS", "body"], ThresholdMethod="Between",
                     LowerThreshold=CORN - 0.5, UpperThreshold=CORN + 0.5)
    corn_all = mirrored(corn)
    grains = Show(corn_all, view)
    # Point Gaussian spheres scaled by the `radius` array itself (no transfer function): each
    # particle's sphere of its volume, drawn by the GPU, fast for 10^5 particles.
    grains.SetRepresentationType("Point Gaussian")
    grains.ShaderPreset = "Sphere"
    grains.ScaleByArray = 1
    grains.SetScaleArray = ["POINTS", "radius"]
    grains.UseScaleFunction = 0
    grains.GaussianRadius = 1.0
    if component is None:
        ColorBy(grains, ("POINTS", field, "Magnitude"))
    else:
        ColorBy(grains, ("POINTS", field, component))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    if data_range is None:
        # speed: 0 ... the drag speed, the still bed dark, what the bucket carries bright
        data_range = (0.0, SPEED) if field == "velocity" and component is None else None
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = t
    view.ViewTime = t
    if data_range is not None:
        lut.RescaleTransferFunction(data_range[0], data_range[1])
    else:
        grains.RescaleTransferFunctionToDataRange(False, True)

    # The rigid bodies' surfaces (parts 2, 3, ...): opaque grey, in their current position.
    surfaces = [p for p in block if p >= 2]
    bounds = None
    for p in surfaces:
        surface = ExtractBlock(Input=reader, Selectors=["/Root/Block%d" % block[p]])
        body = Show(mirrored(surface), view)
        body.ColorArrayName = ["POINTS", ""]  # solid colour, no array
        body.AmbientColor = body.DiffuseColor = [0.62, 0.62, 0.64]
        body.Specular = 0.3
        surface.UpdatePipeline(t)
        bounds = surface.GetDataInformation().GetBounds()

    # The bar: black on the white background, titled with the field and its unit.
    bar = GetScalarBar(lut, view)
    if field == "velocity" and component is None:
        bar.Title, bar.ComponentTitle = "corn speed |v|", "[m/s]"
    else:
        unit = {"velocity": "[m/s]", "displacement": "[m]", "initialPosition": "[m]"}.get(field, "")
        name = "%s %s" % (field, component) if component else "|%s|" % field
        bar.Title, bar.ComponentTitle = "corn " + name, unit
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize, bar.LabelFontSize = 18, 16
    bar.TitleBold = 1
    bar.RangeLabelFormat = "%-#.2f"
    bar.WindowLocation = "Any Location"   # upper left, over the empty sky behind the bucket
    bar.Orientation = "Horizontal"
    bar.Position = [0.04, 0.82]
    bar.ScalarBarLength = 0.3
    bar.ScalarBarThickness = 16
    grains.SetScalarBarVisibility(view, True)

    label = Text(Text="t = %g s" % t)
    caption = Show(label, view)
    caption.Color = [0.0, 0.0, 0.0]
    caption.FontSize = 18
    caption.WindowLocation = "Upper Right Corner"

    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    # The camera: in front of the bucket's mouth (+x1), to the glass side (+x2) and above,
    # aimed just behind the tooth, where the corn flows into the bucket; it follows the bucket.
    Render(view)  # the first render resets the camera to the whole scene: before placing it
    if bounds is not None:
        x_mouth, z_tooth = bounds[1], bounds[4]
    else:
        x_mouth, z_tooth = 0.75, 0.28
    focus = [x_mouth - 0.05, 0.0, z_tooth + 0.08]
    azimuth, elevation = math.radians(AZIMUTH), math.radians(ELEVATION)
    view.CameraFocalPoint = focus
    view.CameraPosition = [focus[0] + DISTANCE * math.cos(elevation) * math.cos(azimuth),
                           focus[1] + DISTANCE * math.cos(elevation) * math.sin(azimuth),
                           focus[2] + DISTANCE * math.sin(elevation)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    SetActiveSource(corn_all)
    return view, t


def main(argv=None):
    parser = argparse.ArgumentParser(description="the 3D dragline bucket in ParaView")
    parser.add_argument("case", nargs="?", default=here, help="a run's directory or .pvd")
    parser.add_argument("--field", default="velocity")
    parser.add_argument("--component", help="e.g. X of displacement; default the magnitude")
    parser.add_argument("--time", default="last", help="a time, first or last")
    parser.add_argument("--png", help="save a picture (pvbatch) instead of leaving the pipeline")
    parser.add_argument("--size", default="1200x700")
    parser.add_argument("--range", nargs=2, type=float, help="colour range")
    # pvbatch passes the script's arguments; the GUI's --script may pass its own: ignored.
    if argv is None:
        argv = [a for a in getattr(sys, "argv", [""])[1:] if not a.startswith("--script")]
    args, _ = parser.parse_known_args(argv)
    index = particles.find_index(args.case)
    view, t = show(index, args.field, args.component, args.time, args.range)
    if args.png:
        width, height = (int(v) for v in args.size.split("x"))
        view.ViewSize = [width, height]
        Render(view)
        SaveScreenshot(args.png, view, ImageResolution=[width, height], CompressionLevel=9)
        print("paraviewParticles.py: %s at t = %g, coloured by %s -> %s"
              % (index, t, args.field, args.png))
    else:
        Render(view)


main()
