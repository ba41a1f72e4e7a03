#!/usr/bin/python3
"""Measured data against the fitted model of `cdea fit`, and its model selection.

Usage: plot_fit.py FILE.h5 [--out PNG] [--ring K]

Writes FILE.png next to FILE.h5 (or PNG), after what the file holds:
- <base>_fit.h5 of displacement points (doc/optimization.md, "Calibration"):
  (a) the data points and the fitted model along the data against the
  voltage of ring K (default: the ring whose voltage changes most), with the
  fitted values and their standard errors; (b) the residuals of every point.
- <base>_fit.h5 of material tests (doc/materials.md, "Fitting material
  tests"): one row per file, its measured nominal stress and the model's
  (fitted, or predicted for a --predict file) against time and against
  stretch, and the residuals against time.
- <base>_models.h5 of a model selection (doc/materials.md, "Choosing a
  model"): per candidate AIC and BIC (from the lowest), and the held-out
  error, the recommended model marked.
Needs h5py, numpy and matplotlib (Agg).
"""

import argparse
import os
import sys
import textwrap

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


def require(f, path, keys, what):
    for key in keys:
        if key not in f:
            sys.exit(f"{PROG}: error: '{path}' is not {what} (no /{key})")


def plot_displacements(f, args):
    """The displacement-voltage fit: data, model curve and residuals."""
    require(f, args.file, ("data/voltage_kV", "data/displacement_mm", "data/fitted_mm",
                           "curve/voltage_kV", "curve/displacement_mm"), "a file of cdea fit")
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
    lines = [value_line(name, value, error) for name, value, error in zip(names, values, errors)]
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
    return fig


def value_line(name, value, error):
    v, unit = shown(name, value)
    e, _ = shown(name, error)
    return f"{name.split(' (')[0]} = {v:.6g} ± {e:.2g} {unit}".rstrip()


def plot_material_tests(f, args):
    """A material-test fit: per file stress against time and stretch, residuals."""
    require(f, args.file, ("tests/file", "tests/fitted", "samples/test", "samples/time_s",
                           "samples/stretch", "samples/measured_stress_kPa",
                           "samples/model_stress_kPa"), "a material-test fit of cdea fit")
    files = [text(x) for x in f["tests/file"][()]]
    kinds = [text(x) for x in f["tests/kind"][()]]
    fitted = f["tests/fitted"][()]
    rms = f["tests/rms_kPa"][()]
    s = {key: f["samples/" + key][()] for key in ("test", "time_s", "stretch",
                                                  "measured_stress_kPa", "model_stress_kPa")}
    names = [n.strip() for n in text(f.attrs["free_parameters"]).split(";")]
    values = np.atleast_1d(f.attrs["fitted_values"])
    errors = np.atleast_1d(f.attrs["standard_errors"])
    fig, axes = plt.subplots(len(files), 3, figsize=(13, 3.2 * len(files)), squeeze=False)
    for k, name in enumerate(files):
        rows = s["test"] == k
        t, stretch = s["time_s"][rows], s["stretch"][rows]
        measured, model = s["measured_stress_kPa"][rows], s["model_stress_kPa"][rows]
        role = "fitted" if fitted[k] else "predicted"
        style = "-" if fitted[k] else "--"
        a_t, a_l, a_r = axes[k]
        for ax, x in ((a_t, t), (a_l, stretch)):
            ax.plot(x, measured, ".", ms=3, color="0.5", label="measured")
            ax.plot(x, model, style, color="C0" if fitted[k] else "C1", label="model, " + role)
            ax.set_ylabel("nominal stress (kPa)")
        a_t.set_title(f"{name} ({kinds[k]}, {role}): rms {rms[k]:.3g} kPa", fontsize=9)
        a_t.set_xlabel("time (s)")
        a_l.set_xlabel("stretch")
        a_l.legend(loc="upper left", fontsize=8)
        a_r.axhline(0., color="0.6", lw=0.8)
        a_r.plot(t, model - measured, ".", ms=3, color="C3")
        a_r.set_xlabel("time (s)")
        a_r.set_ylabel("model - measured (kPa)")
    axes[0][2].set_title("\n".join(value_line(n, v, e) for n, v, e in zip(names, values, errors)),
                         fontsize=8)
    return fig


def plot_models(f, args):
    """A model selection: AIC, BIC and held-out error per candidate."""
    require(f, args.file, ("models/model", "models/aic", "models/bic", "models/held_out_error"),
            "a model selection of cdea fit")
    names = [text(x) for x in f["models/model"][()]]
    aic, bic = f["models/aic"][()], f["models/bic"][()]
    held = f["models/held_out_error"][()]
    recommended = text(f.attrs["recommended"])
    colours = ["C2" if n == recommended else "C0" for n in names]
    x = np.arange(len(names))
    fig, (a_ic, a_h) = plt.subplots(1, 2, figsize=(11, 4))
    width = 0.4
    a_ic.bar(x - width / 2, aic - np.nanmin(aic), width, color=colours, label="AIC")
    a_ic.bar(x + width / 2, bic - np.nanmin(bic), width, color=colours, hatch="//",
             edgecolor="white", label="BIC")
    a_ic.set_yscale("symlog", linthresh=1.)
    a_ic.set_ylabel("criterion minus the lowest")
    a_ic.set_title("(a) AIC (plain) and BIC (hatched)")
    if np.all(np.isnan(held)):
        a_h.text(0.5, 0.5, "held-out error not computed (one file)", ha="center",
                 transform=a_h.transAxes)
    else:
        a_h.bar(x, held, color=colours)
        a_h.set_yscale("log")
    a_h.set_ylabel("held-out relative rms (mean over files)")
    a_h.set_title("(b) leave-one-file-out error")
    for ax in (a_ic, a_h):
        ax.set_xticks(x)
        ax.set_xticklabels(names, rotation=20)
    verdict = text(f.attrs["verdict"])
    fig.suptitle("recommended (green): " + recommended + "\n" + textwrap.fill(verdict, 130),
                 fontsize=9)
    return fig


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
        if "models" in f:
            fig = plot_models(f, args)
        elif "samples" in f:
            fig = plot_material_tests(f, args)
        else:
            fig = plot_displacements(f, args)
    fig.tight_layout()
    out = args.out or os.path.splitext(args.file)[0] + ".png"
    fig.savefig(out, dpi=120)
    print(f"{PROG}: wrote {out}")


if __name__ == "__main__":
    main()
