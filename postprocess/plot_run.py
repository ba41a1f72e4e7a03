#!/usr/bin/python3
"""Plots of one cdea run from its HDF5 results file.

Usage: plot_run.py RESULTS.h5 [--out DIR] [--steps all|last|N,N,...]

Writes, into DIR (default: the directory of RESULTS.h5), with <base> the file
name of RESULTS.h5 without its extension:
  <base>_profiles.png       deformed meridians (r, z), z positive down
  <base>_displacement.png   displacement and stroke over the voltage stage
  <base>_distributions.png  lambda1, lambda2, s1/mu, s2/mu vs r/a

The file layout is the one written by cdea::ResultsFile
(include/cdea/output/results_file.h). Needs h5py, numpy and matplotlib.
"""

import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.legend_handler import HandlerTuple  # noqa: E402

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_run.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_run.py"

STAGE_PRESTRETCH, STAGE_LOAD, STAGE_VOLTAGE = 0, 1, 2

# One hue per ring (profiles), shaded from light to dark over the chosen steps.
RING_COLORMAPS = ["Blues", "Oranges", "Greens", "Purples", "Reds", "Greys"]


class RunError(Exception):
    """A problem with the input that ends the program with a message."""


def fail(message):
    sys.stderr.write(f"{PROG}: error: {message}\n")
    sys.exit(1)


# ---------------------------------------------------------------- reading

