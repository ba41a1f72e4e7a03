#!/usr/bin/python3
"""Bode plot of `cdea response`: the small-signal transfer functions and the modes.

Usage: plot_response.py RESPONSE.h5 [MORE.h5 ...] [--out PNG]

Reads <base>_response.h5 (layout in doc/dynamics.md) and writes
<base>_response.png next to the first file (or PNG): (a) the amplitude of the
disk's displacement per kV of the drive (every ring in proportion to its bias
voltage) and, thin, per kV on each ring, against the drive frequency; (b) the
phase of the drive's transfer function; the natural frequencies of the modes
as dotted vertical lines in both; (c) the modes' shapes (vertical
displacement per unit disk displacement against the reference radius).
Several files are overlaid, one colour each. Needs h5py, numpy and
matplotlib (Agg).
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import plot as entry_point  # noqa: E402  (postprocess/plot.py: saving, the command line)

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_response.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_response.py"
REQUIRED = ("transfer/frequency_Hz", "transfer/drive_disk_amplitude_mm_per_kV",
            "transfer/drive_disk_phase_deg", "transfer/disk_mm_per_kV_real",
            "transfer/disk_mm_per_kV_imag", "modes/frequency_Hz", "modes/R_mm", "modes/shape_z")


class ResponseError(ValueError):
    """A file that is not a response file."""


def read(path):
    """The datasets of /transfer and /modes and the root attributes."""
    try:
        with h5py.File(path, "r") as f:
            missing = [k for k in REQUIRED if k not in f]
            if missing:
                raise ResponseError(f"'{path}' is not a file of cdea response (no /{missing[0]})")
            data = {f"{g}/{k}": f[g][k][()] for g in ("transfer", "modes") for k in f[g]}
            attrs = dict(f.attrs)
    except OSError as error:
        raise ResponseError(f"cannot read '{path}': {error}") from None
    return data, attrs


def draw_response(axes, data, color, label):
    """One response on the panels (amplitude, phase, mode shapes)."""
    amp, phase, shapes = axes
    f = data["transfer/frequency_Hz"]
    amp.loglog(f, data["transfer/drive_disk_amplitude_mm_per_kV"], "-", color=color,
               label=f"{label}: drive")
    per_ring = np.abs(data["transfer/disk_mm_per_kV_real"] +
                      1j * data["transfer/disk_mm_per_kV_imag"]).reshape(len(f), -1)
    if per_ring.shape[1] > 1:
        for k in range(per_ring.shape[1]):
            amp.loglog(f, per_ring[:, k], ("--", ":", "-.")[k % 3], color=color, lw=0.8,
                       label=f"{label}: ring {k + 1}")
    # Unwrapped: the jump from -180 to +180 deg is no change of the response.
    unwrapped = np.degrees(np.unwrap(np.radians(data["transfer/drive_disk_phase_deg"])))
    phase.semilogx(f, unwrapped, "-", color=color, label=label)
    for k, fn in enumerate(data["modes/frequency_Hz"]):
        for ax in (amp, phase):
            ax.axvline(fn, color=color, ls=":", lw=1,
                       label=f"{label}: mode {k + 1}, {fn:.3g} Hz" if ax is amp else None)
        shapes.plot(data["modes/R_mm"], data["modes/shape_z"][k], color=color,
                    ls=("-", "--", ":", "-.")[k % 4], label=f"{label}: mode {k + 1}, {fn:.3g} Hz")


def draw(paths, out):
    """The files @p paths overlaid in one picture, written to @p out (and plot.py's)."""
    fig, axes = plt.subplots(3, 1, figsize=(7.5, 9.5),
                             gridspec_kw={"height_ratios": [3, 2, 2]})
    for k, path in enumerate(paths):
        data, attrs = read(path)
        draw_response(axes, data, f"C{k}", os.path.basename(path))
    amp, phase, shapes = axes
    amp.set_ylabel("disk displacement per kV (mm/kV)")
    amp.set_title("(a) amplitude of the transfer functions", fontsize=10)
    phase.set_ylabel("phase (deg)")
    phase.set_xlabel("drive frequency (Hz)")
    phase.set_title("(b) phase of the drive's transfer function (0: in phase; unwrapped)",
                    fontsize=10)
    phase.sharex(amp)
    shapes.set_xlabel("reference radius R (mm)")
    shapes.set_ylabel("vertical displacement per disk displacement")
    shapes.set_title("(c) mode shapes", fontsize=10)
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    entry_point.save(fig, out, PROG)


if __name__ == "__main__":
    entry_point.files_main(PROG, __doc__.splitlines()[0], draw,
                           "<base>_response.h5 files of cdea response")
