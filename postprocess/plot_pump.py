#!/usr/bin/python3
"""Level drop of the pump module against the outer ring voltage (like figure 11
of Guo et al. 2025), from one or more cdea results files of the pump scene.

Usage: plot_pump.py RESULTS.h5 [MORE.h5 ...] [--out DIR] [--no-paper]

Writes <base>_level_drop.png into DIR (default: the directory of the first
file), <base> being the first file's name without its extension, and prints
the level drop at every waypoint of the voltage path of each file.

Each file is one curve over the voltage stage, x = the outer (last) ring's
voltage: dashed while the rings ramp together, solid once the inner ring
holds its final voltage, waypoints marked. The label says whether the water
load was on (read from the file's parameters). The paper's measured level
drops (24 mm at 4.0/4.0 kV, 35 mm at 4.0/5.0 kV) are drawn as squares unless
--no-paper. Needs h5py, numpy and matplotlib (Agg backend); the columns
level_drop_mm (written by cdea since issue 6), stage, load_factor and
voltage_kV of /summary.
"""

import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_pump.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_pump.py"
STAGE_VOLTAGE = 2
# Guo et al. 2025, section 4 and figure 11: inner ring 4.0 kV, outer 4.0 and 5.0 kV.
PAPER = [(4.0, 5.0), (24.0, 35.0)]


class PumpError(Exception):
    """A problem with the input that ends the program with a message."""


