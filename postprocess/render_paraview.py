"""A picture of one state of a cdea run from its ParaView output, rendered by
ParaView itself (Debian: paraview and python3-paraview; without a display
run it under xvfb-run):

    xvfb-run -a pvbatch postprocess/render_paraview.py RESULTS.pvd OUT.png
                        [--array s2|s1|sigma1|sigma2|lambda1|lambda2|E] [--step N]

The film is coloured by the array (default s2, the hoop stress in kPa), the
disk is grey, z is turned so that the disk hangs below the frame plane, and
the caption gives the ring voltages and the displacement of the step (default:
the last one). Optional: nothing else in cdea needs ParaView.
"""

import argparse
import sys

from paraview import simple as pv
from paraview import servermanager
from vtk.util.numpy_support import vtk_to_numpy

UNITS = {"s1": "kPa", "s2": "kPa", "sigma1": "kPa", "sigma2": "kPa", "E": "MV/m",
         "lambda1": "-", "lambda2": "-"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd")
    parser.add_argument("out")
    parser.add_argument("--array", default="s2", choices=sorted(UNITS))
    parser.add_argument("--step", type=int, default=-1, help="step index (default: last)")
    args = parser.parse_args()

    reader = pv.PVDReader(FileName=args.pvd)
    times = list(reader.TimestepValues)
    if not times:
        sys.exit(f"render_paraview.py: error: {args.pvd} lists no step")
    time = times[args.step]
    # The solver's z grows downward from the frame plane: turn it over.
    down = pv.Transform(Input=reader)
    down.Transform = "Transform"
    down.Transform.Scale = [1.0, 1.0, -1.0]
    film = pv.Threshold(Input=down, Scalars=["POINTS", "ring"], LowerThreshold=-0.5,
                        UpperThreshold=1e9)
    disk = pv.Threshold(Input=down, Scalars=["POINTS", "ring"], LowerThreshold=-1.5,
                        UpperThreshold=-0.5)

    view = pv.CreateView("RenderView")
    view.ViewSize = [900, 620]
    view.ViewTime = time
    if hasattr(view, "UseColorPaletteForBackground"):  # ParaView 5.10 and later
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    shown = pv.Show(film, view)
    pv.ColorBy(shown, ("POINTS", args.array))
    lut = pv.GetColorTransferFunction(args.array)
    lut.ApplyPreset("Cool to Warm", True)
    shown.RescaleTransferFunctionToDataRange(False, True)
    shown.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = f"{args.array} ({UNITS[args.array]})"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    plate = pv.Show(disk, view)
    pv.ColorBy(plate, None)
    plate.AmbientColor = plate.DiffuseColor = [0.35, 0.35, 0.35]

    # Caption from the step's field data.
    reader.UpdatePipeline(time)
    fields = servermanager.Fetch(reader).GetFieldData()
    volts = vtk_to_numpy(fields.GetArray("voltage_kV")).ravel()
    disp = float(vtk_to_numpy(fields.GetArray("displacement_mm")).ravel()[0])
    text = pv.Text(Text="ring voltages " + " / ".join(f"{v:g}" for v in volts)
                   + f" kV, displacement {disp:.2f} mm")
    caption = pv.Show(text, view)
    caption.Color = [0.1, 0.1, 0.1]
    caption.FontSize = 14
    caption.WindowLocation = "Upper Left Corner"

    view.CameraPosition = [0.0, -125.0, 95.0]
    view.CameraFocalPoint = [0.0, 0.0, -10.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 28
    pv.Render(view)
    pv.SaveScreenshot(args.out, view, ImageResolution=[900, 620])
    print(args.out)


if __name__ == "__main__":
    main()
