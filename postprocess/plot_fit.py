#!/usr/bin/python3
"""Measured data against the fitted model of `cdea fit`, with the residuals.

Usage: plot_fit.py FILE.h5 [--out PNG] [--ring K]

Reads <base>_fit.h5 (layouts in doc/optimization.md, "Calibration", and
doc/materials.md) and writes <base>_fit.png next to it (or PNG). The file's
kind decides the panels, (a) measured against fitted and (b) the residuals
(model - measured):
  actuator points: the displacements and the fitted model along the data
    (the curve through the points in file order) against the voltage of
    ring K (default: the ring whose voltage changes most over the data);
  creep: the displacement against time, measured and fitted, with the ring
    voltages on the right axis;
  DMA: storage and loss modulus against frequency, measured and fitted;
  material tests: nominal stress against stretch of every test file,
    measured and fitted (dashed: a test predicted with --predict, not fitted).
Reads <base>_models.h5 of a model selection too (doc/materials.md, "Choosing
a model"): per candidate AIC and BIC (from the lowest) and the held-out
error, the recommended model marked.
Each writes the fitted values with their standard errors and the rms
residual into panel (a). Needs h5py, numpy and matplotlib (Agg).
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

# The kinds of fit files and the datasets that tell them apart (the writer
# of each kind writes them all; checked in this order).
KINDS = (("material tests", ("tests/kind", "samples/stretch", "samples/measured_stress_kPa",
                             "samples/model_stress_kPa", "samples/residual_kPa", "samples/test")),
         ("DMA", ("data/frequency_Hz", "data/storage_kPa", "data/loss_kPa",
                  "data/fitted_storage_kPa", "data/fitted_loss_kPa")),
         ("creep", ("data/time_s", "data/voltage_kV", "data/displacement_mm",
                    "data/fitted_mm")),
         ("actuator points", ("data/voltage_kV", "data/displacement_mm", "data/fitted_mm",
                              "curve/voltage_kV", "curve/displacement_mm")))


class FitFileError(ValueError):
    """A file that is not a fit file of a known kind."""


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def kind_of(f):
    """The kind of the open fit file @p f, or None."""
    if "free_parameters" not in f.attrs or "fitted_values" not in f.attrs:
        return None
    for kind, keys in KINDS:
        if all(k in f for k in keys):
            return kind
    return None


def shown(name, value):
    """A fitted value in the units of its prm entry."""
    if "(Pa)" in name:
        return value * 1e-3, "kPa"
    if name.startswith("mass"):
        return value * 1e3, "g"
    if name.startswith("permittivity"):
        return value, "F/m"
    if "(s)" in name:
        return value, "s"
    return value, ""


def read(path):
    """Every dataset and root attribute of a fit file, and its kind."""
    try:
        f = h5py.File(path, "r")
    except OSError as error:
        raise FitFileError(f"cannot read '{path}': {error}") from None
    with f:
        kind = kind_of(f)
        if kind is None:
            raise FitFileError(f"'{path}' is not a file of cdea fit (no fitted values, or "
                               "not the datasets of actuator points, creep, DMA or material "
                               "tests)")
        data = {}
        f.visititems(lambda name, o: data.__setitem__(name, o[()])
                     if isinstance(o, h5py.Dataset) else None)
        attrs = dict(f.attrs)
    return kind, data, attrs


def summary_lines(attrs):
    names = [n.strip() for n in text(attrs["free_parameters"]).split(";")]
    lines = []
    for name, value, error in zip(names, np.atleast_1d(attrs["fitted_values"]),
                                  np.atleast_1d(attrs["standard_errors"])):
        v, unit = shown(name, value)
        e, _ = shown(name, error)
        lines.append(f"{name.split(' (')[0]} = {v:.6g} ± {e:.2g} {unit}".rstrip())
    if "rms_residual_kPa" in attrs:
        lines.append(f"rms residual {float(attrs['rms_residual_kPa']):.3g} kPa")
    else:
        lines.append(f"rms residual {float(attrs['rms_residual_mm']):.3g} mm")
    for warning in filter(None, text(attrs.get("warnings", "")).split("\n")):
        lines.append("warning: " + (warning[:70] + " ..." if len(warning) > 70 else warning))
    return lines


def draw_points(ax, ax_r, data, ring):
    volts = data["data/voltage_kV"]
    n_rings = volts.shape[1]
    ring = ring or int(np.argmax(np.ptp(volts, axis=0))) + 1
    if not 1 <= ring <= n_rings:
        raise FitFileError(f"--ring {ring}: the data have {n_rings} ring(s)")
    x = volts[:, ring - 1]
    if len(data["curve/displacement_mm"]):
        ax.plot(data["curve/voltage_kV"][:, ring - 1], data["curve/displacement_mm"], "-",
                color="C0", label="model, fitted")
    ax.plot(x, data["data/displacement_mm"], "o", mfc="none", color="k", label="measured")
    ax.plot(x, data["data/fitted_mm"], ".", color="C0")
    ax.set_ylabel("displacement (mm)")
    ax_r.plot(x, data["data/fitted_mm"] - data["data/displacement_mm"], "o", color="C3")
    ax_r.set_xlabel(f"voltage of ring {ring} (kV)")
    ax_r.set_ylabel("model - measured (mm)")


def draw_creep(ax, ax_r, data, ring):
    t = data["data/time_s"]
    ax.plot(t, data["data/displacement_mm"], "o", mfc="none", color="k", ms=4, label="measured")
    ax.plot(t, data["data/fitted_mm"], "-", color="C0", label="model, fitted")
    ax.set_ylabel("displacement (mm)")
    volts = ax.twinx()
    for k in range(data["data/voltage_kV"].shape[1]):
        volts.step(t, data["data/voltage_kV"][:, k], where="post", color="0.6", lw=0.8,
                   ls=("-", "--", ":")[k % 3], label=f"ring {k + 1} voltage")
    volts.set_ylabel("ring voltage (kV)", color="0.4")
    ax_r.plot(t, data["data/fitted_mm"] - data["data/displacement_mm"], "o", ms=3, color="C3")
    ax_r.set_xlabel("time (s)")
    ax_r.set_ylabel("model - measured (mm)")


def draw_dma(ax, ax_r, data, ring):
    f = data["data/frequency_Hz"]
    for key, color, marker, label in (("storage", "C0", "o", "E' (storage)"),
                                      ("loss", "C3", "s", "E'' (loss)")):
        ax.loglog(f, data[f"data/{key}_kPa"], marker, mfc="none", color=color,
                  label=f"{label} measured")
        ax.loglog(f, data[f"data/fitted_{key}_kPa"], "-", color=color, label=f"{label} fitted")
        ax_r.semilogx(f, data[f"data/fitted_{key}_kPa"] - data[f"data/{key}_kPa"], marker,
                      ms=4, color=color, label=label)
    ax.set_ylabel("modulus (kPa)")
    ax_r.set_xlabel("frequency (Hz)")
    ax_r.set_ylabel("model - measured (kPa)")
    ax_r.legend(fontsize=7)


def draw_material(ax, ax_r, data, ring):
    test = data["samples/test"]
    kinds = [text(k) for k in data["tests/kind"]]
    fitted = data["tests/fitted"]
    for k, kind in enumerate(kinds):
        rows = test == k
        stretch = data["samples/stretch"][rows]
        use = "fitted" if fitted[k] else "predicted"
        ax.plot(stretch, data["samples/measured_stress_kPa"][rows], "o", ms=2.5, mfc="none",
                color=f"C{k}", alpha=0.6, label=f"{kind}, measured")
        ax.plot(stretch, data["samples/model_stress_kPa"][rows], "-" if fitted[k] else "--",
                color=f"C{k}", lw=1.2, label=f"{kind}, model ({use})")
        ax_r.plot(stretch, data["samples/residual_kPa"][rows], ".", ms=3, color=f"C{k}")
    ax.set_ylabel("nominal stress (kPa)")
    ax_r.set_xlabel("stretch of the loaded direction")
    ax_r.set_ylabel("model - measured (kPa)")


DRAW = {"actuator points": draw_points, "creep": draw_creep, "DMA": draw_dma,
        "material tests": draw_material}


def plot_models(f, path):
    """A model selection: AIC, BIC and held-out error per candidate."""
    for key in ("models/aic", "models/bic", "models/held_out_error"):
        if key not in f:
            raise FitFileError(f"'{path}' is not a model selection of cdea fit (no /{key})")
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


def plot_selection(path, out):
    """The figure of a model selection file @p path, written to @p out."""
    with h5py.File(path, "r") as f:
        fig = plot_models(f, path)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"{PROG}: wrote {out}")


def is_selection(path):
    try:
        with h5py.File(path, "r") as f:
            return "models/model" in f
    except OSError:
        return False


def plot(path, out, ring=None):
    """The figure of the fit or model-selection file @p path, written to @p out."""
    if is_selection(path):
        plot_selection(path, out)
        return
    kind, data, attrs = read(path)
    fig, (ax, ax_r) = plt.subplots(2, 1, figsize=(7, 7), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 1]})
    try:
        DRAW[kind](ax, ax_r, data, ring)
    except FitFileError:
        plt.close(fig)
        raise
    ax.text(0.02, 0.97, "\n".join(summary_lines(attrs)), transform=ax.transAxes, va="top",
            fontsize=8, bbox=dict(facecolor="white", alpha=0.8, edgecolor="0.8"))
    ax.legend(loc="lower right", fontsize=7)
    ax.set_title(f"(a) {kind}: data and fitted model ({os.path.basename(path)})", fontsize=10)
    ax_r.axhline(0., color="0.6", lw=0.8)
    ax_r.set_title("(b) residuals", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"{PROG}: wrote {out}")


def draw(paths, out):
    """The picture of plot.py: one fit file (a fit is not overlaid)."""
    if len(paths) != 1:
        raise FitFileError(f"fit files are drawn one at a time, got {len(paths)}")
    plot(paths[0], out)


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--out")
    parser.add_argument("--ring", type=int, help="actuator points: the ring of the x axis")
    args = parser.parse_args()
    try:
        plot(args.file, args.out or os.path.splitext(args.file)[0] + ".png", args.ring)
    except FitFileError as error:
        sys.exit(f"{PROG}: error: {error}")


if __name__ == "__main__":
    main()
