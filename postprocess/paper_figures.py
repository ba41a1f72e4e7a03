#!/usr/bin/python3
"""The figures of Guo, Liu, Liu and Leng, Smart Mater. Struct. 34 (2025) 085029
("the paper") computed by cdea, in one command.

    paper_figures.py [--out DIR] [--work DIR] [--cdea EXE] [--measured CSV]
                     [--only 3,4,6,7,8,9,11] [--quick]

Runs what the figures need with the cdea executable (parameter files written
into --work, default results/paper; a few seconds in all) and writes into --out
(default results/paper/figures):

  paper-fig3.png   (a) configurations, r_v/a = 1.7, both rings 0 to 5 kV;
                   (b) inner ring 5 kV, outer 5 to 6.5 kV (z/a against r/a)
  paper-fig4.png   (a) full electrode, (b) inner 5 kV and the outer voltage
                   raised for r_v/a = 1.4, 1.7, 2.0: displacement against voltage
  paper-fig6.png   the experiments' comparison: stroke with both rings at 5.0
                   and 5.5 kV and with the outer ring on the red line
  paper-fig7.png   (a-d) lambda1, lambda2, s1/mu, s2/mu against r/a, r_v/a = 1.7
  paper-fig8.png   (a, b) design maps, inner 5 and 5.5 kV, red and blue lines
  paper-fig9.png   the displacement at loss of tension (red line) against r_v/a
  paper-fig11.png  the pump module's level drop, inner ring at 4 kV

The paper's "out-of-plane displacement" is the stroke: the disk's deflection
minus its value at 0 V under the same weight (doc/validation.md, section 5).
Wrinkled parts (lost tension) are shaded red; states cdea flags as
non-physical (/summary/nonphysical) are drawn dashed. --measured overlays
points from a CSV file with the columns figure, series, x, y (figure: a panel
of MEASURED_PANELS, 3a to 11; x and y in the units of that panel's axes, 8a
and 8b: outer voltage in kV and r_v/a; lines starting with # are comments;
another figure is an error); postprocess/paper_measured.csv holds the measured values
the paper quotes in its text. --quick uses coarser design maps (the lines
and the experiments' numbers are located exactly either way). Prints the
comparison with the paper's experiments (+58.2 %, +19.4 %), the largest
stroke on the red line (figure 9) and the pump's levels (figure 11).

Needs Debian's python3-h5py, python3-numpy and python3-matplotlib.
"""

import argparse
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import plot_map  # noqa: E402
import plot_pump  # noqa: E402
import plot_run  # noqa: E402

PROG = "paper_figures.py"
FIGURES = ("3", "4", "6", "7", "8", "9", "11")
# The panels --measured can overlay points on (the CSV's figure column).
MEASURED_PANELS = ("3a", "3b", "4a", "4b", "6a", "6b", "7a", "7b", "7c", "7d", "8a", "8b",
                   "9", "11")
LAYOUTS = (1.4, 1.7, 2.0)  # the paper's r_v/a
A_MM = 14.0  # disk radius a


class FigureError(Exception):
    """A problem that ends the program with a message."""


# ---------------------------------------------------------------- runs

