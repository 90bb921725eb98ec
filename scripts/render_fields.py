#!/usr/bin/env pvpython
"""A picture of a rouleau run's fields, rendered by ParaView.

    DISPLAY=:N pvpython --disable-xdisplay-test scripts/render_fields.py RUN_DIR OUT.png
        [--time T] [--plasma-velocity magnitude|x|y|z] [--cell-field NAME]
        [--view x|y|z] [--oblique] [--size W H] [--caption TEXT]

Opens RUN_DIR/fields_fluid.xdmf and, when the case has cells, RUN_DIR/fields_cells.xdmf
(the per-mesh files a run writes; docs/paraview.md) with ParaView's Xdmf3ReaderT, and
draws at time T (seconds; default: the last step written, otherwise the nearest step):
  - the plasma: a slice across the line of sight, at the back of a fluid box, through a
    vessel's axis (or behind its cells when they all lie behind the axis), coloured by
    its velocity (velocity_um_s, um/s): the magnitude (default) or one component, on a
    scale up to the 99th percentile on the slice (the spikes next to membranes, above it,
    in a colour of their own, with a swatch on the bar), and the box's outline;
  - the cells: their outer surfaces, coloured by the magnitude of --cell-field (default
    displacement_um, um, from the cells' shape as placed; also velocity_um_s,
    internal_force_pN, interaction_force_pN, or cell_id);
  - a colour bar for each, and a title: the case's name (the run's provenance), the time
    and the case's description (case.resolved.toml), or --caption.
--view z (default) looks along -z at the x-y plane (the shear plane of the shear cases),
y along +y (x to the right, z up: a vessel's side view), x along -x (parallel
projection); --oblique turns the camera 25 degrees about the vertical and 20 degrees up,
to show the cells' thickness. Prints the path of the PNG.

Needs an X display (Debian's ParaView has no offscreen build): under Xvfb, `Xvfb :7 &`
and then `DISPLAY=:7 pvpython --disable-xdisplay-test scripts/render_fields.py ...`
(without the option, pvpython 5.11's start-up display test aborts now and then under
Xvfb with "bad X server connection").
"""
import argparse
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy
from paraview import servermanager
from paraview import simple as pv
from vtkmodules.numpy_interface import dataset_adapter as dsa

MU = "\u00b5"
CELL_FIELDS = {  # array name -> (colour bar title, magnitude of a vector)
    "displacement_um": (f"cell displacement ({MU}m)", True),
    "velocity_um_s": (f"cell velocity ({MU}m/s)", True),
    "internal_force_pN": ("elastic force per node (pN)", True),
    "interaction_force_pN": ("interaction force per node (pN)", True),
    "cell_id": ("cell (index in [[cells]])", False),
}
INK = [0.1, 0.1, 0.1]


def parse_arguments():
    parser = argparse.ArgumentParser(description="A picture of a rouleau run's fields, rendered by ParaView.")
    parser.add_argument("run_dir")
    parser.add_argument("out_png")
    parser.add_argument("--time", type=float, help="time in seconds (default: the last step written)")
    parser.add_argument("--plasma-velocity", default="magnitude", choices=["magnitude", "x", "y", "z"])
    parser.add_argument("--cell-field", default="displacement_um", choices=sorted(CELL_FIELDS))
    parser.add_argument("--view", default="z", choices=["x", "y", "z"])
    parser.add_argument("--oblique", action="store_true")
    parser.add_argument("--size", type=int, nargs=2, default=[1400, 1000], metavar=("W", "H"))
    parser.add_argument("--caption", help="the line below the title (default: the case's description)")
    return parser.parse_args()


def resolved_case_entry(run_dir, key):
    """[case] KEY of RUN_DIR/case.resolved.toml, or None."""
    try:
        with open(os.path.join(run_dir, "case.resolved.toml")) as f:
            text = f.read()
    except OSError:
        return None
    section = re.search(r"^\[case\]\s*$(.*?)(?=^\[|\Z)", text, re.MULTILINE | re.DOTALL)
    match = section and re.search(rf"^{key}\s*=\s*(['\"])(.*)\1\s*$", section.group(1), re.MULTILINE)
    return match.group(2) if match else None


def is_vessel(run_dir):
    """Whether RUN_DIR's case is a vessel (its case.resolved.toml has a [vessel] table)."""
    try:
        with open(os.path.join(run_dir, "case.resolved.toml")) as f:
            return re.search(r"^\[vessel\]\s*$", f.read(), re.MULTILINE) is not None
    except OSError:
        return False


def case_name(run_dir):
    """The `case` provenance entry of the run's .xdmf, else case.resolved.toml's name."""
    for file in ("fields.xdmf", "fields_fluid.xdmf"):
        try:
            for info in ET.parse(os.path.join(run_dir, file)).getroot().iter("Information"):
                if info.get("Name") == "case" and info.get("Value"):
                    return info.get("Value")
        except (OSError, ET.ParseError):
            continue
    return resolved_case_entry(run_dir, "name") or os.path.basename(os.path.normpath(run_dir))