def as_str(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return str(value)


def prm_value(text, name):
    """Value of 'set NAME = value' in the prm text, or None."""
    match = re.search(r"^\s*set\s+" + re.escape(name) + r"\s*=\s*(.*?)\s*$", text, re.MULTILINE)
    return match.group(1) if match else None


class PumpRun:
    def __init__(self, path):
        if not os.path.isfile(path):
            raise PumpError(f"no such file: {path}")
        try:
            handle = h5py.File(path, "r")
        except OSError as e:
            raise PumpError(f"cannot open {path} as an HDF5 file: {e}") from None
        with handle as f:
            if "summary" not in f:
                raise PumpError(f"{path} has no /summary group: not a cdea results file")
            s = f["summary"]
            for name in ("stage", "load_factor", "voltage_kV", "level_drop_mm"):
                if name not in s:
                    raise PumpError(f"{path}: /summary/{name} is missing "
                                    "(level_drop_mm needs a cdea with volume output)")
            self.path = path
            self.stage = np.asarray(s["stage"][...], dtype=int)
            n = len(self.stage)
            self.t = np.asarray(s["load_factor"][...], dtype=float)
            self.volts = np.asarray(s["voltage_kV"][...], dtype=float).reshape(n, -1)
            self.drop = np.asarray(s["level_drop_mm"][...], dtype=float)
            self.wrinkled = (np.asarray(s["wrinkled"][...], dtype=int)
                             if "wrinkled" in s else np.zeros(n, dtype=int))
            nan = np.full(n, np.nan)
            self.volume = (np.asarray(s["volume_mm3"][...], dtype=float)
                           if "volume_mm3" in s else nan)
            self.displacement = (np.asarray(s["displacement_mm"][...], dtype=float)
                                 if "displacement_mm" in s else nan)
            self.s2_min = (np.asarray(s["s2_min_kPa"][...], dtype=float)
                           if "s2_min_kPa" in s else nan)
            params = as_str(f.attrs.get("parameters", ""))
        mu = prm_value(params, "Shear modulus (kPa)")
        self.mu = float(mu) if mu else np.nan
        reference = np.flatnonzero((self.stage == 1) & (self.t == 1.0))
        self.reference = int(reference[0]) if len(reference) else None
        water = (prm_value(params, "Water load") or "false").lower() == "true"
        volume = prm_value(params, "Water volume (ml)")
        self.label = (f"cdea, water load on ({volume} ml)" if water
                      else "cdea, water load off")
        self.water = water
        # Free surface above the frame plane: the water not in the cone stands in the tube.
        try:
            area = float(prm_value(params, "Width (mm)")) * float(prm_value(params, "Depth (mm)"))
            self.surface = (float(volume) * 1e3 - self.volume) / area
        except (TypeError, ValueError):
            self.surface = np.full(n, np.nan)
        rows = np.flatnonzero(self.stage == STAGE_VOLTAGE)
        if len(rows) == 0:
            raise PumpError(f"{path}: no step of the voltage stage")
        self.rows = rows

    def waypoints(self):
        """Rows at integer path parameters (the waypoints of the voltage path)."""
        return [i for i in self.rows if abs(self.t[i] - round(self.t[i])) < 1e-9]


def draw(ax, runs, paper):
    """The level-drop curves of @p runs (and the paper's points) on @p ax."""
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown"]
    for k, run in enumerate(runs):
        color = colors[k % len(colors)]
        rows = run.rows
        outer = run.volts[rows, -1]
        inner = run.volts[rows, 0]
        held = np.isclose(inner, inner[-1])
        ramp = ~held
        if run.volts.shape[1] > 1 and ramp.any():
            # include the first held point so the two parts join
            last_ramp = np.flatnonzero(ramp)[-1]
            idx = np.arange(0, min(last_ramp + 2, len(rows)))
            ax.plot(outer[idx], run.drop[rows][idx], ls="--", color=color, lw=1.2)
        ax.plot(outer[held], run.drop[rows][held], ls="-", color=color, lw=1.8,
                label=f"{run.label}, inner {inner[-1]:g} kV")
        wp = run.waypoints()
        ax.plot(run.volts[wp, -1], run.drop[wp], "o", color=color, ms=5)
        bad = [i for i in rows if run.wrinkled[i]]
        if bad:
            ax.plot(run.volts[bad, -1], run.drop[bad], "x", color="tab:red", ms=5,
                    label="wrinkled (s2 < 0)" if k == 0 else None)
    if paper:
        ax.plot(PAPER[0], PAPER[1], "s", color="black", ms=7, mfc="none", mew=1.5,
                label="Guo et al. 2025, fig. 11 (inner 4.0 kV)")
    ax.set_xlabel("outer ring voltage (kV)")
    ax.set_ylabel("level drop in the tube (mm)")
    ax.set_title("Pump module: water level drop (dashed: both rings ramped together)",
                 fontsize=9)
    ax.grid(alpha=0.3)


def plot(runs, out, paper):
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    draw(ax, runs, paper)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=PROG, description="Level drop of the pump module vs outer voltage (PNG).")
    parser.add_argument("results", nargs="+", help=".h5 files written by cdea run")
    parser.add_argument("--out", default=None,
                        help="output directory (default: next to the first file)")
    parser.add_argument("--no-paper", action="store_true",
                        help="leave out the paper's measured points")
    args = parser.parse_args(argv)
    try:
        runs = [PumpRun(p) for p in args.results]
        out_dir = args.out if args.out else os.path.dirname(os.path.abspath(args.results[0]))
        os.makedirs(out_dir, exist_ok=True)
        base = os.path.splitext(os.path.basename(args.results[0]))[0]
        target = os.path.join(out_dir, f"{base}_level_drop.png")
        for run in runs:
            print(f"{run.path}: {run.label}")
            rows = ([run.reference] if run.reference is not None else []) + run.waypoints()
            for i in rows:
                volts = " / ".join(f"{v:g}" for v in run.volts[i])
                print(f"  {volts:>9} kV: level drop {run.drop[i]:6.2f} mm, volume "
                      f"{run.volume[i]:9.0f} mm3, displacement {run.displacement[i]:6.2f} mm, "
                      f"min s2/mu {run.s2_min[i] / run.mu:6.3f}"
                      + (f", free surface {run.surface[i]:5.1f} mm" if run.water else ""))
        plot(runs, target, not args.no_paper)
    except (PumpError, OSError) as e:
        sys.stderr.write(f"{PROG}: error: {e}\n")
        return 1
    print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