class Runs:
    """Runs cdea once per scene (on first use) and keeps the results."""

    def __init__(self, exe, work, quick):
        self.exe, self.work, self.quick = exe, work, quick
        self.cache = {}
        os.makedirs(work, exist_ok=True)

    def _cdea(self, command, base, text, allowed=(0,)):
        prm = os.path.join(self.work, base + ".prm")
        with open(prm, "w") as f:
            f.write(text + f"subsection Output\n  set Directory = .\n  set Base name = {base}\nend\n")
        done = subprocess.run([self.exe, command, base + ".prm"], cwd=self.work,
                              capture_output=True, text=True)
        if done.returncode not in allowed:
            raise FigureError(f"cdea {command} {prm} failed ({done.returncode}):\n"
                              + done.stderr.strip())

    def run(self, base, rings, path, allowed=(0,)):
        """plot_run.Run of `cdea run` on the paper's actuator."""
        if base not in self.cache:
            self._cdea("run", base, "subsection Electrodes\n"
                       f"  set Ring edges (r/a) = {rings}\n"
                       f"  set Voltage path (kV) = {path}\nend\n", allowed)
            self.cache[base] = plot_run.Run(os.path.join(self.work, base + ".h5"))
        return self.cache[base]

    def partitioned(self):
        """r_v/a = 1.7: both rings to 5 kV, then the outer one to 6.5 kV (a
        waypoint at every state the figures show: the run lands on each)."""
        return self.run("rv1.7-outer6.5", "1, 1.7, 3", "5, 5; 5, 5.5; 5, 6; 5, 6.5")

    def full(self):
        """The full electrode to 5.5 kV (it wrinkles at 5.38 kV)."""
        return self.run("full-5.5", "1, 3", "5; 5.5")

    def outer_raised(self, rv):
        """Inner 5 kV, the outer ring raised to 7 kV (a fold may end it: exit 2)."""
        return self.run(f"rv{rv:g}-outer7", f"1, {rv:g}, 3", "5, 5; 5, 7", allowed=(0, 2))

    def sweep(self, inner):
        base = f"sweep-inner{inner:g}"
        if base not in self.cache:
            rows = "1.2, 1.3, ..., 2.6" if self.quick else "1.2, 1.25, ..., 2.6"
            step = 0.25 if self.quick else 0.05
            self._cdea("sweep", base, "subsection Sweep\n"
                       f"  set Ring edge values (r/a) = {rows}\n"
                       f"  set Inner voltage (kV) = {inner:g}\n"
                       f"  set Outer voltage range (kV) = {inner:g}, {inner + 3:g}, {step:g}\n"
                       "end\n")
            self.cache[base] = plot_map.Map(os.path.join(self.work, base + "_map.h5"))
        return self.cache[base]

    def pump(self):
        if "pump" not in self.cache:
            with open(os.path.join(HERE, "..", "prm", "pump.prm")) as f:
                text = f.read()
            self._cdea("run", "pump", text)
            self.cache["pump"] = plot_pump.PumpRun(os.path.join(self.work, "pump.h5"))
        return self.cache["pump"]


# ---------------------------------------------------------------- helpers

def read_measured(path):
    """{figure: [(series, x, y), ...]} from a CSV file (see the module text)."""
    if path is None:
        return {}
    if not os.path.isfile(path):
        raise FigureError(f"--measured: no such file: {path}")
    with open(path, newline="") as f:
        lines = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
    points = {}
    for k, row in enumerate(csv.DictReader(lines)):
        try:
            key = row["figure"].strip()
            point = (row["series"].strip(), float(row["x"]), float(row["y"]))
        except (KeyError, TypeError, ValueError, AttributeError):
            raise FigureError(f"{path}: data line {k + 1} is not 'figure,series,x,y' "
                              "with numbers x and y") from None
        if key not in MEASURED_PANELS:
            raise FigureError(f"{path}: data line {k + 1}: figure '{key}' is not a panel "
                              f"measured points are drawn on (choose from "
                              f"{', '.join(MEASURED_PANELS)})")
        points.setdefault(key, []).append(point)
    return points


def overlay(ax, measured, key):
    """The measured points of figure @p key, one marker per series."""
    markers = ["s", "D", "^", "v", "o", "P"]
    series = []
    for name, x, y in measured.get(key, []):
        if name not in series:
            series.append(name)
        ax.plot(x, y, markers[series.index(name) % len(markers)], ms=8, mfc="white",
                mec="black", mew=1.5, ls="none", zorder=7, gid=name,
                label=name if (name, key) not in overlay.labelled else None)
        overlay.labelled.add((name, key))


overlay.labelled = set()


def rows_at(run, volts, tolerance=1e-6):
    """The row of each ring-voltage vector in @p volts (first match in the
    voltage stage; all zero: the end of the load stage)."""
    rows = []
    for v in volts:
        if not np.any(v):
            rows.append(run.end_of_load_stage())
            continue
        hit = np.flatnonzero(np.all(np.abs(run.voltage_kV - np.asarray(v)) < tolerance, axis=1)
                             & (run.stage == plot_run.STAGE_VOLTAGE))
        if not len(hit):
            raise FigureError(f"{run.path}: no step at {v} kV")
        rows.append(int(hit[0]))
    return rows


