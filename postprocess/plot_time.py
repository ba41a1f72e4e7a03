#!/usr/bin/python3
"""Time-dependent cdea runs (Time/Enabled = true; doc/time.md): displacement,
ring voltages and the pump's level drop against time, the holds of a
staircase and the level between the states of a square wave.

Usage:
  plot_time.py RESULTS.h5 [MORE.h5 ...] [--out DIR] [--elastic QUASI.h5] [--labels A,B,...]
               [--from T] [--to T] [--min-hold S] [--levels L1,L2,...]
  plot_time.py --response OUT.png RUN.h5 [RUN.h5 ...] [--labels A,B,...]

First form: writes <base>_time.png into DIR (default: the directory of the
first file), <base> being the first file's name without its extension: one
panel each for the displacement, the ring voltages and the level drop against
time, one line per file (between --from and --to seconds). It prints, for
every file,
  - each hold of the voltages (a plateau of at least --min-hold s, default 1): voltages,
    the mean displacement over its first and over its last second (which
    averages out most of the disk's ringing), the creep between them and, with
    --elastic, the quasi-static displacement at the same voltages and what is
    still to creep at the end of the hold, and the disk's ringing: its
    amplitude about the creep over the last second and its decay rate;
  - for a square waveform, each cycle's level drop at the end of its on half
    (state B) and of its off half (state A), each averaged over the last tenth
    of the period, and their difference, and the frequency and amplitude of
    the displacement's oscillation in each half (the disk's ringing); the
    differences against the cycle go to <base>_cycles.png, with the
    quasi-static levels --levels as lines.
With --elastic (a quasi-static run of the same scene) it also writes
<base>_holds.png: the displacement over the last second of every hold against
the last ring's voltage, over the quasi-static curve, and below it what is
still to creep.

Second form (--response): the stroke amplitude (half the peak-to-peak
displacement over the last cycle) of each run against its drive frequency
(Time/Frequency (Hz) of the file's parameters), one curve per label (default:
one per value of Time/Inertia and Material/Relaxation time (s)).

Needs h5py, numpy and matplotlib (Agg backend).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from plot_pump import prm_value  # noqa: E402  (the stored parameters name each entry once)

try:
    import h5py  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("plot_time.py: error: the python module h5py is missing "
             "(Debian: apt-get install python3-h5py)")

PROG = "plot_time.py"


class TimeError(Exception):
    """A problem with the input that ends the program with a message."""


class TimeRun:
    """The time rows of one results file."""

    def __init__(self, path):
        if not os.path.isfile(path):
            raise TimeError(f"no such file: {path}")
        try:
            handle = h5py.File(path, "r")
        except OSError as e:
            raise TimeError(f"cannot open {path} as an HDF5 file: {e}") from None
        with handle as f:
            if "summary" not in f:
                raise TimeError(f"{path} has no /summary group: not a cdea results file")
            s = f["summary"]
            if "time_s" not in s:
                raise TimeError(f"{path}: /summary/time_s is missing: not a time-dependent run "
                                "(Time/Enabled = true)")
            time = np.asarray(s["time_s"][...], dtype=float)
            rows = np.isfinite(time)
            n = len(time)
            self.path = path
            self.t = time[rows]
            self.disp = np.asarray(s["displacement_mm"][...], dtype=float)[rows]
            self.stroke = np.asarray(s["stroke_mm"][...], dtype=float)[rows]
            self.volts = np.asarray(s["voltage_kV"][...], dtype=float).reshape(n, -1)[rows]
            self.level = (np.asarray(s["level_drop_mm"][...], dtype=float)[rows]
                          if "level_drop_mm" in s else np.full(rows.sum(), np.nan))
            text = f.attrs.get("parameters", "")
            self.prm = text.decode() if isinstance(text, bytes) else str(text)
        self.name = os.path.splitext(os.path.basename(path))[0]
        self.waveform = prm_value(self.prm, "Waveform") or "?"
        freq = prm_value(self.prm, "Frequency (Hz)")
        self.frequency = float(freq) if freq else float("nan")

    def holds(self, min_length=1.0):
        """(start, end) row indices of voltage plateaus lasting at least min_length s."""
        result, start = [], 0
        for i in range(1, len(self.t) + 1):
            if i == len(self.t) or np.abs(self.volts[i] - self.volts[start]).max() > 1e-9:
                if self.t[i - 1] - self.t[start] >= min_length and self.volts[start].max() > 0:
                    result.append((start, i - 1))
                start = i
        return result

    def cycles(self):
        """(k, level B, level A, displacement B, displacement A) per cycle of a
        square wave: state B is the end of the on half, A the end of the off
        half, each the mean in time over the last tenth of the period (which
        averages the disk's ringing out)."""
        if self.waveform != "square" or not np.isfinite(self.frequency):
            return []
        period = 1.0 / self.frequency
        rows = []
        for k in range(int(round(self.t[-1] / period + 1e-9))):
            ends = ((k + 0.5) * period, (k + 1.0) * period)
            values = []
            for end in ends:
                values.append((window_mean(self.t, self.level, end - 0.1 * period, end),
                               window_mean(self.t, self.disp, end - 0.1 * period, end)))
            rows.append((k + 1, values[0][0], values[1][0], values[0][1], values[1][1]))
        return rows

    def ringing(self, start, end):
        """Frequency (from the zero crossings about the mean) and half the
        peak-to-peak amplitude of the displacement on [start, end]."""
        window = (self.t > start) & (self.t <= end)
        t, x = self.t[window], self.disp[window] - self.disp[window].mean()
        cross = np.where(np.diff(np.sign(x)) != 0)[0]
        if len(cross) < 3:
            return float("nan"), 0.5 * np.ptp(self.disp[window])
        tc = t[cross] - x[cross] * (t[cross + 1] - t[cross]) / (x[cross + 1] - x[cross])
        return (len(tc) - 1) / (2 * (tc[-1] - tc[0])), 0.5 * np.ptp(self.disp[window])

    def hold_ringing(self, i, j):
        """The disk's ringing in the hold of rows i..j: half the peak-to-peak
        displacement about a straight line (which takes out the creep) over
        the hold's last second, and the exponential decay rate (1/s) of that
        amplitude fitted over the 1 s windows of the hold's second half (NaN
        if the hold is shorter than 4 s or does not ring)."""
        def amplitude(start, end):
            window = (self.t >= start) & (self.t <= end)
            if window.sum() < 3:
                return float("nan")
            t, x = self.t[window], self.disp[window]
            return 0.5 * np.ptp(x - np.polyval(np.polyfit(t, x, 1), t))
        t0, t1 = self.t[i], self.t[j]
        last = amplitude(t1 - 1.0, t1)
        starts = np.arange(0.5 * (t0 + t1), t1 - 1.0 + 1e-9, 1.0)
        if t1 - t0 < 4.0 or len(starts) < 2:
            return last, float("nan")
        amps = np.array([amplitude(a, a + 1.0) for a in starts])
        if not np.all(amps > 0):
            return last, float("nan")
        return last, -np.polyfit(starts, np.log(amps), 1)[0]

    def amplitude(self):
        """Half the peak-to-peak displacement over the last drive period."""
        period = 1.0 / self.frequency
        last = self.t >= self.t[-1] - period * (1 - 1e-9)
        return 0.5 * (self.disp[last].max() - self.disp[last].min())


def time_mean(t, x):
    """Mean of x over [t[0], t[-1]] by the trapezoidal rule: a plain mean of
    the rows would weigh the window's ends by the time step, an error of first
    order in the step where the disk rings."""
    if len(t) < 2:
        return float(np.mean(x))
    return float(np.sum(0.5 * (x[1:] + x[:-1]) * np.diff(t)) / (t[-1] - t[0]))


def window_mean(t, x, a, b):
    """Mean of the piecewise-linear x(t) over [a, b], x interpolated at a and
    b: error-controlled steps do not land on the window's ends (the first
    row inside can lie a step after a, a bias of the ringing's amplitude
    times the step over the window)."""
    inside = (t > a) & (t < b)
    tt = np.concatenate(([a], t[inside], [b]))
    xx = np.concatenate(([np.interp(a, t, x)], x[inside], [np.interp(b, t, x)]))
    return time_mean(tt, xx)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    print(f"wrote {path}")


def plot_time(runs, path, labels, t_from, t_to):
    """Displacement, voltages and level drop against time, one line per run, to @p path."""
    fig, axes = plt.subplots(3, 1, figsize=(7.5, 7.5), sharex=True)
    for run, label in zip(runs, labels):
        keep = (run.t >= t_from) & (run.t <= t_to)
        axes[0].plot(run.t[keep], run.disp[keep], lw=0.9, label=label)
        # The voltages once per distinct waveform.
        if not any(len(other.t) == len(run.t) and np.array_equal(other.volts, run.volts)
                   for other in runs[:runs.index(run)]):
            for k in range(run.volts.shape[1]):
                axes[1].plot(run.t[keep], run.volts[keep, k], lw=0.9,
                             label=f"{label}, ring {k + 1}" if run.volts.shape[1] > 1 else label)
        axes[2].plot(run.t[keep], run.level[keep], lw=0.9, label=label)
    axes[0].set_ylabel("displacement (mm)")
    axes[1].set_ylabel("voltage (kV)")
    axes[2].set_ylabel("level drop (mm)")
    axes[2].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[1].legend(fontsize=7, ncol=2)
    save(fig, path)


def plot_cycles(runs, labels, out_dir, levels):
    square = [(r, l) for r, l in zip(runs, labels) if r.cycles()]
    if not square:
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for run, label in square:
        c = np.array(run.cycles())
        ax.plot(c[:, 0], c[:, 1] - c[:, 2], "o-", ms=3, lw=0.8, label=label)
    for k, value in enumerate(levels):
        ax.axhline(value, color="k", ls="--", lw=0.8,
                   label="quasi-static" if k == 0 else None)
    ax.set_xlabel("cycle")
    ax.set_ylabel("level drop between states A and B (mm)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.join(out_dir, runs[0].name + "_cycles.png"))


def quasi_static_curve(path):
    with h5py.File(path, "r") as f:
        s = f["summary"]
        stage = np.asarray(s["stage"][...], dtype=int)
        n = len(stage)
        volts = np.asarray(s["voltage_kV"][...], dtype=float).reshape(n, -1)
        disp = np.asarray(s["displacement_mm"][...], dtype=float)
        factor = np.asarray(s["load_factor"][...], dtype=float)
        keep = (stage == 2) | ((stage == 1) & (factor == 1.0))
        if "time_s" in s:
            keep &= ~np.isfinite(np.asarray(s["time_s"][...], dtype=float))
    return volts[keep], disp[keep]


def plot_holds(runs, labels, elastic, out_dir, min_hold):
    curve = quasi_static_curve(elastic)
    fig, axes = plt.subplots(2, 1, figsize=(6.5, 6.5), sharex=True)
    axes[0].plot(curve[0][:, -1], curve[1], "k-", lw=1.2, label="quasi-static (elastic)")
    for run, label in zip(runs, labels):
        ends = [e for _, e in run.holds(min_hold)]
        last = [run.disp[(run.t >= run.t[e] - 1.0) & (run.t <= run.t[e])].mean() for e in ends]
        qs = [quasi_static_at(curve, run.volts[e]) for e in ends]
        axes[0].plot(run.volts[ends, -1], last, "o", ms=4, label=f"{label}: end of each hold")
        axes[1].plot(run.volts[ends, -1], np.array(qs) - np.array(last), "o-", ms=4, label=label)
    axes[0].set_ylabel("displacement (mm)")
    axes[1].set_ylabel("still to creep (mm)")
    axes[1].set_xlabel("voltage of the last ring (kV)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, os.path.join(out_dir, runs[0].name + "_holds.png"))


def quasi_static_at(curve, volts):
    """Displacement of the quasi-static curve at these voltages, interpolated in
    the last ring's voltage among its rows with the other rings' voltages (NaN
    if there are none)."""
    if curve is None:
        return float("nan")
    cv, cd = curve
    same = np.abs(cv[:, :-1] - volts[:-1]).max(axis=1, initial=0.0) < 1e-6
    x, y = cv[same, -1], cd[same]
    order = np.argsort(x)
    x, y = x[order], y[order]
    if len(x) == 0 or volts[-1] < x[0] - 1e-9 or volts[-1] > x[-1] + 1e-9:
        return float("nan")
    return float(np.interp(volts[-1], x, y))


def report(run, min_hold, curve):
    print(f"{run.path}: {run.waveform} waveform, {len(run.t)} time rows to t = {run.t[-1]:g} s")
    holds = run.holds(min_hold)
    if holds:
        print("  hold  voltages (kV)     end (s)  first 1 s (mm)  last 1 s (mm)  creep (mm)"
              "  quasi-static (mm)  still to creep (mm)  ringing last 1 s (mm)  decay (1/s)")
        for k, (i, j) in enumerate(holds):
            v = ", ".join(f"{x:.2f}" for x in run.volts[i])
            early = run.disp[i:j + 1][run.t[i:j + 1] <= run.t[i] + 1.0].mean()
            late = run.disp[i:j + 1][run.t[i:j + 1] >= run.t[j] - 1.0].mean()
            qs = quasi_static_at(curve, run.volts[j])
            ring, decay = run.hold_ringing(i, j)
            print(f"  {k + 1:4d}  {v:16s} {run.t[j]:8.2f} {early:15.5f} {late:14.5f}"
                  f" {late - early:11.5f} {qs:18.5f} {qs - late:20.5f} {ring:22.6f} {decay:12.4f}")
    cycles = run.cycles()
    if cycles:
        # Ringing: the displacement over each half after its edge (+10 % of
        # the half period).
        half = 0.5 / run.frequency
        print("  cycle  level B (mm)  level A (mm)  B - A (mm)  disp B (mm)  disp A (mm)"
              "  ringing on: Hz, mm  off: Hz, mm")
        for k, b, a, db, da in cycles:
            t0 = 2 * (k - 1) * half
            f_on, a_on = run.ringing(t0 + 0.1 * half, t0 + half)
            f_off, a_off = run.ringing(t0 + 1.1 * half, t0 + 2 * half)
            print(f"  {k:5d} {b:13.3f} {a:13.3f} {b - a:11.3f} {db:12.4f} {da:12.4f}"
                  f" {f_on:10.3f} {a_on:7.3f} {f_off:8.3f} {a_off:7.3f}")


def response(out, runs, labels):
    groups = {}
    for run, label in zip(runs, labels):
        if not np.isfinite(run.frequency):
            raise TimeError(f"{run.path}: no Time/Frequency (Hz) in its parameters")
        groups.setdefault(label, []).append((run.frequency, run.amplitude()))
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    print("label, frequency (Hz), stroke amplitude (mm)")
    for label, points in groups.items():
        points.sort()
        f = np.array([p[0] for p in points])
        a = np.array([p[1] for p in points])
        ax.semilogx(f, a, "o-", ms=4, label=label)
        for x, y in points:
            print(f"{label}, {x:g}, {y:.5f}")
    ax.set_xlabel("drive frequency (Hz)")
    ax.set_ylabel("stroke amplitude (mm)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save(fig, out)


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--out")
    parser.add_argument("--elastic")
    parser.add_argument("--labels")
    parser.add_argument("--response")
    parser.add_argument("--from", dest="t_from", type=float, default=-np.inf)
    parser.add_argument("--to", dest="t_to", type=float, default=np.inf)
    parser.add_argument("--min-hold", dest="min_hold", type=float, default=1.0)
    parser.add_argument("--levels", default="")
    args = parser.parse_args(argv)
    try:
        runs = [TimeRun(p) for p in args.files]
        if args.labels:
            labels = [x.strip() for x in args.labels.split(",")]
            if len(labels) != len(runs):
                raise TimeError(f"--labels has {len(labels)} names for {len(runs)} files")
        elif args.response:
            labels = [f"inertia {prm_value(r.prm, 'Inertia')}, tau = "
                      f"{prm_value(r.prm, 'Relaxation time (s)')} s" for r in runs]
        else:
            labels = [r.name for r in runs]
        if args.response:
            response(args.response, runs, labels)
            return 0
        out_dir = args.out or os.path.dirname(os.path.abspath(args.files[0]))
        os.makedirs(out_dir, exist_ok=True)
        curve = quasi_static_curve(args.elastic) if args.elastic else None
        for run in runs:
            report(run, args.min_hold, curve)
        plot_time(runs, os.path.join(out_dir, runs[0].name + "_time.png"), labels, args.t_from,
                  args.t_to)
        levels = [float(x) for x in args.levels.split(",") if x.strip()]
        plot_cycles(runs, labels, out_dir, levels)
        if args.elastic:
            plot_holds(runs, labels, args.elastic, out_dir, args.min_hold)
    except TimeError as e:
        print(f"{PROG}: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
