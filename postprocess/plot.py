#!/usr/bin/python3
"""A picture of any results file of cdea: the product recognised, several overlaid.

Usage: plot.py FILE.h5 [MORE.h5 ...] [-o OUT.png]

Recognises the product of each file from the groups and datasets its writer
always writes (python/cdea_products.py) and draws it with the product's own
script: a run (plot_run.py: displacement and stroke over the voltage stage;
several runs overlaid here), a time run (plot_time.py: displacement, voltages
and level drop against time), a design map (plot_map.py; several: the stroke
increase on the red and blue lines), an optimum (plot_optimum.py), a fit
(plot_fit.py, one file; a model selection too), a chart (plot_chart.py), a
response (plot_response.py:
the Bode plot and the mode shapes) or a frequency sweep
(plot_frequency_sweep.py). Several files must be of one kind. Writes OUT.png
(default: the first file's name with .png) and prints its path. A file that
is missing, not HDF5 or of no known product, or a mix of kinds: a message
naming the file, exit status 1, nothing written.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# The product scripts beside this one, and the reader of products in python/.
sys.path[:0] = [HERE, os.path.join(os.path.dirname(HERE), "python")]

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cdea_products  # noqa: E402

PROG = "plot.py"


def draw_runs(paths, out):
    """One run: plot_run.py's displacement picture; several: their
    displacements over the voltage stage in one panel."""
    import plot_run
    try:
        runs = [plot_run.Run(p) for p in paths]
        if len(runs) == 1:
            return plot_run.plot_displacement(runs[0], out)
    except plot_run.RunError as error:
        raise cdea_products.ProductError(str(error)) from None
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    for k, run in enumerate(runs):
        rows = run.rows(plot_run.STAGE_VOLTAGE)
        if len(rows) == 0:
            rows = np.arange(run.n_steps)
        x, xlabel = run.x_axis(rows)
        ax.plot(x, run.displacement_mm[rows], "o-", ms=3, color=f"C{k}",
                label=os.path.basename(run.path))
        bad = run.nonphysical[rows] != 0
        ax.plot(x[bad], run.displacement_mm[rows][bad], "x", ms=7, color="k",
                label="non-physical state" if bad.any() else None)
        if run.onset_found and not xlabel.startswith(("voltage path", "time")):
            ax.axvline(run.onset_voltage_kV[-1], color=f"C{k}", ls="-.", lw=1,
                       label=f"{os.path.basename(run.path)}: loss of tension")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("displacement (mm)")
    ax.set_title("Displacement over the voltage stage", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def draw_time_runs(paths, out):
    import plot_time
    try:
        runs = [plot_time.TimeRun(p) for p in paths]
    except plot_time.TimeError as error:
        raise cdea_products.ProductError(str(error)) from None
    plot_time.plot_time(runs, out, [r.name for r in runs], -np.inf, np.inf)


def draw_maps(paths, out):
    import plot_map
    try:
        maps = [plot_map.Map(p) for p in paths]
    except plot_map.MapError as error:
        raise cdea_products.ProductError(str(error)) from None
    if len(maps) > 1:
        return plot_map.plot_increase(maps, out, False)
    fig, ax = plt.subplots(figsize=(7.2, 5.0), constrained_layout=True)
    plot_map.draw_map(fig, ax, maps[0])
    fig.savefig(out, dpi=110)
    plt.close(fig)


def drawer(kind):
    """The function that draws files of @p kind: f(paths, out)."""
    if kind == "run":
        return draw_runs
    if kind == "time run":
        return draw_time_runs
    if kind == "map":
        return draw_maps
    module = {"optimum": "plot_optimum", "fit": "plot_fit", "model selection": "plot_fit",
              "chart": "plot_chart",
              "response": "plot_response", "frequency sweep": "plot_frequency_sweep"}[kind]
    return __import__(module).draw


def kinds_of(paths):
    """The one product of @p paths; ProductError naming a file otherwise."""
    kinds = [cdea_products.kind(p) for p in paths]
    for path, kind in zip(paths, kinds):
        if kind != kinds[0]:
            raise cdea_products.ProductError(
                f"{path} is a {kind} file, {paths[0]} a {kinds[0]} file: "
                "several files are overlaid only if they are of one kind")
    return kinds[0]


def save(fig, out, prog, dpi=110):
    """Writes @p fig to @p out and says so."""
    fig.tight_layout()
    fig.savefig(out, dpi=dpi)
    plt.close(fig)
    print(f"{prog}: wrote {out}")


def files_main(prog, description, draw, what, argv=None):
    """The command line of a product script that draws several files into
    one PNG: FILE.h5 [MORE.h5 ...] [--out PNG]; its errors (ValueError) as
    `prog: error: ...` with exit status 1."""
    parser = argparse.ArgumentParser(prog=prog, description=description)
    parser.add_argument("files", nargs="+", help=what)
    parser.add_argument("--out", help="the PNG to write (default: beside the first file)")
    args = parser.parse_args(argv)
    try:
        draw(args.files, args.out or os.path.splitext(args.files[0])[0] + ".png")
    except ValueError as error:
        sys.exit(f"{prog}: error: {error}")


def main(argv=None):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", help="results files (.h5) of cdea")
    parser.add_argument("-o", "--out", help="the PNG to write (default: the first file's "
                                            "name with .png)")
    args = parser.parse_args(argv)
    out = args.out or os.path.splitext(args.files[0])[0] + ".png"
    try:
        kind = kinds_of(args.files)
        drawer(kind)(args.files, out)
    except (ValueError, OSError) as error:  # the scripts' errors are ValueErrors
        sys.exit(f"{PROG}: error: {error}")
    print(f"{PROG}: {kind}: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