def stroke(run):
    """Stroke of every row (mm): displacement minus its value at 0 V."""
    return run.displacement_mm - run.displacement_mm[run.end_of_load_stage()]


def save(fig, out, name):
    path = os.path.join(out, f"paper-fig{name}.png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    print("wrote", path)


def meridian(ax, run, row, colors, label):
    """One configuration (z/a down against r/a), each ring in its colour, the
    disk black, wrinkled samples shaded, non-physical states dashed."""
    f = run.fields(row)
    sign = plot_run.downward_sign(run, [f])
    x, y = f["r"] / A_MM, sign * (f["z"] - f["z"][-1]) / A_MM
    plot_run.shade_wrinkled(ax, x, y, run.wrinkled_points(row, f), None)
    last = run.n_rings - 1  # the label goes with the outer ring, whose colour varies
    for ring, idx in plot_run.ring_segments(f):
        ax.plot(x[idx], y[idx], color=colors[ring], lw=1.6, label=label if ring == last else None,
                ls="--" if run.nonphysical[row] else "-")
    # Thin and in the state's colour (the outer ring's, which differs between
    # states): the disks of neighbouring states lie close.
    ax.plot([0, x[0]], [y[0], y[0]], color=colors[-1], lw=2, solid_capstyle="butt", zorder=5)


def configuration_axes(ax, title):
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(0, 3.1)
    ax.set_ylim(2.2, -0.1)  # z/a positive down
    ax.set_xlabel("r / a")
    ax.set_ylabel("z / a (down)")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.plot([], [], color="0.3", lw=2, label="rigid disk (colour of its state)")
    ax.plot([], [], color="tab:red", lw=9, alpha=0.3, label="wrinkled (s2 < 0)")
    ax.legend(fontsize=7.5, loc="lower right")


# ---------------------------------------------------------------- figures

def figure3(runs, measured, out):
    run = runs.partitioned()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.4))
    equal = [0, 1, 2, 3, 4, 5]
    shades = plt.get_cmap("viridis")(np.linspace(0, 0.9, len(equal)))
    for v, color, row in zip(equal, shades, rows_at(run, [[v, v] for v in equal])):
        meridian(ax, run, row, [color, color], f"Φ = {v} kV")
    overlay(ax, measured, "3a")
    configuration_axes(ax, "(a) r_v/a = 1.7, the same voltage on both rings")
    outer = [5.0, 5.5, 6.0, 6.5]
    hues = plt.get_cmap("autumn")(np.linspace(0, 0.75, len(outer)))
    for v, color, row in zip(outer, hues, rows_at(run, [[5, v] for v in outer])):
        meridian(ax=bx, run=run, row=row, colors=["tab:blue", color],
                 label=f"Φi = 5 kV (blue), Φo = {v:g} kV")
    overlay(bx, measured, "3b")
    configuration_axes(bx, "(b) inner ring 5 kV, outer ring 5 to 6.5 kV")
    fig.tight_layout()
    save(fig, out, "3")


def curve(ax, run, rows, color, label, onset):
    """Stroke over the outer voltage; solid up to the loss of tension (the
    located onset, where s2 = 0, included), dotted past it, non-physical
    states crossed, the onset marked."""
    x, d = run.voltage_kV[rows, -1], stroke(run)[rows]
    wrinkled = run.wrinkled[rows] != 0
    end = int(np.argmax(wrinkled)) if wrinkled.any() else len(rows)
    at_onset = (run.onset_found and end < len(rows)
                and abs(x[end] - run.onset_voltage_kV[-1]) < 1e-6)
    solid = end + 1 if at_onset else end
    ax.plot(x[:solid], d[:solid], "-", color=color, lw=1.8, label=label)
    if end < len(rows):
        ax.plot(x[max(solid - 1, 0):], d[max(solid - 1, 0):], ":", color=color, lw=1.3)
    bad = run.nonphysical[rows] != 0
    if bad.any():
        ax.plot(x[bad], d[bad], "x", color="black", ms=6)
    if onset and run.onset_found:
        v = run.onset_voltage_kV[-1]
        ax.plot(v, np.interp(v, x[:end + 1], d[:end + 1]), "o", color=color, mec="black", ms=7,
                zorder=6)


