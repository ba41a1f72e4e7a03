#!/usr/bin/python3
"""Measured displacements against the fitted model of `cdea fit`.

Usage: plot_fit.py FIT.h5 [--out PNG] [--ring K]

Reads <base>_fit.h5 (layout in doc/optimization.md, "Calibration") and writes
<base>_fit.png next to it (or PNG): (a) the data points and the fitted model
along the data (the curve through the points in file order) against the
voltage of ring K (default: the ring whose voltage changes most over the
data), with the fitted values and their standard errors; (b) the residuals
(model - measured) of every point. Needs h5py, numpy and matplotlib (Agg).
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
    sys.exit("plot_fit.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_fit.py"


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def shown(name, value):
    """A fitted value in the units of its prm entry."""
    if name.startswith("shear modulus"):
        return value * 1e-3, "kPa"
    if name.startswith("mass"):
        return value * 1e3, "g"
    if name.startswith("permittivity"):
        return value, "F/m"
    return value, ""


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--out")
    parser.add_argument("--ring", type=int)
    args = parser.parse_args()
    try:
        f = h5py.File(args.file, "r")
    except OSError as error:
        sys.exit(f"{PROG}: error: cannot read '{args.file}': {error}")
    with f:
        for key in ("data/voltage_kV", "data/displacement_mm", "data/fitted_mm",
                    "curve/voltage_kV", "curve/displacement_mm"):
            if key not in f:
                sys.exit(f"{PROG}: error: '{args.file}' is not a file of cdea fit (no /{key})")
        volts = f["data/voltage_kV"][()]
        measured = f["data/displacement_mm"][()]
        fitted = f["data/fitted_mm"][()]
        curve_v = f["curve/voltage_kV"][()]
        curve_d = f["curve/displacement_mm"][()]
        names = [n.strip() for n in text(f.attrs["free_parameters"]).split(";")]
        values = np.atleast_1d(f.attrs["fitted_values"])
        errors = np.atleast_1d(f.attrs["standard_errors"])
        rms = float(f.attrs["rms_residual_mm"])
        warnings = text(f.attrs["warnings"])
    n_rings = volts.shape[1]
    ring = args.ring if args.ring else int(np.argmax(np.ptp(volts, axis=0))) + 1
    if not 1 <= ring <= n_rings:
        sys.exit(f"{PROG}: error: --ring {ring}: the data have {n_rings} ring(s)")

    fig, (ax, ax_r) = plt.subplots(2, 1, figsize=(7, 7), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 1]})
    x = volts[:, ring - 1]
    if len(curve_d):
        ax.plot(curve_v[:, ring - 1], curve_d, "-", color="C0", label="model, fitted")
    ax.plot(x, measured, "o", mfc="none", color="k", label="measured")
    ax.plot(x, fitted, ".", color="C0")
    lines = []
    for name, value, error in zip(names, values, errors):
        v, unit = shown(name, value)
        e, _ = shown(name, error)
        label = name.split(" (")[0]
        lines.append(f"{label} = {v:.6g} ± {e:.2g} {unit}".rstrip())
    lines.append(f"rms residual {rms:.3g} mm")
    for warning in filter(None, warnings.split("\n")):
        lines.append("warning: " + (warning[:70] + " ..." if len(warning) > 70 else warning))
    ax.text(0.02, 0.97, "\n".join(lines), transform=ax.transAxes, va="top", fontsize=9,
            bbox=dict(facecolor="white", alpha=0.8, edgecolor="0.8"))
    ax.set_ylabel("displacement (mm)")
    ax.legend(loc="lower right")
    ax.set_title("(a) data and fitted model")
    ax_r.axhline(0., color="0.6", lw=0.8)
    ax_r.plot(x, fitted - measured, "o", color="C3")
    ax_r.set_xlabel(f"voltage of ring {ring} (kV)")
    ax_r.set_ylabel("model - measured (mm)")
    ax_r.set_title("(b) residuals")
    fig.tight_layout()
    out = args.out or os.path.splitext(args.file)[0] + ".png"
    fig.savefig(out, dpi=120)
    print(f"{PROG}: wrote {out}")


if __name__ == "__main__":
    main()
