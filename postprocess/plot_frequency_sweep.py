#!/usr/bin/python3
"""Frequency sweeps of `cdea frequency-sweep`: stroke and dissipation per cycle.

Usage: plot_frequency_sweep.py SWEEP.h5 [MORE.h5 ...] [--out PNG] [--labels A,B,...]

Reads <base>_frequency_sweep.h5 files (layout in doc/dynamics.md, "Periodic
steady states and the frequency sweep") and writes <base>_frequency_sweep.png
next to the first (or PNG): (a) the stroke amplitude of the periodic steady
state against the drive frequency, with each file's quasi-static amplitude
and the usable factor's bounds dashed; (b) the energy dissipated per cycle.
Several files are overlaid, one colour each (labelled by --labels, default
the file names). Frequencies whose swing reaches loss of tension are marked
with a red cross, those without a converged steady state with a grey circle;
the usable band is shaded. Needs h5py, numpy and matplotlib (Agg).
"""

import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_frequency_sweep.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_frequency_sweep.py"


def read(path):
    """The sweep's columns and attributes; exits with a message if it is not one."""
    try:
        with h5py.File(path, "r") as f:
            s = f["sweep"]
            data = {name: s[name][...] for name in s}
            attrs = dict(f.attrs)
    except (OSError, KeyError) as e:
        sys.exit(f"{PROG}: error: {path} is not a frequency sweep file ({e})")
    return data, attrs


def draw_sweep(axes, data, attrs, color, label):
    """One sweep on the two panels (a) stroke amplitude and (b) dissipation."""
    a, b = axes
    f = data["frequency_Hz"]
    flagged = data["loss_of_tension"] == 1
    failed = data["converged"] == 0
    low, high = attrs["usable_band_low_Hz"], attrs["usable_band_high_Hz"]
    qs, factor = attrs["quasi_static_amplitude_mm"], attrs["usable_stroke_factor"]
    for ax, y in ((a, data["stroke_amplitude_mm"]), (b, data["dissipated_energy_mJ"])):
        ax.plot(f, y, "o-", color=color, ms=4, label=label)
        ax.plot(f[flagged], y[flagged], "x", color="red", ms=10, mew=2,
                label=f"{label}: loss of tension" if flagged.any() else None)
        ax.plot(f[failed], y[failed], "o", mfc="none", color="grey", ms=10,
                label=f"{label}: not converged" if failed.any() else None)
        if not (math.isnan(low) or math.isnan(high)):
            ax.axvspan(low, high, color=color, alpha=0.12, label=f"{label}: usable band")
    a.axhline(qs, color=color, ls="--", lw=1, label=f"{label}: quasi-static {qs:.3g} mm")
    for bound in (qs * factor, qs / factor):
        a.axhline(bound, color=color, ls=":", lw=1)


def plot(sweeps, out, labels=None):
    """@p sweeps: (data, attrs) pairs of read(); one colour and label each."""
    labels = labels or [f"sweep {k + 1}" for k in range(len(sweeps))]
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True)
    for k, ((data, attrs), label) in enumerate(zip(sweeps, labels)):
        draw_sweep((a, b), data, attrs, f"C{k}", label)
    for ax, ylabel in ((a, "stroke amplitude (mm)"), (b, "dissipated per cycle (mJ)")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
    a.set_title("(a) stroke amplitude of the periodic steady state", fontsize=10)
    b.set_title("(b) energy dissipated per cycle", fontsize=10)
    a.legend(fontsize=7)
    b.set_xlabel("drive frequency (Hz)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"wrote {out}")


def draw(paths, out):
    """The picture of plot.py: the sweeps of @p paths overlaid, labelled by file."""
    plot([read(p) for p in paths], out, [os.path.basename(p) for p in paths])


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("sweeps", nargs="+",
                        help="<base>_frequency_sweep.h5 files of cdea frequency-sweep")
    parser.add_argument("--out", help="the PNG to write (default: beside the first file)")
    parser.add_argument("--labels", help="comma-separated labels, one per file "
                                         "(default: the file names)")
    args = parser.parse_args()
    labels = (args.labels.split(",") if args.labels
              else [os.path.basename(p) for p in args.sweeps])
    if len(labels) != len(args.sweeps):
        sys.exit(f"{PROG}: error: --labels gives {len(labels)} label(s) for "
                 f"{len(args.sweeps)} file(s)")
    out = args.out or os.path.splitext(args.sweeps[0])[0] + ".png"
    plot([read(p) for p in args.sweeps], out, labels)


if __name__ == "__main__":
    main()