def figure4(runs, measured, out):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.4))
    full = runs.full()
    rows = np.concatenate(([full.end_of_load_stage()], full.rows(plot_run.STAGE_VOLTAGE)))
    curve(ax, full, rows, "tab:blue", "cdea, full electrode", onset=True)
    overlay(ax, measured, "4a")
    ax.set_title("(a) the same voltage on the whole electrode", fontsize=10)
    colors = ["tab:red", "tab:green", "tab:purple"]
    for rv, color in zip(LAYOUTS, colors):
        run = runs.outer_raised(rv)
        rows = np.concatenate(([run.end_of_load_stage()], run.rows(plot_run.STAGE_VOLTAGE)))
        curve(bx, run, rows, color, f"cdea, r_v/a = {rv:g}", onset=True)
    overlay(bx, measured, "4b")
    bx.set_title("(b) inner ring 5 kV, outer ring raised until it wrinkles", fontsize=10)
    for a, xlabel in ((ax, "voltage Φ (kV)"), (bx, "outer ring voltage Φo (kV)")):
        a.plot([], [], "o", color="white", mec="black", label="loss of tension (s2 = 0)")
        a.plot([], [], ":", color="0.3", label="wrinkled (past it)")
        a.set_xlabel(xlabel)
        a.set_ylabel("displacement (stroke, mm)")
        a.grid(alpha=0.3)
        a.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    save(fig, out, "4")


def experiments(runs):
    """Strokes (mm) for the paper's figure 6 and its two measured increases."""
    full = runs.full()
    s = stroke(full)
    both = {v: float(s[rows_at(full, [[v]])[0]]) for v in (5.0, 5.5)}
    mp = runs.sweep(5.0)
    red = {}
    for rv in LAYOUTS:
        i = int(np.argmin(np.abs(mp.rv - rv)))
        if abs(mp.rv[i] - rv) > 1e-6:
            raise FigureError(f"{mp.path}: no row at r_v/a = {rv}")
        red[rv] = (float(mp.line["red"][0][i]), float(mp.line_disp["red"][i] - mp.zero_disp))
    print("The paper's experiments (stroke = displacement minus its 0 V value, 280 g):")
    print(f"  both rings at 5.0 kV: {both[5.0]:.4f} mm; both at 5.5 kV: {both[5.5]:.4f} mm")
    for rv in LAYOUTS:
        v, st = red[rv]
        print(f"  r_v/a = {rv:g}: inner 5 kV, outer on the red line {v:.4f} kV: stroke "
              f"{st:.4f} mm, {100 * (st / both[5.0] - 1):+.2f} % over both at 5.0 kV, "
              f"{100 * (st / both[5.5] - 1):+.2f} % over both at 5.5 kV")
    print(f"  measured (paper, section 4): +58.2 % at r_v/a = 1.4 over both at 5.0 kV -> cdea "
          f"{100 * (red[1.4][1] / both[5.0] - 1):+.2f} %; +19.4 % at r_v/a = 1.7 over both at "
          f"5.5 kV -> cdea {100 * (red[1.7][1] / both[5.5] - 1):+.2f} %")
    # The measured increases are of the stroke; the displacement including
    # the sag under the weight rises much less.
    sag = float(full.displacement_mm[full.end_of_load_stage()])
    with_sag = [100 * ((red[rv][1] + sag) / (both[v] + sag) - 1) for rv, v in ((1.4, 5.0),
                                                                               (1.7, 5.5))]
    print(f"  displacement including the {sag:.2f} mm sag under the weight: "
          f"{with_sag[0]:+.2f} % at r_v/a = 1.4 over both at 5.0 kV, {with_sag[1]:+.2f} % at "
          "1.7 over both at 5.5 kV")
    return both, red


