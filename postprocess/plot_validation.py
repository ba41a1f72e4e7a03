#!/usr/bin/python3
"""Figures of doc/validation.md and doc/performance.md from the CSV files that
the validation benchmarks write.

Usage: plot_validation.py [DATA_DIR] [--out FIG_DIR]

DATA_DIR (default: results/validation) holds the output of
  build/benchmarks/bench_convergence     -> convergence.csv
  build/benchmarks/bench_work_precision  -> work_precision.csv
  build/benchmarks/bench_failure_modes   -> failure_*.csv
  build/benchmarks/bench_paper_lines     -> paper_lines.csv
FIG_DIR (default: doc/figures next to this script's folder) receives
  convergence.png, work-precision.png, failure-modes.png, paper-lines.png;
a figure whose input file is missing is skipped with a message.
Needs numpy and matplotlib (Agg backend, no display).
"""

import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 80
COLORS = {1: "tab:blue", 2: "tab:orange", 3: "tab:green", 4: "tab:red", 5: "tab:purple",
          6: "tab:brown"}


def read_csv(path):
    """Rows of a CSV file as dicts; numbers converted where possible."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key, value in row.items():
            try:
                row[key] = float(value)
            except (TypeError, ValueError):
                pass
    return rows


def column(rows, key):
    return np.array([r[key] for r in rows], dtype=float)


def select(rows, **conditions):
    return [r for r in rows if all(r[k] == v for k, v in conditions.items())]


def save(fig, out_dir, name):
    path = os.path.join(out_dir, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    print(f"wrote {os.path.normpath(path)} ({os.path.getsize(path) // 1024} kB)")


def slope_marker(ax, x0, y0, order, text_right=True):
    """A short line of the given slope (in log-log) starting at (x0, y0)."""
    x1 = x0 * 2.0
    y1 = y0 * 2.0 ** (-order)
    ax.plot([x0, x1], [y0, y1], color="0.3", lw=1)
    ax.text(x1 * (1.05 if text_right else 0.6), y1, f"{order:g}", fontsize=7, color="0.3",
            va="center")


def plot_convergence(data_dir, out_dir):
    path = os.path.join(data_dir, "convergence.csv")
    if not os.path.exists(path):
        print(f"skip convergence.png: {path} missing")
        return
    rows = read_csv(path)
    scenes = [("full", "full electrode, 5 kV"),
              ("partitioned", "$r_v/a$ = 1.7, 5 / 6 kV")]
    quantities = [("disp_err", "displacement", lambda p: 2 * p),
                  ("s2_err_max", "$s_2$ at the ring edges", lambda p: p),
                  ("l2_err", "L2 of (r, z)", lambda p: p + 1)]
    fig, axes = plt.subplots(2, 4, figsize=(13, 6.2))
    for i, (scene, title) in enumerate(scenes):
        for j, (key, label, theory) in enumerate(quantities):
            ax = axes[i, j]
            for p in range(1, 5):
                r = select(rows, scene=scene, study="h", degree=p)
                n = column(r, "elements_per_ring")
                e = column(r, key)
                ax.loglog(n, e, "o-", color=COLORS[p], ms=3, lw=1.2, label=f"p = {p}")
                k = min(2, len(n) - 1)
                slope_marker(ax, n[k] * 1.15, e[k] * 2.5, theory(p))
            r = select(rows, scene=scene, study="h-uniform", degree=3)
            ax.loglog(column(r, "elements_per_ring"), column(r, key), "s--", color=COLORS[3],
                      ms=3, lw=0.8, mfc="none", label="p = 3, uniform")
            if key == "s2_err_max":
                for p in range(1, 5):
                    r = select(rows, scene=scene, study="h", degree=p)
                    ax.loglog(column(r, "elements_per_ring"), column(r, "s2_recovered_err"),
                              ":", color=COLORS[p], lw=1.2)
                ax.plot([], [], "k:", label="disk edge from the reaction")
            ax.axhspan(1e-16, 3e-13, color="0.9", zorder=0)
            ax.set_ylim(1e-14, 2)
            ax.set_xlabel("elements per ring")
            ax.set_title(f"{label}\n{title}", fontsize=9)
            ax.grid(True, which="major", lw=0.3)
            if j == 0:
                ax.set_ylabel("relative error")
            if i == 0 and j in (0, 1):
                ax.legend(fontsize=7, loc="upper right" if j == 0 else "lower left")
        ax = axes[i, 3]
        for key, label, marker in [("disp_err", "displacement", "o"),
                                   ("s2_err_max", "$s_2$ at ring edges", "s"),
                                   ("l2_err", "L2 of (r, z)", "^")]:
            for n, style in [(8, "-"), (2, "--")]:
                r = select(rows, scene=scene, study=f"p{n}")
                ax.semilogy(column(r, "degree"), column(r, key), marker + style, ms=3, lw=1,
                            label=f"{label}, {n}/ring")
        ax.axhspan(1e-16, 3e-13, color="0.9", zorder=0)
        ax.set_ylim(1e-14, 2)
        ax.set_xlabel("polynomial degree p")
        ax.set_title(f"p-refinement\n{title}", fontsize=9)
        ax.grid(True, lw=0.3)
        if i == 0:
            ax.legend(fontsize=6, loc="lower left")
    fig.suptitle("FE against the shooting solution (tolerance 1e-12; grey: its own "
                 "uncertainty); graded meshes (grading 4) unless marked", fontsize=10)
    fig.tight_layout()
    save(fig, out_dir, "convergence.png")


def plot_work_precision(data_dir, out_dir):
    path = os.path.join(data_dir, "work_precision.csv")
    if not os.path.exists(path):
        print(f"skip work-precision.png: {path} missing")
        return
    rows = [r for r in read_csv(path) if r["completed"] == 1]
    scenes = [("full", "full electrode, 0 to 5 kV"),
              ("partitioned", "$r_v/a$ = 1.7: 5 / 5 then 5 / 6 kV")]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    for ax, (scene, title) in zip(axes, scenes):
        for p in sorted({int(r["degree"]) for r in rows if r["method"] == "fe"}):
            r = select(rows, scene=scene, method="fe", degree=p)
            ax.loglog(column(r, "cpu_median_s") * 1e3, np.maximum(column(r, "disp_err"), 1e-14),
                      "o-", color=COLORS[p], ms=3, lw=1.1, label=f"FE p = {p} (1 to "
                      f"{int(r[-1]['elements_per_ring'])} elements/ring)")
        r = [x for x in select(rows, scene=scene, method="shooting")
             if abs(x["tolerance"] / 1e-12 - 1) > 1e-6]
        ax.loglog(column(r, "cpu_median_s") * 1e3, np.maximum(column(r, "disp_err"), 1e-14),
                  "k*-", ms=6, lw=1.4, label="shooting (tolerance 1e-2 to 1e-13 but 1e-12, "
                  "the reference)")
        for rr in r:
            if rr["tolerance"] in (1e-3, 1e-6, 1e-9, 1e-12):
                ax.annotate(f"{rr['tolerance']:.0e}", (rr["cpu_median_s"] * 1e3,
                                                       max(rr["disp_err"], 1e-14)),
                            textcoords="offset points", xytext=(-28, -3), fontsize=7)
        for p, n, marker, text in [(4, 4, "s", "default p = 4, 4/ring"),
                                   (3, 8, "o", "former default p = 3, 8/ring")]:
            d = select(rows, scene=scene, method="fe", degree=p, elements_per_ring=n)
            if d:
                ax.plot(d[0]["cpu_median_s"] * 1e3, d[0]["disp_err"], marker, ms=11,
                        mfc="none", color="k", label=text)
        ax.axhspan(1e-9, 1e-3, color="0.93", zorder=0)
        ax.axhline(1e-5, color="0.5", lw=0.6, ls=":")
        ax.set_xlabel("CPU time of a whole run (ms, median)")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", lw=0.3)
        ax.set_ylim(1e-14, 1e-1)
    axes[0].set_ylabel("relative error of the disk displacement")
    axes[1].legend(fontsize=7, loc="upper right")
    fig.suptitle("Work against precision: one run (pre-stretch, weight, voltage path in 0.25 "
                 "kV steps); grey band: 1e-3 to 1e-9", fontsize=10)
    fig.tight_layout()
    save(fig, out_dir, "work-precision.png")


def plot_failure_modes(data_dir, out_dir):
    needed = ["failure_curve.csv", "failure_steps.csv", "failure_residual.csv",
              "failure_onset_mesh.csv"]
    for name in needed:
        if not os.path.exists(os.path.join(data_dir, name)):
            print(f"skip failure-modes.png: {name} missing")
            return
    curve = read_csv(os.path.join(data_dir, "failure_curve.csv"))
    steps = read_csv(os.path.join(data_dir, "failure_steps.csv"))
    residual = read_csv(os.path.join(data_dir, "failure_residual.csv"))
    onset = read_csv(os.path.join(data_dir, "failure_onset_mesh.csv"))

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    titles = {"full": "full electrode", "rv1.7": "$r_v/a$ = 1.7, inner ring at 5 kV"}
    # The FE run on the library's default mesh, whatever it is (the benchmark
    # names it "FE p=..; ../ring (default)").
    fe_default = next((x["method"] for x in steps
                       if x["method"].startswith("FE") and "(default)" in x["method"]),
                      "FE (default)")
    for ax, case in zip(axes[0], ["full", "rv1.7"]):
        c = select(curve, case=case)
        v = column(c, "V_kV")
        d = column(c, "displacement_mm")
        b = column(c, "branch")
        for branch, style, label in [(0, "-", "stable branch"),
                                     (1, "--", "unstable branch (behind the fold)"),
                                     (2, ":", "far branch ($s_2$ very negative)")]:
            m = b == branch
            ax.plot(v[m], d[m], style, color="k", lw=1.3, label=label)
        s2 = column(c, "s2_min_over_mu")
        m = (b == 0) & (s2 < 0)
        ax.plot(v[m], d[m], "-", color="tab:red", lw=3, alpha=0.35,
                label="$s_2 < 0$ somewhere (wrinkled)")
        for method, marker, color in [(fe_default, "o", "tab:green"),
                                      ("FE p=2; 2/ring (coarse)", "^", "tab:orange"),
                                      ("shooting tol 1e-10 (default)", "x", "tab:blue")]:
            s = select(steps, case=case, method=method)
            if s:
                ax.plot(column(s, "V_kV"), column(s, "displacement_mm"), marker, ms=3,
                        color=color, mfc="none", label=f"load steps: {method.replace(';', ',')}")
                ax.plot(s[-1]["V_kV"], s[-1]["displacement_mm"], marker, ms=9, color=color)
        turns = [k for k in range(1, len(c)) if b[k] != b[k - 1]]
        for k in turns:
            first = b[k] == 1
            ax.annotate(f"fold: {v[k]:.4f} kV" if first else f"turn: {v[k]:.3f} kV",
                        (v[k], d[k]), textcoords="offset points",
                        xytext=(-120, 12) if first else (-70, 14), fontsize=8,
                        arrowprops=dict(arrowstyle="->", lw=0.6))
        if turns:
            # Zoom on the fold: where each method's load stepping stopped.
            k = turns[0]
            inset = ax.inset_axes([0.62, 0.06, 0.35, 0.33])
            inset.plot(v[b <= 1], d[b <= 1], "k-", lw=1)
            inset.plot(v[k], d[k], "k*", ms=9)
            for method, marker, color in [(fe_default, "o", "tab:green"),
                                          ("FE p=4; 32/ring (refined)", "s", "tab:purple"),
                                          ("shooting tol 1e-10 (default)", "x", "tab:blue")]:
                s = select(steps, case=case, method=method)
                if s:
                    inset.plot(s[-1]["V_kV"], s[-1]["displacement_mm"], marker, ms=7,
                               color=color, mfc="none")
            inset.set_xlim(v[k] - 0.02, v[k] + 0.004)
            inset.set_ylim(d[k] - 2.5, d[k] + 2.5)
            inset.tick_params(labelsize=6)
            inset.set_title("fold (star) and last converged steps", fontsize=7)
            inset.ticklabel_format(useOffset=False)
        lo = 4.5 if case == "full" else 5.0
        ax.set_xlim(lo, 9.0)
        ax.set_ylim(15, 50)
        ax.set_xlabel("voltage (kV)" if case == "full" else "outer voltage (kV)")
        ax.set_ylabel("disk displacement (mm)")
        ax.set_title(f"({'a' if case == 'full' else 'b'}) {titles[case]}: equilibria; large "
                     "marker: last load step", fontsize=9)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=6.5, loc="lower left")

    ax = axes[1, 0]
    r = select(residual, case="full")
    voltages = sorted({x["V_kV"] for x in r})
    cmap = plt.get_cmap("viridis")
    for i, V in enumerate(voltages):
        rv = select(r, V_kV=V)
        th = column(rv, "theta0")
        f = column(rv, "residual")
        ax.plot(th, f, color=cmap(i / max(1, len(voltages) - 1)), lw=1, label=f"{V:g} kV")
        ok = column(rv, "ok")
        if np.any(ok == 0):
            ax.axvline(th[np.argmax(ok == 0)], color=cmap(i / max(1, len(voltages) - 1)),
                       lw=0.5, ls=":")
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlim(0, 2.3)
    ax.set_ylim(-1.2, 1.5)
    ax.set_xlabel(r"shooting angle $\theta_0$ at the disk edge (rad)")
    ax.set_ylabel("residual r(B)/b - 1")
    ax.set_title("(c) full electrode: single-shooting residual (dotted: integration fails "
                 "beyond)", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, ncol=2, loc="upper right")

    ax = axes[1, 1]
    for case, style in [("full", "-"), ("rv1.7", "--")]:
        for p in range(1, 5):
            o = [x for x in select(onset, case=case, degree=p, grading=4.0)] + \
                [x for x in select(onset, case=case, degree=p, grading=1.0)
                 if x["elements_per_ring"] == 1]
            o.sort(key=lambda x: x["dofs"])
            dofs = column(o, "dofs")
            shift = np.abs(column(o, "onset_kV") - column(o, "reference_kV")) * 1e3
            ax.loglog(dofs, np.maximum(shift, 1e-6), "o" + style, color=COLORS[p], ms=3, lw=1,
                      label=f"p = {p}, {titles[case]}" if case == "full" or p == 1 else None)
            miss = np.isnan(shift)
            if np.any(miss):
                ax.plot(dofs[miss], np.full(np.count_nonzero(miss), 3e3), "v", color=COLORS[p],
                        ms=7, ls="none")
    # Reference levels and the marker for a missed onset: explained in a
    # legend of their own, in the empty upper right, not as text on the data.
    levels = [ax.axhline(118, color="0.5", lw=0.8, ls="--"),
              ax.axhline(0.01, color="0.5", lw=0.8, ls=":"),
              ax.plot([], [], "v", color="0.3", ms=7, ls="none")[0]]
    ax.set_ylim(4e-7, 3e4)
    ax.set_xlabel("unknowns (graded meshes, 1 to 16 elements per ring)")
    ax.set_ylabel("|onset voltage FE - shooting| (V)")
    ax.set_title("(d) onset shift by the mesh; solid: full electrode, dashed: $r_v/a$ = 1.7",
                 fontsize=9)
    ax.grid(True, which="major", lw=0.3)
    meshes = ax.legend(fontsize=7, loc="lower left")
    ax.add_artist(meshes)
    ax.legend(levels, ["5.5 kV - onset (full electrode): a path to 5.5 kV\n"
                       "misses any larger shift", "0.01 V", "no onset found up to 6.6 kV"],
              fontsize=7, loc="upper right")
    fig.tight_layout()
    save(fig, out_dir, "failure-modes.png")


def plot_paper_lines(data_dir, out_dir):
    path = os.path.join(data_dir, "paper_lines.csv")
    if not os.path.exists(path):
        print(f"skip paper-lines.png: {path} missing")
        return
    rows = select(read_csv(path), method="fe")
    fig, ax = plt.subplots(figsize=(7, 4.6))
    for Vi, style in [(5.0, "-"), (5.5, "--")]:
        r = select(rows, Vi_kV=Vi)
        rv = column(r, "r_v")
        d0 = column(r, "disp0_mm")
        base = column(r, "disp_base_mm") - d0
        for line, color in [("blue", "tab:blue"), ("red", "tab:red")]:
            inc = 100 * ((column(r, f"{line}_disp_mm") - d0) / base - 1)
            note = " (past the red line)" if (Vi == 5.5 and line == "blue") else ""
            ax.plot(rv, inc, style, color=color, lw=1.4,
                    label=f"{line} line, inner {Vi:g} kV (cdea){note}")
    for rv, value, color, marker, text in [(1.7, 32.9, "tab:blue", "s", "paper, blue, 5 kV"),
                                           (1.8, 40.5, "tab:red", "s", "paper, red, 5 kV"),
                                           (2.0, 20.3, "tab:red", "D", "paper, red, 5.5 kV"),
                                           (1.4, 58.2, "k", "*", "paper, measured, 5 kV")]:
        ax.plot(rv, value, marker, color=color, ms=8, mfc="none" if marker != "*" else color,
                label=text)
    ax.set_xlabel("$r_v/a$")
    ax.set_ylabel("stroke increase over both rings at the inner voltage (%)")
    ax.set_title("Stroke increase on the paper's lines", fontsize=10)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, ncol=2, loc="upper right")
    ax.set_ylim(15, 75)
    fig.tight_layout()
    save(fig, out_dir, "paper-lines.png")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("data_dir", nargs="?", default=os.path.join("results", "validation"))
    parser.add_argument("--out", default=os.path.join(here, "..", "doc", "figures"))
    args = parser.parse_args()
    if not os.path.isdir(args.data_dir):
        sys.exit(f"plot_validation.py: no directory {args.data_dir}; run the benchmarks first")
    os.makedirs(args.out, exist_ok=True)
    plot_convergence(args.data_dir, args.out)
    plot_work_precision(args.data_dir, args.out)
    plot_failure_modes(args.data_dir, args.out)
    plot_paper_lines(args.data_dir, args.out)


if __name__ == "__main__":
    main()
