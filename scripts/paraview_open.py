"""Opens a slidesim result in ParaView ready to play.

    paraview --script=scripts/paraview_open.py        (asks nothing: opens $SLIDESIM_XMF)
    pvpython scripts/paraview_open.py RESULT.xmf [--screenshot OUT.png | --no-render]
    in ParaView's Python shell: exec(open('scripts/paraview_open.py').read()) after
    setting xmf = 'RESULT.xmf'

Opens RESULT.xmf (the XDMF file next to RESULT.h5, whose arrays it reads) with ParaView's "Xdmf3
Reader (T)" (the "(S)" reader it picks by itself reads the same, but as
pieces of one block without their names), shows the slide half transparent, the water band coloured
by its speed, the rider's bodies by their normal force and the paths by the
speed; of a contact result with flights (docs/contact.md, "Outputs") the
contact's path and moving point by `open` (1 in flight, 0 closed) and the
impacts as large points by their approach speed (normal_speed_before). It
sets the animation to the file's time steps and goes to the first.
With --screenshot it renders the last time step into OUT.png (needs a
display, or a ParaView built for off-screen rendering); with --no-render
it only builds the pipeline and prints each grid's points and the array it
is coloured by (what CI runs).
"""
import os
import sys

from paraview.simple import (ExtractBlock, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction,
                             Render, ResetCamera, SaveScreenshot, Show, Xdmf3ReaderT)

# grid name -> (array to colour by, its centring), None: a plain colour
COLOURS = {
    'water band': ('speed', 'POINTS'),
    'rider pelvis': ('normal_force', 'CELLS'),
    'rider legs': ('normal_force', 'CELLS'),
    'rider trunk': ('normal_force', 'CELLS'),
    'streamline': ('speed', 'POINTS'),
    'impacts': ('normal_speed_before', 'POINTS'),
}


def colour_of(name, block):
    """(array, centring) to colour a grid by, or None."""
    if name in COLOURS:
        return COLOURS[name]
    if 'open' in block.PointData.keys():   # a contact that can open: its flight phases
        return ('open', 'POINTS')
    return ('speed', 'POINTS') if name.endswith('path') else None


def grids(reader):
    """{grid name: selector} of the file's grids (a grid included in every
    time step is labelled with its name and "[1]"s)."""
    hierarchy = reader.GetDataInformation().DataInformation.GetHierarchy()
    found = {}
    for node in hierarchy.GetChildNodes(0):
        label = hierarchy.GetAttributeOrDefault(node, 'label', hierarchy.GetNodeName(node))
        found[label.split('[', 1)[0]] = hierarchy.GetNodePath(node)
    return found


def open_result(xmf, screenshot=None, render=True):
    """Opens `xmf`; returns the reader and its grids {name: source}."""
    if not os.path.isfile(xmf):
        sys.exit(f"paraview_open.py: {xmf}: no such file (the .xmf next to a slidesim result)")
    h5 = os.path.splitext(xmf)[0] + '.h5'
    if not os.path.isfile(h5):
        sys.exit(f"paraview_open.py: {h5}: no such file (the .xmf reads its arrays from the result beside it)")
    # by its full path: the Xdmf3 readers look for `ride.xmfride.h5` (and
    # abort) when the .xmf is named without a folder
    reader = Xdmf3ReaderT(FileName=[os.path.abspath(xmf)])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues or [0.0])
    reader.UpdatePipeline(times[0])
    view = GetActiveViewOrCreate('RenderView') if render else None
    shown = {}
    for name, selector in grids(reader).items():
        block = ExtractBlock(registrationName=name, Input=reader, Selectors=[selector])
        shown[name] = block
        block.UpdatePipeline(times[0])
        colour = colour_of(name, block)
        if not render:
            print(f"{name}: {block.GetDataInformation().GetNumberOfPoints()} points"
                  f"{', coloured by ' + colour[0] if colour else ''}")
            continue
        display = Show(block, view)
        if 'surface' in name:
            display.Opacity = 0.35
        if name == 'impacts':   # the landing points, seen among the paths
            display.PointSize = 12
            display.RenderPointsAsSpheres = 1
        if colour:
            display.ColorArrayName = [colour[1], colour[0]]
            display.RescaleTransferFunctionToDataRange(True, False)
            GetColorTransferFunction(colour[0])
            display.SetScalarBarVisibility(view, True)
    if not render:
        return reader, shown
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.GoToFirst()
    ResetCamera(view)
    if screenshot:
        scene.GoToLast()
        Render(view)
        SaveScreenshot(screenshot, view, ImageResolution=[1280, 720])
    return reader, shown


if __name__ == '__main__':
    args = sys.argv[1:]
    out = None
    render = '--no-render' not in args
    args = [a for a in args if a != '--no-render']
    if '--screenshot' in args:
        k = args.index('--screenshot')
        out = args[k + 1]
        del args[k:k + 2]
    target = args[0] if args else os.environ.get('SLIDESIM_XMF', '')
    if not target:
        sys.exit(__doc__)
    open_result(target, out, render)
    if render:
        Render()
elif 'xmf' in globals():
    open_result(globals()['xmf'])
    Render()