def figure6(runs, measured, out):
    both, red = experiments(runs)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    x = np.arange(len(LAYOUTS))
    bars = [("Φi = Φo = 5.0 kV", [both[5.0]] * 3, "tab:gray"),
            ("Φi = Φo = 5.5 kV (wrinkled)", [both[5.5]] * 3, "tab:orange"),
            ("Φi = 5.0 kV, Φo on the red line", [red[rv][1] for rv in LAYOUTS], "tab:blue")]
    for k, (label, values, color) in enumerate(bars):
        ax.bar(x + (k - 1) * 0.27, values, 0.27, color=color, label=label)
    ax.set_ylabel("displacement (stroke, mm)")
    ax.set_title("(a) stroke", fontsize=10)
    over5 = [100 * (red[rv][1] / both[5.0] - 1) for rv in LAYOUTS]
    over55 = [100 * (red[rv][1] / both[5.5] - 1) for rv in LAYOUTS]
    bx.bar(x - 0.15, over5, 0.3, color="tab:gray", label="over both at 5.0 kV")
    bx.bar(x + 0.15, over55, 0.3, color="tab:orange", label="over both at 5.5 kV")
    for k in range(len(LAYOUTS)):
        for dx, value in ((-0.15, over5[k]), (0.15, over55[k])):
            bx.annotate(f"{value:+.1f} %", (x[k] + dx, value), ha="center", va="bottom",
                        fontsize=8, xytext=(0, 2), textcoords="offset points")
    overlay(bx, measured, "6b")
    overlay(ax, measured, "6a")
    bx.set_ylabel("stroke increase, outer ring on the red line (%)")
    bx.set_title("(b) increase; the paper measured +58.2 % (1.4) and +19.4 % (1.7)",
                 fontsize=10)
    for a in (ax, bx):
        a.set_xticks(x)
        a.set_xticklabels([f"r_v/a = {rv:g}" for rv in LAYOUTS])
        a.grid(axis="y", alpha=0.3)
        a.set_ylim(0, 1.35 * a.get_ylim()[1])
        a.legend(fontsize=8, loc="upper center", ncol=2)
    # Measured points come at x = r_v/a: move them onto their bar (a series
    # named "... 5.5 kV" goes with the bars over both rings at 5.5 kV).
    for line in ax.lines + bx.lines:
        shift = 0.15 if "5.5" in str(line.get_gid()) else -0.15
        line.set_xdata(np.interp(line.get_xdata(), LAYOUTS, x) + (shift if line in bx.lines
                                                                    else 0.0))
    fig.tight_layout()
    save(fig, out, "6")


def figure7(runs, measured, out):
    run = runs.partitioned()
    mu = run.mu_kPa
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharex=True)
    states = [(5.0, "tab:red", "Φi = Φo = 5 kV")] + [
        (v, c, f"Φi = 5 kV, Φo = {v:g} kV")
        for v, c in zip((5.5, 6.0, 6.5), ("tab:orange", "tab:green", "tab:blue"))]
    panels = [("lambda1", r"$\lambda_1$", 1.0, "a"), ("lambda2", r"$\lambda_2$", 1.0, "b"),
              ("s1", r"$s_1/\mu$", 1.0 / mu, "c"), ("s2", r"$s_2/\mu$", 1.0 / mu, "d")]
    for ax, (key, ylabel, factor, letter) in zip(axes.flat, panels):
        for (v, color, label), row in zip(states, rows_at(run, [[5, v] for v, _, _ in states])):
            f = run.fields(row)
            x = f["r"] / A_MM
            plot_run.shade_wrinkled(ax, x, f[key] * factor, run.wrinkled_points(row, f), None)
            for ring, idx in plot_run.ring_segments(f):
                ax.plot(x[idx], f[key][idx] * factor, color=color, lw=1.5,
                        label=label if ring == 0 else None)
        overlay(ax, measured, "7" + letter)
        ax.set_ylabel(ylabel)
        ax.set_title(f"({letter})", fontsize=10, loc="left")
        ax.grid(alpha=0.3)
        if key == "s2":
            ax.axhline(0, color="black", lw=0.8)
    (band,) = axes[1, 1].plot([], [], color="tab:red", lw=9, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("r / a")
    axes[0, 0].legend(fontsize=8)
    axes[1, 1].legend([band], ["wrinkled (s2 < 0)"], fontsize=8, loc="lower right")
    fig.suptitle(f"r_v/a = 1.7: stretches and nominal stresses (μ = {mu:g} kPa)", fontsize=10)
    fig.tight_layout()
    save(fig, out, "7")


def figure8(runs, measured, out):
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8), constrained_layout=True)
    for ax, inner, letter in zip(axes, (5.0, 5.5), "ab"):
        mp = runs.sweep(inner)
        plot_map.draw_map(fig, ax, mp, stroke=True)
        overlay(ax, measured, "8" + letter)
        ax.set_title(f"({letter}) inner ring {inner:g} kV: stroke; * = largest increase on a "
                     "line", fontsize=10)
        ax.set_ylabel("r_v / a")
    save(fig, out, "8")


