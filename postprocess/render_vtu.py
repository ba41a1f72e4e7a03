"""A picture of one state of a cdea run from its ParaView output, without
ParaView and without a display: VTK's reader (Debian's python3-vtk9, which
scripts/setup.sh installs for the tests) and matplotlib's 3D axes.

    /usr/bin/python3 postprocess/render_vtu.py RESULTS.pvd OUT.png
        [--array s2|s1|sigma1|sigma2|lambda1|lambda2|E] [--step N]

The far half of the film, cut through the axis, is coloured by the array
(default s2, the hoop stress in kPa), the disk is grey, z is turned so that
the disk hangs below the frame plane, and the caption gives the ring voltages
and the displacement of the step (default: the last one).
postprocess/render_paraview.py draws the whole film in ParaView, where
ParaView is installed.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402
from vtk import vtkXMLUnstructuredGridReader  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

UNITS = {"s1": "kPa", "s2": "kPa", "sigma1": "kPa", "sigma2": "kPa", "E": "MV/m",
         "lambda1": "-", "lambda2": "-"}


def fail(message):
    sys.exit(f"render_vtu.py: error: {message}")


def step_file(pvd, step):
    """The VTU file of step @p step (an index into the collection) of @p pvd."""
    try:
        sets = ElementTree.parse(pvd).getroot().iter("DataSet")
        files = [d.get("file") for d in sets]
    except (OSError, ElementTree.ParseError) as e:
        fail(f"cannot read {pvd}: {e}")
    if not files:
        fail(f"{pvd} lists no step")
    if not -len(files) <= step < len(files):
        fail(f"--step {step}: {pvd} has {len(files)} steps")
    return os.path.join(os.path.dirname(os.path.abspath(pvd)), files[step])


def read_vtu(path):
    """Points, cells (lists of point indices), point arrays and field data."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or grid.GetNumberOfPoints() == 0:
        fail(f"cannot read {path} as a VTK unstructured grid")
    points = vtk_to_numpy(grid.GetPoints().GetData())
    cells = []
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    data = grid.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    fields = grid.GetFieldData()
    field = {fields.GetArrayName(i): vtk_to_numpy(fields.GetArray(i))
             for i in range(fields.GetNumberOfArrays())}
    return points, cells, arrays, field


def draw(points, cells, arrays, field, name, out):
    xyz = points * np.array([1.0, 1.0, -1.0])  # the solver's z grows downward
    ring = arrays["ring"]
    values = arrays[name]
    # The far half of the film only, cut through the axis: the view looks
    # into the cone, and matplotlib (which sorts whole polygons by depth,
    # without a depth buffer) draws no near face over a far one.
    elevation, azimuth = 18.0, -60.0
    toward = np.array([np.cos(np.radians(azimuth)), np.sin(np.radians(azimuth))])
    film = [c for c in cells if np.all(ring[c] >= 0) and np.mean(xyz[c, :2], axis=0) @ toward <= 0]
    disk = [c for c in cells if np.all(ring[c] < 0)]
    cell_values = np.array([np.mean(values[c]) for c in film])
    norm = matplotlib.colors.Normalize(float(np.min(values[ring >= 0])),
                                       float(np.max(values[ring >= 0])))
    cmap = matplotlib.colormaps["coolwarm"]

    fig = plt.figure(figsize=(9.0, 6.2))
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection([xyz[c] for c in film],
                                         facecolors=cmap(norm(cell_values)),
                                         edgecolors="none"))
    ax.add_collection3d(Poly3DCollection([xyz[c] for c in disk], facecolors="0.6",
                                         edgecolors="none"))
    low, high = xyz.min(axis=0), xyz.max(axis=0)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    ax.set_box_aspect(high - low)
    ax.view_init(elev=elevation, azim=azimuth)
    ax.set_axis_off()
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax,
                       shrink=0.7, pad=0.02)
    bar.set_label(f"{name} ({UNITS[name]})")
    volts = ", ".join(f"{v:g}" for v in np.ravel(field.get("voltage_kV", [])))
    displacement = float(np.ravel(field.get("displacement_mm", [np.nan]))[0])
    ax.set_title(f"{volts} kV, displacement {displacement:.2f} mm")
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd")
    parser.add_argument("out")
    parser.add_argument("--array", default="s2", choices=sorted(UNITS))
    parser.add_argument("--step", type=int, default=-1, help="step index (default: last)")
    args = parser.parse_args()
    points, cells, arrays, field = read_vtu(step_file(args.pvd, args.step))
    if args.array not in arrays or "ring" not in arrays:
        fail(f"{args.pvd}: the step has no point array '{args.array}' or 'ring'")
    draw(points, cells, arrays, field, args.array, args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
