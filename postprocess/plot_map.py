#!/usr/bin/python3
"""Design maps of `cdea sweep` (like figures 8 and 9 of Guo et al. 2025).

Usage: plot_map.py MAP.h5 [MAP.h5 ...] [--out DIR] [--combined PNG] [--paper]
                   [--rows] [--find-increase RV:PERCENT ...]

For every <base>_map.h5 written by `cdea sweep` it writes into DIR (default:
the directory of the file):
  <base>_map.png       displacement over outer voltage and r_v/a, the red line
                       (s2 = 0 at the outer ring's inner edge), the blue line
                       (equal s2 at both inner edges), their maxima of the
                       stroke increase marked, and the continuation limit
  <base>_increase.png  stroke increase on the red and blue lines vs r_v/a
--combined PNG  one figure-9-like plot of the increases of all files given
--paper         mark the largest increases the paper quotes (section 3)
and prints a table of the largest increase on each line (stdout);
--rows adds one line per r_v/a; --find-increase 1.8:40.5 prints the outer
voltage at which row r_v/a = 1.8 reaches a 40.5 % stroke increase
(linear interpolation in the map) and s2 at both inner edges there.

The file layout is described in doc/design-maps.md. Needs h5py, numpy and
matplotlib (Agg backend, no display).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_map.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_map.py"

# Largest stroke increases quoted in the paper's section 3 (figure 8 text):
# inner voltage (kV) -> list of (line, r_v/a, percent).
PAPER = {5.0: [("blue", 1.7, 32.9), ("red", 1.8, 40.5)],
         5.5: [("red", 2.0, 20.3)]}

REQUIRED = ("rv_over_a", "outer_voltage_kV", "displacement_mm", "stroke_increase_percent",
            "s2_inner_edge_kPa", "red_line_outer_kV", "red_line_increase_percent",
            "blue_line_outer_kV", "blue_line_increase_percent")


class MapError(Exception):
    """A problem with the input that ends the program with a message."""


class Map:
    """Everything the plots need from one map file."""

    def __init__(self, path):
        if not os.path.exists(path):
            raise MapError(f"no such file: {path}")
        if not os.path.isfile(path):
            raise MapError(f"not a regular file: {path}")
        try:
            handle = h5py.File(path, "r")
        except OSError as e:
            raise MapError(f"cannot open {path} as an HDF5 file: {e}") from None
        with handle as f:
            missing = [k for k in REQUIRED if k not in f]
            if missing:
                raise MapError(f"{path} is not a cdea map file: missing "
                               + ", ".join(missing))
            self.path = path
            self.rv = np.asarray(f["rv_over_a"][...], dtype=float)
            self.outer = np.asarray(f["outer_voltage_kV"][...], dtype=float)
            n, m = len(self.rv), len(self.outer)
            self.disp = np.asarray(f["displacement_mm"][...], dtype=float).reshape(n, m)
            self.zero_disp = float(np.asarray(f.attrs.get("zero_voltage_displacement_mm",
                                                          np.nan)).ravel()[0])
            self.inc = np.asarray(f["stroke_increase_percent"][...], dtype=float).reshape(n, m)
            self.s2 = np.asarray(f["s2_inner_edge_kPa"][...], dtype=float).reshape(n, m, 2)
            self.line = {}
            self.line_disp = {}
            for name in ("red", "blue"):
                self.line[name] = (np.asarray(f[f"{name}_line_outer_kV"][...], dtype=float),
                                   np.asarray(f[f"{name}_line_increase_percent"][...],
                                              dtype=float))
                key = f"{name}_line_displacement_mm"
                self.line_disp[name] = (np.asarray(f[key][...], dtype=float) if key in f
                                        else np.full(n, np.nan))
            self.highest = (np.asarray(f["highest_outer_kV"][...], dtype=float)
                            if "highest_outer_kV" in f else np.full(n, np.nan))
            self.inner = float(np.asarray(f.attrs.get("inner_voltage_kV", np.nan)))
        if n == 0 or m == 0:
            raise MapError(f"{path}: the map is empty")
        name = os.path.basename(path)
        for suffix in ("_map.h5", ".h5"):
            if name.endswith(suffix):
                name = name[: -len(suffix)]
                break
        self.base = name

    def maximum(self, name):
        """(index, outer kV, percent) of the largest increase on a line, or None."""
        outer, inc = self.line[name]
        if np.all(np.isnan(inc)):
            return None
        i = int(np.nanargmax(inc))
        return i, outer[i], inc[i]

    def find_increase(self, rv, percent):
        """Outer voltage (kV) where row rv first reaches percent, s2 there (kPa)."""
        i = int(np.argmin(np.abs(self.rv - rv)))
        if abs(self.rv[i] - rv) > 1e-9:
            raise MapError(f"{self.path}: r_v/a = {rv} is not a row of the map "
                           f"(rows: {', '.join(f'{x:g}' for x in self.rv)})")
        inc = self.inc[i]
        for k in range(len(inc) - 1):
            a, b = inc[k], inc[k + 1]
            if np.isnan(a) or np.isnan(b):
                continue
            if (a - percent) * (b - percent) <= 0 and a != b:
                t = (percent - a) / (b - a)
                v = self.outer[k] + t * (self.outer[k + 1] - self.outer[k])
                s2 = self.s2[i, k] + t * (self.s2[i, k + 1] - self.s2[i, k])
                return v, s2
        return None


def line_label(name):
    return {"red": "red line: s2 = 0 at the outer ring's inner edge",
            "blue": "blue line: equal s2 at both inner edges"}[name]


def draw_map(fig, ax, mp, stroke=False):
    """The map of one file on @p ax: displacement (or the stroke, displacement
    minus its zero-voltage value, with @p stroke), both lines with their
    maxima, and the region past the red line grey and hatched: there the
    outer ring has lost tension, so those layouts and voltages are not usable
    (and take no part in the colour scale)."""
    values = mp.disp - mp.zero_disp if stroke else mp.disp
    quantity = "stroke" if stroke else "displacement"
    red_outer = mp.line["red"][0]
    # The colour scale spans the usable cells only (up to the red line), so
    # that they get the whole range; the cells past it are grey.
    past = np.isfinite(red_outer)[:, None] & (mp.outer[None, :] > red_outer[:, None])
    usable = np.ma.masked_where(past | ~np.isfinite(values), values)
    unusable = np.ma.masked_where(~past | ~np.isfinite(values), np.zeros_like(values))
    if usable.count() == 0:  # every cell past the red line: scale on them all
        usable = np.ma.masked_invalid(values)
    low, high = float(usable.min()), float(usable.max())
    grey = matplotlib.colors.ListedColormap(["0.8"])
    if len(mp.outer) > 1 and len(mp.rv) > 1:
        mesh = ax.pcolormesh(mp.outer, mp.rv, usable, shading="nearest", cmap="viridis",
                             vmin=low, vmax=high)
        if unusable.count():
            ax.pcolormesh(mp.outer, mp.rv, unusable, shading="nearest", cmap=grey)
        levels = np.arange(np.floor(low), np.ceil(high) + 1, 1.0)
        if len(levels) > 1:
            cs = ax.contour(mp.outer, mp.rv, usable, levels=levels, colors="white",
                            linewidths=0.5, alpha=0.6)
            ax.clabel(cs, fmt="%g", fontsize=7)
    else:
        x = np.repeat(mp.outer[None, :], len(mp.rv), 0)
        y = np.repeat(mp.rv[:, None], len(mp.outer), 1)
        mesh = ax.scatter(x, y, c=usable, cmap="viridis", vmin=low, vmax=high)
        if unusable.count():
            ax.scatter(x[past], y[past], c="0.8")
    fig.colorbar(mesh, ax=ax, label=f"{quantity} (mm), up to the red line")
    if np.any(np.isfinite(red_outer)):
        # Past the red line, up to the end of the grid (or where the row
        # stopped): greyed and hatched.
        right = np.where(np.isfinite(mp.highest), np.minimum(mp.highest, mp.outer[-1]),
                         mp.outer[-1])
        has = np.isfinite(red_outer)
        rv, left, right = mp.rv[has], red_outer[has], np.maximum(right[has], red_outer[has])
        if len(rv) > 1:  # out to the cell edges of the first and last row
            half = 0.5 * (mp.rv[1] - mp.rv[0])
            rv = np.concatenate(([rv[0] - half], rv, [rv[-1] + half]))
            left = np.concatenate(([left[0]], left, [left[-1]]))
            right = np.concatenate(([right[0]], right, [right[-1]]))
        ax.fill_betweenx(rv, left, right,
                         facecolor=(1, 1, 1, 0.55), edgecolor="0.25", hatch="///", lw=0,
                         zorder=3, label="past the red line: lost tension, not usable")
    if not np.all(np.isnan(mp.highest)) and np.any(mp.highest < mp.outer[-1]):
        ax.plot(mp.highest, mp.rv, color="0.4", ls=":", lw=1.2,
                label="highest outer voltage reached (fold)")
    for name, color, offset in (("red", "tab:red", (10, 6)), ("blue", "tab:blue", (-62, -16))):
        outer, inc = mp.line[name]
        ax.plot(outer, mp.rv, color=color, lw=2, label=line_label(name), zorder=4)
        best = mp.maximum(name)
        if best is not None:
            i, v, p = best
            ax.plot(v, mp.rv[i], marker="*", ms=15, color=color, mec="black", zorder=5)
            ax.annotate(f"{p:.1f} %", (v, mp.rv[i]), textcoords="offset points",
                        xytext=offset, color="black", fontsize=9, zorder=6,
                        bbox=dict(boxstyle="round,pad=0.2", fc="white", alpha=0.8))
    ax.set_xlabel("outer ring voltage (kV)")
    ax.set_ylabel("r_v / a")
    ax.set_xlim(mp.outer[0], mp.outer[-1])
    ax.set_title(f"inner ring at {mp.inner:g} kV: {quantity}; * = largest stroke increase "
                 "on a line", fontsize=10)
    ax.legend(loc="lower right", fontsize=7.5, framealpha=0.9).set_zorder(6)


def plot_map(mp, out_dir):
    fig, ax = plt.subplots(figsize=(7.2, 5.0), constrained_layout=True)
    draw_map(fig, ax, mp)
    path = os.path.join(out_dir, f"{mp.base}_map.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# Colours of the red and the blue line of each map in a combined figure: the
# first map in red and blue, the next ones in other hues, so that two inner
# voltages never share a colour.
LINE_COLORS = [("tab:red", "tab:blue"), ("tab:orange", "tab:cyan"), ("tab:pink", "tab:purple"),
               ("tab:brown", "tab:green")]


def plot_increase(maps, path, paper):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10.0, 5.0))
    markers = ["o", "s", "^", "D", "v"]
    for j, mp in enumerate(maps):
        mk = markers[j % len(markers)]
        red, blue = LINE_COLORS[j % len(LINE_COLORS)]
        for name, color, ls in (("red", red, "-"), ("blue", blue, "--")):
            outer, inc = mp.line[name]
            label = f"inner {mp.inner:g} kV, {name} line"
            ax.plot(mp.rv, inc, color=color, ls=ls, marker=mk, ms=3.5, lw=1.4, label=label)
            bx.plot(mp.rv, mp.line_disp[name], color=color, ls=ls, marker=mk, ms=3.5, lw=1.4,
                    label=label)
            best = mp.maximum(name)
            if best is not None:
                i, _, p = best
                ax.plot(mp.rv[i], p, marker="*", ms=14, color=color, mec="black", zorder=5)
                bx.plot(mp.rv[i], mp.line_disp[name][i], marker="*", ms=14, color=color,
                        mec="black", zorder=5)
        if paper:
            for name, rv, p in PAPER.get(round(mp.inner, 6), []):
                ax.plot(rv, p, marker=mk, ms=11, ls="none", mfc="none",
                        mec=red if name == "red" else blue, mew=2.2, zorder=6,
                        label=f"paper: largest increase, inner {mp.inner:g} kV, {name} line")
    ax.set_xlabel("r_v / a")
    ax.set_ylabel("stroke increase on the line (%)")
    ax.set_title("(a) stroke increase on the red / blue line (* = maximum)", fontsize=10)
    bx.set_xlabel("r_v / a")
    bx.set_ylabel("displacement on the line (mm)")
    bx.set_title("(b) displacement on the line", fontsize=10)
    for a in (ax, bx):
        a.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    rows = -(-len(labels) // 2)
    fig.subplots_adjust(left=0.07, right=0.98, top=0.93, wspace=0.25,
                        bottom=0.14 + 0.035 * rows)
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=7.5, frameon=False)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def print_table(mp, rows):
    print(f"{mp.path}: inner {mp.inner:g} kV, {len(mp.rv)} r_v/a x {len(mp.outer)} "
          f"outer voltages")
    for name in ("red", "blue"):
        best = mp.maximum(name)
        if best is None:
            print(f"  {name} line: not in the range")
        else:
            i, v, p = best
            print(f"  largest stroke increase on the {name} line: {p:.2f} % "
                  f"at r_v/a = {mp.rv[i]:g} (outer {v:.4f} kV)")
    if rows:
        print(f"  {'r_v/a':>6} {'red kV':>8} {'red %':>7} {'blue kV':>8} {'blue %':>7} "
              f"{'reached kV':>10}")
        # As many decimals as the rows need to be told apart (a refined map
        # has steps of 0.002, the coarse one of 0.05).
        decimals = next((d for d in range(2, 9)
                         if all(abs(round(rv, d) - rv) < 1e-9 for rv in mp.rv)), 9)
        for i, rv in enumerate(mp.rv):
            r, b = mp.line["red"], mp.line["blue"]
            print(f"  {rv:6.{decimals}f} {r[0][i]:8.4f} {r[1][i]:7.2f} {b[0][i]:8.4f} {b[1][i]:7.2f} "
                  f"{mp.highest[i]:10.3f}")


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", help="<base>_map.h5 files of cdea sweep")
    parser.add_argument("--out", help="output directory (default: next to each file)")
    parser.add_argument("--combined", help="write the increases of all files into this PNG")
    parser.add_argument("--paper", action="store_true",
                        help="mark the largest increases quoted in the paper")
    parser.add_argument("--rows", action="store_true", help="print one line per r_v/a")
    parser.add_argument("--find-increase", action="append", default=[], metavar="RV:PERCENT",
                        help="outer voltage where row RV reaches PERCENT stroke increase")
    args = parser.parse_args(argv)
    try:
        maps = [Map(p) for p in args.files]
        queries = []
        for q in args.find_increase:
            try:
                rv, pct = (float(x) for x in q.split(":"))
            except ValueError:
                raise MapError(f"--find-increase wants RV:PERCENT, got '{q}'") from None
            queries.append((rv, pct))
        for mp in maps:
            out_dir = args.out or os.path.dirname(os.path.abspath(mp.path))
            os.makedirs(out_dir, exist_ok=True)
            print_table(mp, args.rows)
            for rv, pct in queries:
                hit = mp.find_increase(rv, pct)
                if hit is None:
                    print(f"  r_v/a = {rv:g} does not reach {pct:g} % in the map")
                else:
                    v, s2 = hit
                    print(f"  r_v/a = {rv:g} reaches {pct:g} % at outer {v:.3f} kV "
                          f"(interpolated), s2 there {s2[0]:.2f} kPa (disk edge), "
                          f"{s2[1]:.2f} kPa (r_v)")
            print("  wrote", plot_map(mp, out_dir))
            print("  wrote", plot_increase([mp], os.path.join(out_dir, f"{mp.base}_increase.png"),
                                           args.paper))
        if args.combined:
            directory = os.path.dirname(os.path.abspath(args.combined))
            os.makedirs(directory, exist_ok=True)
            print("wrote", plot_increase(maps, args.combined, args.paper))
    except MapError as e:
        sys.stderr.write(f"{PROG}: error: {e}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