def as_str(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return as_str(value[()])
    return str(value)


def shear_modulus_kPa(parameters_text):
    """mu from the prm text ('set Shear modulus (kPa) = ...'), or None."""
    match = re.search(r"^\s*set\s+Shear modulus \(kPa\)\s*=\s*([-+0-9.eE]+)",
                      parameters_text, re.MULTILINE)
    if not match:
        return None
    try:
        mu = float(match.group(1))
    except ValueError:
        return None
    return mu if mu > 0 else None


class Run:
    """Everything the plots need from one results file."""

    def __init__(self, path):
        if not os.path.exists(path):
            raise RunError(f"no such file: {path}")
        if not os.path.isfile(path):
            raise RunError(f"not a regular file: {path}")
        try:
            handle = h5py.File(path, "r")
        except OSError as e:
            raise RunError(f"cannot open {path} as an HDF5 file: {e}") from None
        with handle as f:
            if "summary" not in f or not isinstance(f["summary"], h5py.Group):
                raise RunError(f"{path} has no /summary group: not a cdea results file")
            s = f["summary"]
            for name in ("stage", "load_factor", "voltage_kV", "displacement_mm"):
                if name not in s:
                    raise RunError(f"{path}: /summary/{name} is missing")
            self.path = path
            self.parameters = as_str(f.attrs.get("parameters", ""))
            self.code_version = as_str(f.attrs.get("code_version", "?"))
            self.mu_kPa = shear_modulus_kPa(self.parameters)

            self.stage = np.asarray(s["stage"][...], dtype=int)
            self.n_steps = len(self.stage)
            if self.n_steps == 0:
                raise RunError(f"{path}: /summary is empty (no converged step)")
            self.load_factor = np.asarray(s["load_factor"][...], dtype=float)
            voltage = np.asarray(s["voltage_kV"][...], dtype=float)
            self.voltage_kV = voltage.reshape(self.n_steps, -1)
            self.n_rings = self.voltage_kV.shape[1]
            self.displacement_mm = np.asarray(s["displacement_mm"][...], dtype=float)
            self.stroke_mm = self._column(s, "stroke_mm")
            # A time run (Time/Enabled): the time of each step, NaN in the
            # quasi-static stages before the time integration.
            self.time_s = self._column(s, "time_s")
            self.mass_g = self._column(s, "mass_g")
            self.wrinkled = self._column(s, "wrinkled", fill=0).astype(int)
            # 0: possible; bit 1: r outside [0, b]; bit 2: the meridian crosses
            # itself or the disk (files of older versions lack the column).
            self.nonphysical = np.nan_to_num(self._column(s, "nonphysical", fill=0)).astype(int)
            # The relaxed law's wrinkled zone (pre-stretched flat radii, mm).
            self.zone_inner_mm = self._column(s, "wrinkled_zone_inner_mm")

            self.onset_found = int(np.asarray(s.attrs.get("onset_found", 0)).ravel()[0]) == 1
            onset_v = s.attrs.get("onset_voltage_kV", None)
            self.onset_voltage_kV = (np.asarray(onset_v, dtype=float).ravel()
                                     if onset_v is not None else None)
            onset_r = s.attrs.get("onset_radius_mm", np.nan)
            self.onset_radius_mm = float(np.asarray(onset_r, dtype=float).ravel()[0])
            onset_t = s.attrs.get("onset_load_factor", np.nan)
            self.onset_load_factor = float(np.asarray(onset_t, dtype=float).ravel()[0])
            if self.onset_voltage_kV is None or len(self.onset_voltage_kV) != self.n_rings:
                self.onset_found = False

            self.step_groups = set(f["steps"].keys()) if "steps" in f else set()

    def _column(self, s, name, fill=np.nan):
        if name in s:
            return np.asarray(s[name][...], dtype=float).reshape(self.n_steps)
        return np.full(self.n_steps, fill, dtype=float)

    @staticmethod
    def group_name(step):
        return f"{step:06d}"

    def has_fields(self, step):
        return self.group_name(step) in self.step_groups

    def fields(self, step):
        """Fields of one step sorted along the meridian (by R), or None."""
        with h5py.File(self.path, "r") as f:
            name = "steps/" + self.group_name(step)
            if name not in f:
                return None
            g = f[name]
            required = ("R", "r", "z", "lambda1", "lambda2", "s1", "s2")
            missing = [k for k in required if k not in g]
            if missing:
                raise RunError(f"{self.path}: /{name} lacks {', '.join(missing)}")
            data = {k: np.asarray(g[k][...], dtype=float) for k in g.keys()
                    if isinstance(g[k], h5py.Dataset) and k != "ring"}
            n = len(data["R"])
            data["ring"] = (np.asarray(g["ring"][...], dtype=int) if "ring" in g
                            else np.zeros(n, dtype=int))
        if n == 0:
            return None
        # Stable sort keeps the two samples of a ring edge in their written order.
        order = np.argsort(data["R"], kind="stable")
        return {k: v[order] for k, v in data.items()}

    # Stage helpers
    def rows(self, stage):
        return np.flatnonzero(self.stage == stage)

    def end_of_load_stage(self):
        """Last row of the dead-load stage (else of the pre-stretch), or None."""
        for stage in (STAGE_LOAD, STAGE_PRESTRETCH):
            rows = self.rows(stage)
            if len(rows):
                return int(rows[-1])
        return None

    def voltage_label(self, step):
        v = self.voltage_kV[step]
        if self.n_rings == 1:
            text = f"Φ = {v[0]:.3g} kV"
        else:
            text = "Φ = " + "/".join(f"{x:.3g}" for x in v) + " kV"
        if self.stage[step] != STAGE_VOLTAGE:
            text += {STAGE_PRESTRETCH: " (pre-stretch)",
                     STAGE_LOAD: " (load)"}.get(int(self.stage[step]), "")
        if self.wrinkled[step]:
            text += ", wrinkled"
        if self.nonphysical[step]:
            text += ", NON-PHYSICAL"
        return text

    def nonphysical_reason(self, step):
        bits = self.nonphysical[step]
        reasons = [text for bit, text in ((1, "r beyond the frame or the axis"),
                                          (2, "the meridian crosses itself or the disk"))
                   if bits & bit]
        return " and ".join(reasons)

    def wrinkled_points(self, step, fields):
        """Samples of a step that have lost tension: s2 < 0 (plain law), or
        s2 = 0 where the relaxed law reports a wrinkled zone; none in the
        pre-stretch stage (it starts from the stress-free film)."""
        if self.stage[step] == STAGE_PRESTRETCH:
            return np.zeros(len(fields["s2"]), dtype=bool)
        mask = fields["s2"] < 0
        if np.isfinite(self.zone_inner_mm[step]):
            mask |= fields["s2"] == 0
        return mask

    def x_axis(self, rows):
        """x values and label of a curve over the voltage stage: the time of
        a time run; else the voltage (one ring); with several rings the outer
        ring's voltage, unless the path holds it while other rings move (then
        the path parameter t)."""
        if np.any(np.isfinite(self.time_s[rows])):
            x = np.nan_to_num(self.time_s[rows], nan=0.0)  # the load stage ends at t = 0
            return x, "time t (s)"
        v = self.voltage_kV[rows]
        if self.n_rings == 1:
            return v[:, 0], "voltage Φ (kV)"
        outer_held = np.any((np.diff(v[:, -1]) == 0) &
                            np.any(np.diff(v[:, :-1], axis=0) != 0, axis=1))
        if not outer_held:
            return v[:, -1], f"voltage of the outer ring (ring {self.n_rings}, kV)"
        x = self.load_factor[rows].copy()
        if self.stage[rows[0]] != STAGE_VOLTAGE and len(rows) > 1:
            x[0] = 0.0  # end of the load stage = start of the voltage path
        return x, "voltage path parameter t (the outer voltage is held on part of the path)"


# ---------------------------------------------------------------- steps

def default_steps(run):
    steps = []
    end_load = run.end_of_load_stage()
    if end_load is not None:
        steps.append(end_load)
    voltage_rows = run.rows(STAGE_VOLTAGE)
    if len(voltage_rows):
        k = min(5, len(voltage_rows))
        # about 5 evenly spread voltage-stage steps, the last one included below
        picks = np.linspace(0, len(voltage_rows) - 1, k + 1)[:-1] if k > 1 else []
        steps.extend(int(voltage_rows[int(round(p))]) for p in picks)
    steps.append(run.n_steps - 1)
    steps = sorted(set(s for s in steps if run.has_fields(s)))
    if not steps:
        steps = [s for s in range(run.n_steps) if run.has_fields(s)][-1:]
    return steps


def parse_steps(spec, run):
    if spec is None:
        return default_steps(run)
    spec = spec.strip()
    if spec == "all":
        steps = list(range(run.n_steps))
    elif spec == "last":
        steps = [run.n_steps - 1]
    else:
        steps = []
        for item in spec.split(","):
            item = item.strip()
            if not item:
                continue
            try:
                step = int(item)
            except ValueError:
                raise RunError(f"--steps: '{item}' is not a step number "
                               "(use all, last or N,N,...)") from None
            if step < 0:
                step += run.n_steps
            if not 0 <= step < run.n_steps:
                raise RunError(f"--steps: step {item} does not exist "
                               f"(the file has steps 0..{run.n_steps - 1})")
            steps.append(step)
        steps = sorted(set(steps))
    missing = [s for s in steps if not run.has_fields(s)]
    if missing:
        sys.stderr.write(f"{PROG}: warning: no /steps group for step(s) "
                         f"{', '.join(map(str, missing))}; skipped\n")
    steps = [s for s in steps if run.has_fields(s)]
    if not steps:
        raise RunError("none of the chosen steps has field data under /steps")
    return steps


# ---------------------------------------------------------------- plots

def ring_segments(fields):
    """(ring, index array) for each maximal run of samples of one ring. When
    a ring edge is not sampled twice (once per ring), a segment starts with
    the last sample of the previous one so that the curve has no gap."""
    ring, R = fields["ring"], fields["R"]
    segments = []
    start = 0
    for k in range(1, len(ring) + 1):
        if k == len(ring) or ring[k] != ring[start]:
            idx = np.arange(start, k)
            if start > 0 and R[start - 1] < R[start]:
                idx = np.concatenate(([start - 1], idx))
            segments.append((int(ring[start]), idx))
            start = k
    return segments


def true_runs(mask):
    """Index arrays of the maximal runs of True in a boolean array."""
    runs, start = [], None
    for k, flag in enumerate(list(mask) + [False]):
        if flag and start is None:
            start = k
        elif not flag and start is not None:
            runs.append(np.arange(start, k))
            start = None
    return runs


def shade_wrinkled(ax, x, y, mask, label):
    """A wide translucent red band under the wrinkled part of a curve.
    Returns the label if it was used (so that it appears once)."""
    for idx in true_runs(mask):
        if len(idx) == 1:
            ax.plot(x[idx], y[idx], "o", color="tab:red", ms=9, alpha=0.35, zorder=1,
                    label=label)
        else:
            ax.plot(x[idx], y[idx], color="tab:red", lw=9, alpha=0.3, zorder=1,
                    solid_capstyle="round", label=label)
        label = None
    return label


def downward_sign(run, loaded):
    """+1 if the solver's z grows downward (the loaded disk lies at larger z
    than the frame), else -1: the disk always sags under its dead load."""
    for fields in reversed(loaded):
        dz = fields["z"][0] - fields["z"][-1]
        if abs(dz) > 1e-12:
            return 1.0 if dz > 0 else -1.0
    return -1.0


def step_shades(n):
    return np.linspace(0.45, 1.0, n) if n > 1 else np.array([0.85])


def plot_profiles(run, steps, all_fields, out):
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    sign = downward_sign(run, [all_fields[s] for s in steps])
    shades = step_shades(len(steps))
    handles, labels = [], []
    disk_r, disk_depths = 0.0, []
    wrinkle_label, wrinkle_handle = "wrinkled (lost tension)", None
    depth_range = [0.0, 0.0]
    for shade, step in zip(shades, steps):
        f = all_fields[step]
        depth = sign * (f["z"] - f["z"][-1])  # below the frame plane, mm
        depth_range = [min(depth_range[0], depth.min()), max(depth_range[1], depth.max())]
        wrinkled = run.wrinkled_points(step, f)
        if wrinkled.any() and wrinkle_handle is None:
            shade_wrinkled(ax, f["r"], depth, wrinkled, wrinkle_label)
            wrinkle_handle = ax.lines[-1]
        elif wrinkled.any():
            shade_wrinkled(ax, f["r"], depth, wrinkled, None)
        step_handles = {}
        style = "--" if run.nonphysical[step] else "-"
        for ring, idx in ring_segments(f):
            cmap = plt.get_cmap(RING_COLORMAPS[ring % len(RING_COLORMAPS)])
            (line,) = ax.plot(f["r"][idx], depth[idx], color=cmap(shade), lw=1.6, ls=style)
            step_handles.setdefault(ring, line)
        disk_r = max(disk_r, f["r"][0])
        disk_depths.append(depth[0])
        ax.plot([0.0, f["r"][0]], [depth[0], depth[0]], color="black", lw=4,
                solid_capstyle="butt", zorder=5)
        handles.append(tuple(step_handles[k] for k in sorted(step_handles)))
        labels.append(f"{run.voltage_label(step)} (step {step})")
    frame_r = max(all_fields[s]["r"][-1] for s in steps)
    r_max = max(np.max(all_fields[s]["r"]) for s in steps)
    ax.plot([frame_r, frame_r * 1.04], [0, 0], color="dimgray", lw=4,
            solid_capstyle="butt")
    ax.axhline(0.0, color="gray", lw=0.6, ls=":")
    # Equal scales: the cone's true shape. Nothing is cut off, also not a
    # non-physical state reaching beyond the frame.
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(0.0, max(frame_r * 1.05, r_max * 1.02))
    margin = 0.05 * (depth_range[1] - depth_range[0] + 1.0)
    ax.set_ylim(depth_range[1] + margin, depth_range[0] - margin)  # positive down
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("z below the frame plane (mm, positive down)")
    notes = "black: rigid disk; one colour per electrode ring, darker = later"
    if any(run.nonphysical[s] for s in steps):
        notes += "\ndashed: non-physical state (" + "; ".join(
            sorted({run.nonphysical_reason(s) for s in steps if run.nonphysical[s]})) + ")"
    ax.set_title(f"Deformed meridians: {os.path.basename(run.path)}\n({notes})", fontsize=10)
    if wrinkle_handle is not None:
        handles.append(wrinkle_handle)
        labels.append(wrinkle_label)
    ax.legend(handles, labels, handler_map={tuple: HandlerTuple(ndivide=None)},
              fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2,
              frameon=False)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def onset_path_parameter(run, rows):
    """Path parameter t at the onset voltages and the distance (kV) of those
    voltages from the path: projection onto the polyline of ring voltages over
    the voltage-stage rows (the onset record holds no t)."""
    v = run.voltage_kV[rows]
    t = run.load_factor[rows]
    target = run.onset_voltage_kV
    if len(rows) == 1:
        return t[0], float(np.linalg.norm(v[0] - target))
    best, best_t = np.inf, None
    for k in range(len(rows) - 1):
        d = v[k + 1] - v[k]
        dd = float(d @ d)
        w = 0.0 if dd == 0 else float(np.clip((target - v[k]) @ d / dd, 0.0, 1.0))
        dist = float(np.linalg.norm(v[k] + w * d - target))
        if dist < best:
            best, best_t = dist, t[k] + w * (t[k + 1] - t[k])
    return best_t, best


def plot_displacement(run, out):
    rows = run.rows(STAGE_VOLTAGE)
    title_note = ""
    if len(rows) == 0:
        rows = np.arange(run.n_steps)
        title_note = " (no voltage stage: all steps)"
    else:
        end_load = run.end_of_load_stage()
        if end_load is not None and np.all(run.voltage_kV[end_load] == 0.0):
            rows = np.concatenate(([end_load], rows))  # the zero-voltage state
    single = run.n_rings == 1
    x, xlabel = run.x_axis(rows)
    # Over the path parameter or the time the onset is at its load factor
    # (a time run's load factor is its time).
    on_path_parameter = xlabel.startswith(("voltage path parameter", "time"))

    fig, ax = plt.subplots(figsize=(7.5, 5.6))
    ax.plot(x, run.displacement_mm[rows], "o-", ms=3, color="tab:blue",
            label="displacement")
    if np.any(np.isfinite(run.stroke_mm[rows])):
        ax.plot(x, run.stroke_mm[rows], "s--", ms=3, color="tab:green", label="stroke")
    bad = run.nonphysical[rows] != 0
    if np.any(bad):
        reasons = "; ".join(sorted({run.nonphysical_reason(r) for r in rows[bad]}))
        ax.plot(x[bad], run.displacement_mm[rows][bad], "x", ms=7, mew=1.5, color="black",
                label=f"non-physical state ({reasons})")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("displacement, stroke (mm)")

    # Wrinkled steps: shade the half-way intervals around each one.
    wrinkled = run.wrinkled[rows] != 0
    if np.any(wrinkled):
        order = np.argsort(x, kind="stable")
        xs = x[order]
        mid = np.concatenate(([xs[0]], 0.5 * (xs[1:] + xs[:-1]), [xs[-1]]))
        first = True
        for k, j in enumerate(order):
            if wrinkled[j]:
                ax.axvspan(mid[k], mid[k + 1], color="tab:red", alpha=0.15, lw=0,
                           label="wrinkled (s2 < 0)" if first else None)
                first = False

    if run.onset_found:
        off_path = ""
        if not on_path_parameter:
            x_onset = run.onset_voltage_kV[-1]
        elif np.isfinite(run.onset_load_factor):
            x_onset = run.onset_load_factor  # written by the solver: exact
        else:
            vrows = run.rows(STAGE_VOLTAGE)
            x_onset, distance = (onset_path_parameter(run, vrows) if len(vrows)
                                 else (None, 0.0))
            scale = max(1e-12, float(np.nanmax(np.abs(run.voltage_kV))))
            if distance > 1e-3 * scale:
                off_path = " (off the path: nearest point)"

        if x_onset is not None and np.isfinite(x_onset):
            volts = "/".join(f"{v:.4g}" for v in run.onset_voltage_kV)
            radius = (f", r = {run.onset_radius_mm:.3g} mm"
                      if np.isfinite(run.onset_radius_mm) else "")
            ax.axvline(x_onset, color="tab:red", ls="-.", lw=1.3,
                       label=f"loss of tension: {volts} kV{radius}{off_path}")

    if not single:
        ax2 = ax.twinx()
        styles = ["-", "--", ":", "-."]
        shown = range(run.n_rings) if on_path_parameter else range(run.n_rings - 1)
        for ring in shown:
            ax2.plot(x, run.voltage_kV[rows, ring], color="gray", lw=1.0,
                     ls=styles[ring % len(styles)], label=f"ring {ring + 1} voltage")
        ax2.set_ylabel("ring voltage (kV)", color="dimgray")
        ax2.tick_params(axis="y", colors="dimgray")
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = ax2.get_legend_handles_labels()
        handles, labels = h1 + h2, l1 + l2
    else:
        handles, labels = ax.get_legend_handles_labels()
    # Below the axes: inside, it would hide the curves of some run or other.
    ax.legend(handles, labels, fontsize=8, loc="upper center", ncol=3,
              bbox_to_anchor=(0.5, -0.13), frameon=False)
    mass = run.mass_g[rows[-1]]
    mass_text = f", m = {mass:.4g} g" if np.isfinite(mass) else ""
    ax.set_title(f"Displacement over the voltage stage{title_note}: "
                 f"{os.path.basename(run.path)}{mass_text}", fontsize=10)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def plot_distributions(run, steps, all_fields, out):
    mu = run.mu_kPa
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharex=True)
    panels = [("lambda1", r"$\lambda_1$ (meridian)", 1.0),
              ("lambda2", r"$\lambda_2$ (hoop)", 1.0),
              ("s1", r"$s_1/\mu$" if mu else r"$s_1$ (kPa)", 1.0 / mu if mu else 1.0),
              ("s2", r"$s_2/\mu$" if mu else r"$s_2$ (kPa)", 1.0 / mu if mu else 1.0)]
    colors = plt.get_cmap("viridis")(np.linspace(0.0, 0.9, len(steps)))
    for ax, (key, ylabel, factor) in zip(axes.flat, panels):
        wrinkle_label = "wrinkled (lost tension)"
        for color, step in zip(colors, steps):
            f = all_fields[step]
            a = f["r"][0]
            label = f"{run.voltage_label(step)} (step {step})"
            wrinkled = run.wrinkled_points(step, f)
            for ring, idx in ring_segments(f):
                ax.plot(f["r"][idx] / a, f[key][idx] * factor, color=color, lw=1.4,
                        label=label, ls="--" if run.nonphysical[step] else "-")
                label = None
                if wrinkled[idx].any():
                    wrinkle_label = shade_wrinkled(ax, f["r"][idx] / a, f[key][idx] * factor,
                                                   wrinkled[idx], wrinkle_label)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        if key == "s2":
            ax.axhline(0.0, color="black", lw=0.9)
    for ax in axes[1]:
        ax.set_xlabel("r / a")
    axes[0, 0].legend(fontsize=7, loc="best")
    mu_text = f"μ = {mu:g} kPa" if mu else "μ not found in the parameters: stresses in kPa"
    fig.suptitle(f"Stretch and nominal stress along the meridian: "
                 f"{os.path.basename(run.path)} ({mu_text})", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


# ---------------------------------------------------------------- main

def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Plots (PNG) of one cdea run from its HDF5 results file.")
    parser.add_argument("results", help="the .h5 file written by cdea")
    parser.add_argument("--out", default=None,
                        help="output directory (default: next to the .h5 file)")
    parser.add_argument("--steps", default=None,
                        help="steps for the profile and distribution plots: all, last "
                             "or a comma-separated list of step numbers (negative "
                             "counts from the end); default: end of the load stage, "
                             "about 5 voltage-stage steps and the last")
    args = parser.parse_args(argv)

    try:
        run = Run(args.results)
        steps = parse_steps(args.steps, run)
        out_dir = args.out if args.out else (os.path.dirname(os.path.abspath(args.results)))
        os.makedirs(out_dir, exist_ok=True)
        base = os.path.splitext(os.path.basename(args.results))[0]
        all_fields = {s: run.fields(s) for s in steps}
        steps = [s for s in steps if all_fields[s] is not None]
        if not steps:
            raise RunError("the chosen steps hold no samples")
        written = []
        target = os.path.join(out_dir, f"{base}_profiles.png")
        plot_profiles(run, steps, all_fields, target)
        written.append(target)
        target = os.path.join(out_dir, f"{base}_displacement.png")
        plot_displacement(run, target)
        written.append(target)
        target = os.path.join(out_dir, f"{base}_distributions.png")
        plot_distributions(run, steps, all_fields, target)
        written.append(target)
    except RunError as e:
        fail(str(e))
    except OSError as e:
        fail(str(e))
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
