# Opens a granular-pic case in ParaView with the particles drawn as areas: a filled disk per
# particle of its current area (the `radius` array), coloured by a field. For pvpython or
# pvbatch (ParaView 5.10 or newer), or the GUI's Python shell.
#
#     pvbatch $GPIC_DIR/etc/paraview/particles.py CASE [--field F] [--component C]
#             [--time T|first|last] [--png FILE] [--size 1600x900] [--range LO HI]
#
# CASE: a case directory (its <name>.pvd, or the one .pvd it holds) or a .pvd file. Without
# --png the pipeline is left as it is for the GUI (paraview --script=...). Each tutorial's
# paraview.py calls main() with its own field.
import argparse
import glob
import os
import sys

from paraview.simple import (ColorBy, ExtractBlock, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, Glyph, Hide, PVDReader, Render, ResetCamera,
                             SaveScreenshot, SetActiveSource, Show)


def find_index(case):
    """The .pvd of a case directory, by the rule of picSolver (case/CaseFiles.H)."""
    if case.endswith(".pvd"):
        return case
    case = os.path.abspath(case)
    own = os.path.join(case, os.path.basename(case) + ".pvd")
    if os.path.exists(own):
        return own
    found = sorted(glob.glob(os.path.join(case, "*.pvd")))
    if len(found) == 1:
        return found[0]
    # A tutorial runs its cases in ladder/<run>/: take the first run.
    runs = sorted(glob.glob(os.path.join(case, "ladder", "*", "*.pvd")))
    if runs:
        return runs[0]
    sys.exit("particles.py: no ParaView index (.pvd) in %s: run the case first (./Allrun)" % case)


def show(index, field, component=None, time="last", data_range=None):
    """Read `index`, draw its particles (part 0 of each time) as disks coloured by `field`."""
    reader = PVDReader(FileName=index)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    view = GetActiveViewOrCreate("RenderView")
    view.InteractionMode = "2D"
    particles = reader
    with open(index) as f:  # with `writeGrid yes` the grid is part 1: draw part 0 only
        if 'part="1"' in f.read():
            particles = ExtractBlock(Input=reader, Selectors=["/Root/Block0"])
    disks = Glyph(Input=particles, GlyphType="2D Glyph")
    disks.GlyphType.GlyphType = "Circle"
    disks.GlyphType.Filled = 1
    disks.ScaleArray = ["POINTS", "radius"]
    disks.ScaleFactor = 2.0  # the unit circle glyph has radius 0.5
    disks.OrientationArray = ["POINTS", "No orientation array"]
    disks.GlyphMode = "All Points"
    Hide(reader, view)
    display = Show(disks, view)
    if component is None:
        ColorBy(display, ("POINTS", field, "Magnitude"))
    else:
        ColorBy(display, ("POINTS", field, component))
    display.SetScalarBarVisibility(view, True)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    t = times[-1] if time == "last" else times[0] if time == "first" else float(time)
    scene.AnimationTime = t
    view.ViewTime = t
    lut = GetColorTransferFunction(field)
    if data_range is not None:
        lut.RescaleTransferFunction(data_range[0], data_range[1])
    else:
        display.RescaleTransferFunctionToDataRange(False, True)
    view.OrientationAxesVisibility = 0
    ResetCamera(view)
    SetActiveSource(disks)
    return view


def main(field="velocity", component=None, default_case=".", argv=None):
    parser = argparse.ArgumentParser(description="granular-pic particles as areas in ParaView")
    parser.add_argument("case", nargs="?", default=default_case, help="case directory or .pvd")
    parser.add_argument("--field", default=field)
    parser.add_argument("--component", default=component, help="e.g. YY of stress, Y of velocity")
    parser.add_argument("--time", default="last", help="a time, first or last")
    parser.add_argument("--png", help="save a picture (pvbatch) instead of leaving the pipeline")
    parser.add_argument("--size", default="1600x900")
    parser.add_argument("--range", nargs=2, type=float, help="colour range")
    # pvbatch passes the script's arguments; the GUI's --script may pass its own: ignored.
    if argv is None:
        argv = [a for a in getattr(sys, "argv", [""])[1:] if not a.startswith("--script")]
    args, _ = parser.parse_known_args(argv)
    index = find_index(args.case)
    view = show(index, args.field, args.component, args.time, args.range)
    if args.png:
        width, height = (int(v) for v in args.size.split("x"))
        view.ViewSize = [width, height]
        Render(view)
        SaveScreenshot(args.png, view, ImageResolution=[width, height])
        print("particles.py: %s at t = %s, coloured by %s -> %s" % (index, args.time, args.field, args.png))
    else:
        Render(view)


if __name__ == "__main__":
    main()
