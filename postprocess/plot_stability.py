#!/usr/bin/python3
"""Displacement against the driving voltage through the folds of the
voltage-displacement curve, for doc/stability.md.

    plot_stability.py OUT.png PLAIN.h5 [RELAXED.h5] [--title TEXT]

PLAIN.h5 is an arc-length run (Solver/Continuation = arc length): its stable
states are drawn solid, unstable ones dashed, limit points as squares and the
loss-of-tension onset as a circle. RELAXED.h5, a run with Wrinkling/Model =
relaxed, is drawn on top, its last state (where the relaxed law stops being
admissible) marked with a cross. The x axis is the voltage of the outermost
ring, which is what the voltage stage drives last.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        sys.exit(f"plot_stability.py: error: cannot read {path}: {e}")
    with f:
        if "summary" not in f:
            sys.exit(f"plot_stability.py: error: {path} has no /summary")
        s = f["summary"]
        volt = s["voltage_kV"][:]
        run = {
            "stage": s["stage"][:],
            "v": volt[:, -1],
            "d": s["displacement_mm"][:],
            "stable": s["stable"][:] if "stable" in s else np.full(len(volt), np.nan),
            "limits_v": np.atleast_2d(s.attrs.get("limit_point_voltage_kV", np.zeros((0, 1)))),
            "limits_d": np.atleast_1d(s.attrs.get("limit_point_displacement_mm", np.zeros(0))),
            "onset": int(s.attrs.get("onset_found", 0)),
            "onset_v": np.atleast_1d(s.attrs.get("onset_voltage_kV", [np.nan])),
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
    v, d, st = plain["v"][keep], plain["d"][keep], plain["stable"][keep]
    # Solid where stable, dashed where not: one line per run of equal
    # stability, sharing its end points with the neighbouring runs.
    flag = st > 0.5
    start = 0
    for k in range(1, len(v) + 1):
        if k == len(v) or flag[k] != flag[start]:
            ax.plot(v[start:k + 1], d[start:k + 1], color="tab:blue", lw=2,
                    ls="-" if flag[start] else "--")
            start = k
    ax.plot([], [], color="tab:blue", lw=2, label="plain membrane, stable")
    ax.plot([], [], color="tab:blue", lw=2, ls="--", label="plain membrane, unstable")
    if plain["limits_d"].size:
        ax.plot(plain["limits_v"][:, -1], plain["limits_d"], "s", color="k", ms=7,
                label="limit points (folds)")
        for lv, ld in zip(plain["limits_v"][:, -1], plain["limits_d"]):
            ax.annotate(f"{lv:.4f} kV, {ld:.2f} mm", (lv, ld), textcoords="offset points",
                        xytext=(8, -4), fontsize=8)
    if plain["onset"]:
        ov = plain["onset_v"][-1]
        od = np.interp(ov, v[: np.argmax(v) + 1], d[: np.argmax(v) + 1])
        ax.plot([ov], [od], "o", color="tab:red", ms=8, label=f"loss of tension, {ov:.4f} kV")
    if args.relaxed:
        relaxed = read(args.relaxed)
        keep = relaxed["stage"] == 2
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
    fig.savefig(args.out, dpi=110)
    print(args.out)


if __name__ == "__main__":
    main()