def time_label(t):
    if t == 0.0:
        return "t = 0 s"
    if abs(t) < 1.0:
        return f"t = {t * 1e3:.4g} ms"
    return f"t = {t:.4g} s"


def colour_bar(lut, view, title, position):
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Any Location"
    bar.Position = position
    bar.ScalarBarLength = 0.3
    bar.ScalarBarThickness = 18
    bar.TitleColor = bar.LabelColor = INK
    bar.TitleFontSize = 20
    bar.LabelFontSize = 17
    bar.TitleBold = 1
    bar.AddRangeLabels = 1
    bar.RangeLabelFormat = "%-.3g"
    bar.Visibility = 1
    return bar


def fixed_range(lut, low, high):
    lut.RescaleTransferFunction(low, high if high > low else low + 1e-12)
    lut.AutomaticRescaleRangeMode = "Never"


def plasma_scale(source, component):
    """The plasma's colour scale: the 99th percentile of |v| (or of |v_x|, ...) on the slice
    when the largest value is more than 10 % above it, else the largest.

    Next to a membrane the plasma's velocity has spikes a few times the flow's own (the
    spread forces act within one element); a scale set by the largest value would leave the
    flow itself in the palest colours. Points above the scale get their own colour, shown
    as a swatch at the bar's end. Returns (scale, largest value).
    """
    data = dsa.WrapDataObject(servermanager.Fetch(source))
    velocity = data.PointData["velocity_um_s"]
    # One array per block of a composite data set; a block without points has none.
    blocks = velocity.Arrays if hasattr(velocity, "Arrays") else [velocity]
    arrays = [numpy.asarray(block) for block in blocks]
    arrays = [array.reshape(-1, 3) for array in arrays if array.ndim == 2 and array.shape[1] == 3]
    values = numpy.concatenate(arrays) if arrays else numpy.zeros((0, 3))
    shown = numpy.linalg.norm(values, axis=1) if component == "magnitude" else numpy.abs(values[:, "xyz".index(component)])
    if shown.size == 0:
        return 0.0, 0.0
    percentile, largest = float(numpy.percentile(shown, 99.0)), float(shown.max())
    # No spike (the largest within 10 % of the percentile): the scale is the largest value.
    return (largest if largest <= 1.1 * percentile else percentile), largest


def mark_beyond_scale(lut, above_colour, below_colour=None):
    """Values beyond the colour scale in colours of their own (the bar shows their swatches)."""
    lut.UseAboveRangeColor = 1
    lut.AboveRangeColor = above_colour
    if below_colour is not None:
        lut.UseBelowRangeColor = 1
        lut.BelowRangeColor = below_colour


