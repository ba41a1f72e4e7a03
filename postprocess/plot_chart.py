#!/usr/bin/python3
"""Material charts of `cdea chart`, with measurements laid on them.

Usage: plot_chart.py CHART.h5 [--out PNG] [--uniaxial CSV] [--equibiaxial CSV] [--dma CSV]

Reads <base>_chart.h5 (layout in doc/materials.md, "Material charts") and
writes <base>_chart.png next to it (or PNG): (a) nominal stress against
stretch in uniaxial and equibiaxial tension (relaxed and, for a law with
internal variables, instantaneous); (b) for such a law, the small-strain DMA
chart: storage and loss modulus and the loss factor against frequency.
Measurements: --uniaxial and --equibiaxial take CSV files with the columns
stretch, stress_kPa (nominal stress); --dma one with frequency_Hz,
storage_kPa, loss_kPa. A first line that is not numbers is a header; '#'
starts a comment (comment lines may come before the header). Needs h5py, numpy and matplotlib (Agg).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_chart.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_chart.py"


def read_csv(path, columns):
    """Rows of @p columns numbers; exits with the file and line of a bad one."""
    rows, header = [], False
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
    except OSError as error:
        sys.exit(f"{PROG}: error: cannot read '{path}': {error.strerror}")
    for number, line in enumerate(lines, start=1):
        line = line.split("#")[0].strip()
        if not line:
            continue
        fields = [x.strip() for x in line.split(",")]
        try:
            values = [float(x) for x in fields]
        except ValueError:
            if not rows and not header:
                header = True  # the first line that is not a comment
                continue
            sys.exit(f"{PROG}: error: {path}, line {number}: not {columns} numbers: '{line}'")
        if len(values) != columns or not all(np.isfinite(values)):
            sys.exit(f"{PROG}: error: {path}, line {number}: expected {columns} finite "
                     f"numbers, got '{line}'")
        rows.append(values)
    if not rows:
        sys.exit(f"{PROG}: error: {path}: no data")
    return np.array(rows)


def stress_panel(ax, f, measured, label="", colors=("C0", "C1")):
    """Uniaxial and equibiaxial curves of the open chart @p f (@p label
    before each curve's name when several charts share the panel)."""
    for path, color in zip(("uniaxial", "equibiaxial"), colors):
        g = f[path]
        name = label + path
        ax.plot(g["stretch"][()], g["nominal_stress_kPa"][()], "-", color=color,
                label=name + (" (relaxed)" if "instantaneous_stress_kPa" in g else ""))
        if "instantaneous_stress_kPa" in g:
            ax.plot(g["stretch"][()], g["instantaneous_stress_kPa"][()], "--", color=color,
                    label=name + " (instantaneous)")
        if measured.get(path) is not None:
            m = measured[path]
            ax.plot(m[:, 0], m[:, 1], "o", mfc="none", color=color, label=name + " measured")
    ax.set_xlabel("stretch")
    ax.set_ylabel("nominal stress (kPa)")
    ax.legend(fontsize=8)
    ax.set_title("(a) stress-stretch at zero voltage")


def dma_panel(ax, f, measured):
    d = f["dma"]
    freq = d["frequency_Hz"][()]
    ax.loglog(freq, d["storage_modulus_kPa"][()], "-", color="C0", label="E' (storage)")
    ax.loglog(freq, d["loss_modulus_kPa"][()], "-", color="C3", label="E'' (loss)")
    if measured is not None:
        ax.loglog(measured[:, 0], measured[:, 1], "o", mfc="none", color="C0", label="E' measured")
        ax.loglog(measured[:, 0], measured[:, 2], "s", mfc="none", color="C3",
                  label="E'' measured")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("modulus (kPa)")
    twin = ax.twinx()
    twin.semilogx(freq, d["loss_factor"][()], ":", color="k", label="tan delta")
    if measured is not None:
        twin.semilogx(measured[:, 0], measured[:, 2] / measured[:, 1], "x", color="k",
                      label="tan delta measured")
    twin.set_ylabel("loss factor tan delta")
    lines = ax.get_legend_handles_labels()
    more = twin.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="center left")
    ax.set_title("(b) small-strain DMA chart (tau = %.3g s)" % d.attrs["relaxation_time_s"])


class ChartError(ValueError):
    """A file that is not a chart of cdea chart, or measurements it cannot take."""


def open_chart(path):
    try:
        f = h5py.File(path, "r")
    except OSError as error:
        raise ChartError(f"cannot read '{path}': {error}") from None
    for key in ("uniaxial/stretch", "uniaxial/nominal_stress_kPa",
                "equibiaxial/stretch", "equibiaxial/nominal_stress_kPa"):
        if key not in f:
            f.close()
            raise ChartError(f"'{path}' is not a file of cdea chart (no /{key})")
    return f


def plot(path, out, measured=None, dma_measured=None):
    """The chart of @p path with the measurements laid on it, written to @p out."""
    with open_chart(path) as f:
        has_dma = "dma" in f
        if dma_measured is not None and not has_dma:
            raise ChartError(f"--dma: the law of '{path}' is elastic "
                             f"(no DMA chart to compare with)")
        fig, axes = plt.subplots(1, 2 if has_dma else 1, figsize=(12 if has_dma else 6.5, 5))
        axes = np.atleast_1d(axes)
        stress_panel(axes[0], f, measured or {})
        if has_dma:
            dma_panel(axes[1], f, dma_measured)
        model = f.attrs["material_model"]
    fig.suptitle(f"Material/Model = {model.decode() if isinstance(model, bytes) else model}")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"{PROG}: wrote {out}")


def draw(paths, out):
    """The picture of plot.py: one chart as plot(); several charts' stress
    curves overlaid in one panel, labelled by file."""
    if len(paths) == 1:
        return plot(paths[0], out)
    fig, ax = plt.subplots(figsize=(7, 5.5))
    for k, path in enumerate(paths):
        with open_chart(path) as f:
            stress_panel(ax, f, {}, os.path.basename(path) + ": ", (f"C{2 * k}", f"C{2 * k + 1}"))
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"{PROG}: wrote {out}")


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--out")
    parser.add_argument("--uniaxial", help="CSV: stretch, stress_kPa")
    parser.add_argument("--equibiaxial", help="CSV: stretch, stress_kPa")
    parser.add_argument("--dma", help="CSV: frequency_Hz, storage_kPa, loss_kPa")
    args = parser.parse_args()
    measured = {path: read_csv(getattr(args, path), 2) if getattr(args, path) else None
                for path in ("uniaxial", "equibiaxial")}
    dma_measured = read_csv(args.dma, 3) if args.dma else None
    try:
        plot(args.file, args.out or os.path.splitext(args.file)[0] + ".png", measured,
             dma_measured)
    except ChartError as error:
        sys.exit(f"{PROG}: error: {error}")


if __name__ == "__main__":
    main()
