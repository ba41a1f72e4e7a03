# %% [markdown]
# # The weight on the disk, swept in-process
#
# A notebook-style example of the Python module (doc/python.md): the default
# actuator (full electrode, 0 to 5 kV) for a range of masses on the disk, one
# `cdea.run` per mass in this process, nothing written but the figure. The
# cells (`# %%`) run one by one in Jupyter or VS Code, or all at once:
#
#     PYTHONPATH=build/python /usr/bin/python3 postprocess/sweep_mass.py \
#         [--out FILE.png] [--masses 100,200,300] [--prm FILE.prm]
#
# In Jupyter, start the kernel in the repository or in postprocess/, or set
# CDEA_SOURCE_DIR to the repository's folder (where prm/ and build/ are).
#
# Left: the stroke against the voltage for each mass, the wrinkling onset
# marked. Right: what the mass does at the end of the path: the disk's
# deflection before any voltage, the stroke at 5 kV and the smallest hoop
# stress there (wrinkling when it reaches zero).

# %%
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402



def source_dir():
    """The repository (its prm/ and build/python/): $CDEA_SOURCE_DIR if set, else
    the folder above this script; a cell run in Jupyter (or by exec) has no
    __file__, so then the working directory or the one above it (a notebook
    opened in postprocess/), whichever holds prm/default.prm."""
    if os.environ.get("CDEA_SOURCE_DIR"):
        return os.path.abspath(os.environ["CDEA_SOURCE_DIR"])
    if "__file__" in globals():
        return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    for folder in (os.getcwd(), os.path.dirname(os.getcwd())):
        if os.path.isfile(os.path.join(folder, "prm", "default.prm")):
            return folder
    sys.exit("sweep_mass.py: cannot find the repository (prm/default.prm) from the working "
             "directory %s: set CDEA_SOURCE_DIR to the repository's folder" % os.getcwd())


REPO = source_dir()
try:
    import cdea
except ImportError:  # not on PYTHONPATH: the module of this checkout's build
    sys.path.insert(0, os.path.join(REPO, "build", "python"))
    import cdea

parser = argparse.ArgumentParser(description="Sweep the mass on the disk with cdea.run.")
parser.add_argument("--out", default=os.path.join("results", "sweep_mass.png"),
                    help="the figure (PNG); default results/sweep_mass.png")
parser.add_argument("--masses", default="50, 100, 150, 200, 250, 280, 300, 350, 400",
                    help="masses on the disk in g, separated by ','")
parser.add_argument("--prm", default=os.path.join(REPO, "prm", "default.prm"),
                    help="the parameter file the masses replace the mass of")
args, _ = parser.parse_known_args()  # tolerates a notebook kernel's own arguments
masses = [float(m) for m in args.masses.split(",")]

# %% [markdown]
# One run per mass: the parameter file with `Loading/Mass (g)` overridden.
# Each result holds every step's /summary row and fields in memory.

# %%
results = [cdea.run(args.prm, overrides={"Loading/Mass (g)": m}) for m in masses]
stopped = [(m, r.message) for m, r in zip(masses, results) if not r.completed]
for m, message in stopped:
    print("mass %g g: the run stopped early: %s" % (m, message))

# %% [markdown]
# The quantities per mass, from the summaries: the deflection at the end of
# the dead-load stage (stage 1, zero voltage), and stroke, voltage and s2 at
# the last step.

# %%
rows = []
print("%8s %16s %14s %12s %14s %s" % ("mass (g)", "deflection (mm)", "voltage (kV)",
                                      "stroke (mm)", "min s2 (kPa)", "onset"))
for m, r in zip(masses, results):
    s = r.summary
    deflection = s["displacement_mm"][s["stage"] == 1][-1]
    rows.append((m, deflection, s["voltage_kV"][-1, 0], s["stroke_mm"][-1], s["s2_min_kPa"][-1]))
    onset = "%.4f kV" % r.onset["voltage_kV"][0] if r.onset else "none"
    print("%8g %16.6f %14.4f %12.6f %14.6f %s" % (m, deflection, rows[-1][2], rows[-1][3],
                                                   rows[-1][4], onset))
rows = np.array(rows)

# %% [markdown]
# The figure.

# %%
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
colours = plt.cm.viridis(np.linspace(0, 0.9, len(masses)))
for m, r, c in zip(masses, results, colours):
    s = r.summary
    on_path = s["stage"] == 2
    voltage, stroke = s["voltage_kV"][on_path, 0], s["stroke_mm"][on_path]
    left.plot(voltage, stroke, color=c, label="%g g" % m)
    if r.onset:  # where the hoop stress first reaches zero (wrinkling)
        v = r.onset["voltage_kV"][0]
        left.plot(v, np.interp(v, voltage, stroke), "x", color="tab:red", ms=8, mew=2)
left.set_xlabel("voltage (kV)")
left.set_ylabel("stroke (mm)")
left.set_title("stroke against voltage (x: wrinkling onset)")
left.legend(fontsize=8)
left.grid(alpha=0.3)

right.plot(rows[:, 0], rows[:, 1], "o-", label="deflection at 0 kV (mm)")
right.plot(rows[:, 0], rows[:, 3], "s-", label="stroke at %.3g kV (mm)" % rows[0, 2])
right.set_xlabel("mass on the disk (g)")
right.set_ylabel("mm")
second = right.twinx()
second.plot(rows[:, 0], rows[:, 4], "^--", color="tab:red",
            label="min s2 at %.3g kV (kPa)" % rows[0, 2])
second.axhline(0, color="tab:red", lw=0.5)
second.set_ylabel("smallest hoop stress s2 (kPa)", color="tab:red")
lines = right.get_legend_handles_labels()
more = second.get_legend_handles_labels()
# Below the axes: inside, the legend would hide the first masses' points.
right.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper center",
             bbox_to_anchor=(0.5, -0.16), ncol=3)
right.set_title("what the mass does")
right.grid(alpha=0.3)
fig.tight_layout()

folder = os.path.dirname(args.out)
if folder:
    os.makedirs(folder, exist_ok=True)
fig.savefig(args.out, dpi=120)
print("wrote", args.out)
