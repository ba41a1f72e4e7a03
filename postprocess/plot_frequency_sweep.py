#!/usr/bin/python3
"""The frequency sweep of `cdea frequency-sweep`: stroke and dissipation per cycle.

Usage: plot_frequency_sweep.py SWEEP.h5 [--out PNG]

Reads <base>_frequency_sweep.h5 (layout in doc/dynamics.md, "Periodic steady
states and the frequency sweep") and writes <base>_frequency_sweep.png next
to it (or PNG): (a) the stroke amplitude of the periodic steady state against
the drive frequency, with the quasi-static amplitude and the usable factor's
bounds dashed; (b) the energy dissipated per cycle. Frequencies whose swing
reaches loss of tension are marked with a red cross, those without a
converged steady state with a grey circle; the usable band is shaded. Needs
h5py, numpy and matplotlib (Agg).
"""

import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

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


def plot(data, attrs, out):
    f = data["frequency_Hz"]
    flagged = data["loss_of_tension"] == 1
    failed = data["converged"] == 0
    low, high = attrs["usable_band_low_Hz"], attrs["usable_band_high_Hz"]
    qs, factor = attrs["quasi_static_amplitude_mm"], attrs["usable_stroke_factor"]
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for ax, y, label in ((a, data["stroke_amplitude_mm"], "stroke amplitude (mm)"),
                         (b, data["dissipated_energy_mJ"], "dissipated per cycle (mJ)")):
        ax.plot(f, y, "o-", color="C0", ms=4)
        ax.plot(f[flagged], y[flagged], "x", color="red", ms=10, mew=2,
                label="loss of tension" if flagged.any() else None)
        ax.plot(f[failed], y[failed], "o", mfc="none", color="grey", ms=10,
                label="not converged" if failed.any() else None)
        if not (math.isnan(low) or math.isnan(high)):
            ax.axvspan(low, high, color="green", alpha=0.15, label="usable band")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    a.axhline(qs, color="k", ls="--", lw=1, label=f"quasi-static {qs:.3g} mm")
    for bound in (qs * factor, qs / factor):
        a.axhline(bound, color="k", ls=":", lw=1)
    a.legend(fontsize=8)
    b.set_xlabel("drive frequency (Hz)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("sweep", help="<base>_frequency_sweep.h5 of cdea frequency-sweep")
    parser.add_argument("--out", help="the PNG to write (default: beside the file)")
    args = parser.parse_args()
    data, attrs = read(args.sweep)
    out = args.out or os.path.splitext(args.sweep)[0] + ".png"
    plot(data, attrs, out)


if __name__ == "__main__":
    main()
