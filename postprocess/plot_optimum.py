#!/usr/bin/python3
"""The electrode layout of `cdea optimize`: the optimum's hoop stress and the search.

Usage: plot_optimum.py OPTIMUM.h5 [MORE.h5 ...] [--out PNG]

Reads <base>_optimum.h5 (layout in doc/optimization.md) and writes
<base>_optimum.png next to the first file (or PNG): (a) the nominal hoop
stress s2 at the optimum against r/a (the pre-stretched flat radius over the
disk radius), each ring's points in a colour of their own, the ring edges as
vertical lines and s2 = 0 as the limit, the true electric field on the right
axis; (b) the stroke of every evaluation of every start, the best layout of
each start's best feasible layout starred (hollow: a layout that breaks a
constraint). Several files are overlaid, one marker each. Needs h5py,
numpy and matplotlib (Agg).
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
    sys.exit("plot_optimum.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_optimum.py"
REQUIRED = ("optimum/r_over_a", "optimum/s2_kPa", "optimum/ring", "optimum/field_MV_per_m",
            "history/start", "history/evaluation", "history/objective", "history/worst_constraint",
            "starts/objective")
FEASIBLE = 1e-6  # the largest scaled constraint value of a feasible layout (the file's)


class OptimumError(ValueError):
    """A file that is not an optimum file."""


def read(path):
    try:
        with h5py.File(path, "r") as f:
            missing = [k for k in REQUIRED if k not in f]
            if missing or "ring_edges_over_a" not in f.attrs:
                raise OptimumError(f"'{path}' is not a file of cdea optimize "
                                   f"(no /{missing[0] if missing else 'ring_edges_over_a'})")
            data = {k: f[k][()] for k in REQUIRED}
            attrs = dict(f.attrs)
    except OSError as error:
        raise OptimumError(f"cannot read '{path}': {error}") from None
    return data, attrs


def draw_optimum(ax, field_ax, history_ax, data, attrs, marker, label):
    x, s2, ring = data["optimum/r_over_a"], data["optimum/s2_kPa"], data["optimum/ring"]
    for k in np.unique(ring):
        rows = ring == k
        ax.plot(x[rows], s2[rows], marker, ms=3.5, color=f"C{int(k) - 1}",
                label=f"{label}: ring {int(k)}")
        field_ax.plot(x[rows], data["optimum/field_MV_per_m"][rows], marker, ms=2.5,
                      mfc="none", color="0.5")
    for edge in np.atleast_1d(attrs["ring_edges_over_a"]):
        ax.axvline(edge, color="0.6", lw=0.8, ls="--")
    start, objective = data["history/start"], data["history/objective"]
    for k in np.unique(start):
        rows = start == k
        n = np.flatnonzero(rows) + 1
        feasible = rows & (data["history/worst_constraint"] <= FEASIBLE)
        history_ax.plot(n, objective[rows], "-", lw=0.8, color=f"C{k}")
        history_ax.plot(np.flatnonzero(feasible) + 1, objective[feasible], marker, ms=4,
                        color=f"C{k}", label=f"{label}: start {int(k)}, feasible")
        infeasible = rows & ~feasible
        history_ax.plot(np.flatnonzero(infeasible) + 1, objective[infeasible], marker, ms=4,
                        mfc="none", color=f"C{k}", label=f"{label}: start {int(k)}, infeasible")
        if feasible.any():
            best = np.flatnonzero(feasible)[np.nanargmax(objective[feasible])]
            history_ax.plot(best + 1, objective[best], "*", ms=12, mec="k", color=f"C{k}")
    ax.set_title(f"(a) hoop stress at the optimum: stroke {float(attrs['stroke_mm']):.4g} mm",
                 fontsize=10)


def draw(paths, out):
    """The files @p paths overlaid in one picture, written to @p out (and plot.py's)."""
    fig, (ax, history_ax) = plt.subplots(2, 1, figsize=(7.5, 8))
    field_ax = ax.twinx()
    for k, path in enumerate(paths):
        data, attrs = read(path)
        draw_optimum(ax, field_ax, history_ax, data, attrs, "os^Dv"[k % 5],
                     os.path.basename(path))
    ax.axhline(0., color="k", lw=0.9)
    ax.set_xlabel("r/a (pre-stretched flat radius over the disk radius)")
    ax.set_ylabel("nominal hoop stress s2 (kPa)")
    field_ax.set_ylabel("true electric field (MV/m, grey)", color="0.4")
    history_ax.set_xlabel("evaluation")
    history_ax.set_ylabel("stroke (mm)")
    history_ax.set_title("(b) stroke of each evaluation (* = best feasible of the start)",
                         fontsize=10)
    for a in (ax, history_ax):
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    entry_point.save(fig, out, PROG)


if __name__ == "__main__":
    entry_point.files_main(PROG, __doc__.splitlines()[0], draw,
                           "<base>_optimum.h5 files of cdea optimize")
