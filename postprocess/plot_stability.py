#!/usr/bin/python3
"""Displacement against the driving voltage through the folds of the
voltage-displacement curve, for doc/stability.md.

    plot_stability.py OUT.png PLAIN.h5 [RELAXED.h5] [--title TEXT]

PLAIN.h5 is an arc-length run (Solver/Continuation = arc length): its stable
states are drawn solid, unstable ones dashed, limit points as squares and the
loss-of-tension onset as a circle. RELAXED.h5, a run with Wrinkling/Model =
relaxed, is drawn on top, its last state (where the relaxed law stops being
admissible) marked with a cross. The x axis is the voltage of the outermost
ring, which is what the voltage stage drives last. States the summary flags as
non-physical (the meridian beyond the frame, or crossing itself) are drawn in
grey. A run without limit points (load stepping, or a path that ends before
the fold) is drawn as well.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def attribute(s, name, shape):
    """A /summary attribute as a float array of at least @p shape's rank; an
    absent or empty (HDF5 null) attribute gives an empty array."""
    value = s.attrs.get(name, None)
    if value is None or isinstance(value, h5py.Empty):
        return np.zeros(shape)
    value = np.asarray(value, dtype=float)
    return value.reshape(-1, shape[1]) if len(shape) == 2 else value.ravel()


def read(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        sys.exit(f"plot_stability.py: error: cannot read {path}: {e}")
    with f:
        if "summary" not in f:
            sys.exit(f"plot_stability.py: error: {path} has no /summary")
        s = f["summary"]
        volt = np.asarray(s["voltage_kV"][:], dtype=float).reshape(len(s["stage"]), -1)
        rings = volt.shape[1]
        run = {
            "stage": s["stage"][:],
            "v": volt[:, -1],
            "d": s["displacement_mm"][:],
            "stable": s["stable"][:] if "stable" in s else np.full(len(volt), np.nan),
            "nonphysical": (np.nan_to_num(s["nonphysical"][:]).astype(int)
                            if "nonphysical" in s else np.zeros(len(volt), dtype=int)),
            "limits_v": attribute(s, "limit_point_voltage_kV", (0, rings)),
            "limits_d": attribute(s, "limit_point_displacement_mm", (0,)),
            "onset": int(np.asarray(s.attrs.get("onset_found", 0)).ravel()[0]),
            "onset_v": attribute(s, "onset_voltage_kV", (rings,)),
        }
    return run


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("plain")
    parser.add_argument("relaxed", nargs="?")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    plain = read(args.plain)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    keep = plain["stage"] == 2
    if not np.any(keep):
        sys.exit(f"plot_stability.py: error: {args.plain} has no voltage-stage step")
    v, d, st = plain["v"][keep], plain["d"][keep], plain["stable"][keep]
    bad = plain["nonphysical"][keep] != 0
    # Solid where stable, dashed where not, grey where non-physical: one line
    # per run of equal kind, sharing its end points with the neighbouring runs.
    kind = np.where(bad, 2, np.where(st > 0.5, 0, 1))
    start = 0
    for k in range(1, len(v) + 1):
        if k == len(v) or kind[k] != kind[start]:
            ax.plot(v[start:k + 1], d[start:k + 1], lw=2,
                    color="0.6" if kind[start] == 2 else "tab:blue",
                    ls="-" if kind[start] == 0 else "--")
            start = k
    ax.plot([], [], color="tab:blue", lw=2, label="plain membrane, stable")
    if np.any(kind == 1):
        ax.plot([], [], color="tab:blue", lw=2, ls="--", label="plain membrane, unstable")
    if np.any(bad):
        ax.plot([], [], color="0.6", lw=2, ls="--",
                label="non-physical: the meridian leaves the frame or crosses itself")
    if plain["limits_d"].size:
        ax.plot(plain["limits_v"][:, -1], plain["limits_d"], "s", color="k", ms=7,
                label="limit points (folds)")
        for lv, ld in zip(plain["limits_v"][:, -1], plain["limits_d"]):
            ax.annotate(f"{lv:.4f} kV, {ld:.2f} mm", (lv, ld), textcoords="offset points",
                        xytext=(8, -4), fontsize=8)
    if plain["onset"] and plain["onset_v"].size:
        ov = plain["onset_v"][-1]
        rising = slice(0, int(np.argmax(v)) + 1)  # up to the first fold
        od = np.interp(ov, v[rising], d[rising])
        ax.plot([ov], [od], "o", color="tab:red", ms=8, label=f"loss of tension, {ov:.4f} kV")
    if args.relaxed:
        relaxed = read(args.relaxed)
        keep = relaxed["stage"] == 2
        if not np.any(keep):
            sys.exit(f"plot_stability.py: error: {args.relaxed} has no voltage-stage step")
        ax.plot(relaxed["v"][keep], relaxed["d"][keep], color="tab:orange", lw=1.2,
                label="relaxed (tension-field) membrane")
        ax.plot(relaxed["v"][keep][-1:], relaxed["d"][keep][-1:], "x", color="tab:orange",
                ms=10, mew=2, label="relaxed law loses ellipticity (run ends)")
    ax.set_xlabel("voltage of the outer ring (kV)")
    ax.set_ylabel("displacement (mm)")
    ax.set_title(args.title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    folder = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(folder, exist_ok=True)
    fig.savefig(args.out, dpi=110)
    print(args.out)


if __name__ == "__main__":
    main()