def figure9(runs, measured, out):
    fig, ax = plt.subplots(figsize=(6.5, 4.4))
    print("Figure 9: the largest stroke on the red line (loss of tension), per map row:")
    for inner, red, blue in ((5.0, "tab:red", "tab:blue"), (5.5, "tab:orange", "tab:cyan")):
        mp = runs.sweep(inner)
        on_red = mp.line_disp["red"] - mp.zero_disp
        if np.any(np.isfinite(on_red)):
            i = int(np.nanargmax(on_red))
            print(f"  inner {inner:g} kV: {on_red[i]:.3f} mm at r_v/a = {mp.rv[i]:g} "
                  f"(outer {mp.line['red'][0][i]:.4f} kV)")
        for name, color, ls in (("red", red, "-"), ("blue", blue, "--")):
            values = mp.line_disp[name] - mp.zero_disp
            ax.plot(mp.rv, values, ls, color=color, lw=1.6, marker="o", ms=3,
                    label=f"inner {inner:g} kV, {name} line"
                    + (" (loss of tension)" if name == "red" else ""))
            if np.any(np.isfinite(values)):
                i = int(np.nanargmax(values))
                ax.plot(mp.rv[i], values[i], "*", ms=14, color=color, mec="black", zorder=5)
    overlay(ax, measured, "9")
    ax.set_xlabel("r_v / a")
    ax.set_ylabel("displacement (stroke, mm)")
    ax.set_title("Largest displacement before loss of tension (* = maximum)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5)
    fig.tight_layout()
    save(fig, out, "9")


def figure11(runs, measured, out):
    fig, ax = plt.subplots(figsize=(6.5, 4.4))
    pump = runs.pump()
    print("Figure 11: the pump's level difference at the waypoints of prm/pump.prm:")
    for i in pump.waypoints():
        print(f"  inner {pump.volts[i, 0]:.1f} kV, outer {pump.volts[i, -1]:.1f} kV: "
              f"{pump.drop[i]:.1f} mm")
    plot_pump.draw(ax, [pump], paper=False)
    overlay(ax, measured, "11")
    ax.set_ylabel("water level difference (mm)")
    ax.set_title("Pump module, inner ring 4.0 kV (dashed: both rings ramped together)",
                 fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    save(fig, out, "11")


DRAW = {"3": figure3, "4": figure4, "6": figure6, "7": figure7, "8": figure8, "9": figure9,
        "11": figure11}


def main(argv=None):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join("results", "paper", "figures"))
    parser.add_argument("--work", default=os.path.join("results", "paper"),
                        help="folder of the parameter files and results of the runs")
    parser.add_argument("--cdea", default=os.path.join(HERE, "..", "build", "cdea"),
                        help="the cdea executable (default: build/cdea of this checkout)")
    parser.add_argument("--measured", default=None, help="CSV of measured points to overlay")
    parser.add_argument("--only", default=",".join(FIGURES),
                        help="comma-separated figure numbers (default: all)")
    parser.add_argument("--quick", action="store_true", help="coarser design maps")
    args = parser.parse_args(argv)
    try:
        only = [x.strip() for x in args.only.split(",") if x.strip()]
        unknown = [x for x in only if x not in DRAW]
        if unknown:
            raise FigureError(f"--only: no figure {', '.join(unknown)} "
                              f"(choose from {', '.join(FIGURES)})")
        if not os.access(args.cdea, os.X_OK):
            raise FigureError(f"cannot run the cdea executable '{args.cdea}' "
                              "(build it with scripts/setup.sh, or give --cdea)")
        measured = read_measured(args.measured)
        os.makedirs(args.out, exist_ok=True)
        runs = Runs(os.path.abspath(args.cdea), os.path.abspath(args.work), args.quick)
        for name in only:
            DRAW[name](runs, measured, args.out)
    except (FigureError, plot_run.RunError, plot_map.MapError, plot_pump.PumpError,
            OSError) as e:
        sys.stderr.write(f"{PROG}: error: {e}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
