#!/usr/bin/python3
"""Figures of the partitioning study (build/benchmarks/bench_partitioning).

Usage: plot_optimization.py [CSV_DIR] [--out DIR]

Reads rings.csv, graded.csv and field.csv from CSV_DIR (default
results/optimization) and writes into DIR (default doc/figures):
  optimization-rings.png  (a) the best stroke against the number of rings N,
                          without and with the field limit, and the graded
                          limits; (b) the voltage profiles of the optima for
                          some N and the graded profile over r/a
  optimization-field.png  stroke increase against r_v/a on the red line
                          (s2 = 0 at the outer ring's inner edge) and where
                          the field there reaches the limit, inner ring at
                          5 and 5.5 kV, with the paper's quoted maxima
Needs numpy and matplotlib (Agg backend).
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROG = "plot_optimization.py"


def rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as error:
        sys.exit(f"{PROG}: error: cannot read {path}: {error} "
                 "(run build/benchmarks/bench_partitioning first)")


def extrapolate(values):
    """Richardson on the last three values of a sequence doubling M."""
    a, b, c = values[-3:]
    p = math.log2((b - a) / (c - b))
    return c + (c - b) / (2 ** p - 1)


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    parser.add_argument("csv_dir", nargs="?", default="results/optimization")
    parser.add_argument("--out", default="doc/figures")
    args = parser.parse_args()
    rings = rows(os.path.join(args.csv_dir, "rings.csv"))
    graded = rows(os.path.join(args.csv_dir, "graded.csv"))
    field = rows(os.path.join(args.csv_dir, "field.csv"))
    os.makedirs(args.out, exist_ok=True)

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    limits = sorted({float(r["field_limit_MV_per_m"]) for r in rings})
    for color, limit in zip(("C0", "C3"), limits):
        sel = [r for r in rings if float(r["field_limit_MV_per_m"]) == limit]
        label = "s2 >= 0" if limit == 0 else f"s2 >= 0, E <= {limit:g} MV/m"
        n = [int(r["N"]) for r in sel]
        ax.plot(n, [float(r["stroke_mm"]) for r in sel], "o-", color=color,
                label=label + ": N rings, all free")
        g = [r for r in graded if float(r["field_limit_MV_per_m"]) == limit and r["M"] != "inf"]
        ms = sorted({int(r["M"]) for r in g})
        strokes = [float(next(r["stroke_mm"] for r in g if int(r["M"]) == m)) for m in ms]
        if len(strokes) >= 3:
            ax.axhline(extrapolate(strokes), color=color, ls="--", lw=1,
                       label=f"graded limit, {ms[-3]}..{ms[-1]} equal rings extrapolated")
        cone = [r for r in graded if float(r["field_limit_MV_per_m"]) == limit and r["M"] == "inf"]
        if cone:
            ax.axhline(float(cone[0]["stroke_mm"]), color=color, ls=":", lw=1.5,
                       label="graded limit, straight cone (s2 = 0 everywhere)")
    ax.set_xlabel("number of rings N")
    ax.set_ylabel("largest stroke (mm)")
    ax.set_title("(a) stroke against the number of rings")
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)

    unlimited = [r for r in rings if float(r["field_limit_MV_per_m"]) == 0]
    for r in unlimited:
        if int(r["N"]) not in (2, 4, 8):
            continue
        edges = [float(x) for x in r["edges_over_a"].split()]
        volts = [float(x) for x in r["voltages_kV"].split()]
        xs, ys = [], []
        for k, v in enumerate(volts):
            xs += [edges[k], edges[k + 1]]
            ys += [v, v]
        bx.plot(xs, ys, "-", label=f"N = {r['N']}")
    g = [r for r in graded if float(r["field_limit_MV_per_m"]) == 0 and r["M"] != "inf"]
    if g:
        m = max(int(r["M"]) for r in g)
        sel = [r for r in g if int(r["M"]) == m]
        bx.plot([float(r["r_over_a"]) for r in sel], [float(r["voltage_kV"]) for r in sel], "k-",
                lw=1, label=f"graded, {m} equal rings")
    bx.set_xlabel("r/a (pre-stretched flat film)")
    bx.set_ylabel("ring voltage (kV)")
    bx.set_title("(b) voltages of the optima (s2 >= 0)")
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    out = os.path.join(args.out, "optimization-rings.png")
    fig.savefig(out, dpi=110)
    print(f"{PROG}: wrote {out}")

    fig, ax = plt.subplots(figsize=(7, 4.8))
    paper = {5.0: (1.8, 40.5), 5.5: (2.0, 20.3)}
    limit = max(limits)
    for color, inner in zip(("C0", "C1"), sorted({float(r["inner_kV"]) for r in field})):
        sel = [r for r in field if float(r["inner_kV"]) == inner]
        rv = [float(r["rv_over_a"]) for r in sel]
        ax.plot(rv, [float(r["red_increase_percent"]) for r in sel], "-", color=color,
                label=f"inner {inner:g} kV: s2 = 0 at r_v (red line)")
        ax.plot(rv, [float(r["field_increase_percent"]) for r in sel], "--", color=color,
                label=f"inner {inner:g} kV: E = {limit:g} MV/m at r_v (if before s2 = 0)")
        if inner in paper:
            ax.plot(*paper[inner], "o", mfc="none", color=color, ms=9,
                    label=f"paper, inner {inner:g} kV (red-line maximum)")
    ax.set_xlabel("r_v/a")
    ax.set_ylabel("stroke increase (%)")
    ax.set_title("Stroke increase: loss of tension and an edge field limit")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out = os.path.join(args.out, "optimization-field.png")
    fig.savefig(out, dpi=110)
    print(f"{PROG}: wrote {out}")


if __name__ == "__main__":
    main()