def main():
    args = parse_arguments()
    run_dir = args.run_dir
    fluid_file = os.path.join(run_dir, "fields_fluid.xdmf")
    cells_file = os.path.join(run_dir, "fields_cells.xdmf")
    if not os.path.exists(fluid_file):
        sys.exit(f"render_fields: no {fluid_file} (a run without field output, or one written "
                 "before rouleau wrote an .xdmf per mesh)")

    fluid = pv.Xdmf3ReaderT(registrationName="fields_fluid.xdmf", FileName=[fluid_file])
    fluid.UpdatePipelineInformation()
    times = list(fluid.TimestepValues) if fluid.TimestepValues else [0.0]
    t = times[-1] if args.time is None else min(times, key=lambda s: abs(s - args.time))

    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = INK
    view.ViewTime = t
    pv.GetAnimationScene().AnimationTime = t

    # The camera looks along -z (view z), +y (view y) or -x (view x), so that x runs to the
    # right in the z and y views; "behind" is the far side from the camera.
    axis = "xyz".index(args.view)
    toward_camera = -1.0 if args.view == "y" else 1.0
    fluid.UpdatePipeline(t)
    bounds = fluid.GetDataInformation().GetBounds()
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    normal = [0.0, 0.0, 0.0]
    normal[axis] = 1.0
    origin = list(centre)
    # The plasma: in a box, a slice 2 % inside its back. In a vessel, through its axis,
    # where the flow is fastest and which crosses every narrowing; a cell straddling the
    # axis hides the slice behind its near half. When the cells all lie behind the axis, the
    # slice goes 0.5 um behind the farthest cell point instead, so that it hides none.
    back = bounds[2 * axis] if toward_camera > 0 else bounds[2 * axis + 1]
    if not is_vessel(run_dir):
        origin[axis] = back + toward_camera * 0.02 * (bounds[2 * axis + 1] - bounds[2 * axis])
    elif os.path.exists(cells_file):
        placed = pv.Xdmf3ReaderT(registrationName="cell bounds", FileName=[cells_file])
        placed.UpdatePipeline(t)
        cell_bounds = placed.GetDataInformation().GetBounds()
        nearest = cell_bounds[2 * axis + 1] if toward_camera > 0 else cell_bounds[2 * axis]
        farthest = cell_bounds[2 * axis] if toward_camera > 0 else cell_bounds[2 * axis + 1]
        if toward_camera * (nearest - centre[axis]) <= 0.0:
            origin[axis] = farthest - toward_camera * 0.5
    plane = pv.Slice(registrationName="plasma slice", Input=fluid)
    plane.SliceType = "Plane"
    plane.SliceType.Origin = origin
    plane.SliceType.Normal = normal
    plane_display = pv.Show(plane, view)
    plane_display.Ambient = 0.25
    plane_display.Diffuse = 0.8
    component = args.plasma_velocity
    pv.ColorBy(plane_display, ("POINTS", "velocity_um_s", "Magnitude" if component == "magnitude" else component.upper()))
    plasma_lut = pv.GetColorTransferFunction("velocity_um_s")
    plane.UpdatePipeline(t)
    scale, largest = plasma_scale(plane, component)
    if component == "magnitude":
        plasma_lut.ApplyPreset("Blues", True)
        plasma_lut.InvertTransferFunction()  # white at rest, as the background
        fixed_range(plasma_lut, 0.0, scale)
        plasma_title = f"plasma speed ({MU}m/s)"
        above_colour = [0.55, 0.0, 0.25]
    else:
        plasma_lut.ApplyPreset("Cool to Warm", True)
        fixed_range(plasma_lut, -scale, scale)  # diverging: white at rest
        plasma_title = f"plasma velocity, {component} component ({MU}m/s)"
        above_colour = [0.35, 0.0, 0.0]
    colour_bar(plasma_lut, view, plasma_title, [0.6, 0.03])
    if largest > scale:
        mark_beyond_scale(plasma_lut, above_colour, None if component == "magnitude" else [0.0, 0.0, 0.35])
        print(f"render_fields: plasma colour scale {scale:.3g} um/s (the 99th percentile on the slice; "
              f"largest {largest:.3g}, drawn in the above-scale colour)", file=sys.stderr)

    outline_display = pv.Show(pv.Outline(registrationName="box", Input=fluid), view)
    outline_display.AmbientColor = outline_display.DiffuseColor = [0.25, 0.25, 0.25]
    outline_display.LineWidth = 2.0

    if os.path.exists(cells_file):
        cells = pv.Xdmf3ReaderT(registrationName="fields_cells.xdmf", FileName=[cells_file])
        field = args.cell_field
        title, is_vector = CELL_FIELDS[field]
        # The outer surfaces (a hollow cell's inner one is hidden behind them), and the
        # field's magnitude on its own colour map (the cells' velocity_um_s is not the plasma's).
        surface = pv.ExtractSurface(registrationName="cell surfaces", Input=cells)
        smooth = pv.GenerateSurfaceNormals(registrationName="smooth shading", Input=surface)
        shown = pv.Calculator(registrationName="cell field", Input=smooth)
        shown.ResultArrayName = "cell_" + field
        shown.Function = f"mag({field})" if is_vector else field
        cell_display = pv.Show(shown, view)
        cell_display.Specular = 0.15
        cell_display.SpecularPower = 40.0
        cell_display.Interpolation = "Gouraud"
        pv.ColorBy(cell_display, ("POINTS", "cell_" + field))
        cell_lut = pv.GetColorTransferFunction("cell_" + field)
        cell_lut.ApplyPreset("Viridis (matplotlib)" if is_vector else "Rainbow Uniform", True)
        shown.UpdatePipeline(t)
        fixed_range(cell_lut, *shown.PointData["cell_" + field].GetRange())
        colour_bar(cell_lut, view, title, [0.17, 0.03])

    heading = pv.Text(registrationName="title", Text=f"{case_name(run_dir)}    {time_label(t)}")
    heading_display = pv.Show(heading, view)
    heading_display.WindowLocation = "Upper Center"
    heading_display.FontSize = 30
    heading_display.Bold = 1
    heading_display.Color = INK
    description = args.caption or resolved_case_entry(run_dir, "description")
    if description:  # a line below the title, at the same anchor
        subtitle_display = pv.Show(pv.Text(registrationName="description", Text="\n\n" + description), view)
        subtitle_display.WindowLocation = "Upper Center"
        subtitle_display.FontSize = 19
        subtitle_display.Color = [0.3, 0.3, 0.3]

    pv.Render(view)  # the first render resets the camera: before placing it
    # Camera: on the near side, looking at the box's centre.
    view.CameraFocalPoint = centre
    position = list(centre)
    position[axis] += toward_camera * 5.0 * max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    view.CameraPosition = position
    view.CameraViewUp = [0.0, 0.0, 1.0] if axis == 1 else [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    camera = pv.GetActiveCamera()
    if args.oblique:
        camera.Azimuth(25.0)
        camera.Elevation(20.0)
    view.ResetCamera(False)
    # Room for the title above and the colour bars below.
    view.SMProxy.UpdatePropertyInformation()
    view.CameraParallelScale = view.GetProperty("CameraParallelScaleInfo")[0] * (1.03 if args.oblique else 0.8)
    pv.Render(view)
    pv.SaveScreenshot(args.out_png, view, ImageResolution=args.size, CompressionLevel="9")
    print(args.out_png)


if __name__ == "__main__":
    main()
