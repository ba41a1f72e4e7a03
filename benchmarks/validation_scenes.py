#!/usr/bin/python3
"""The twelve scenes of tests/test_validation_agreement.cc as parameter files,
and the comparison of two sets of `cdea run` results on them.

Usage:
  validation_scenes.py write PRM_DIR RESULTS_DIR
      writes PRM_DIR/<scene>.prm (default discretization and solver settings)
      whose results go to RESULTS_DIR/<scene>.h5
  validation_scenes.py compare OLD_DIR NEW_DIR
      for every /summary column: the largest difference between the two
      results of a scene over all its rows (relative to the column's largest
      magnitude in the old file) and at the last row (relative to the old
      value), the largest over the scenes; exit 1 if a scene is missing or
      the rows differ in number.

Used by benchmarks/compare_revisions.sh. Needs h5py and numpy.
"""

import os
import sys

# The paper's actuator (radii in mm, mass in g; material None: mu 25.1 kPa,
# Jlim 270, eps 3.98e-11 F/m, H 1 mm), and per scene: name, what differs from
# it, ring edges (r/a), voltage path (kV).
PAPER = dict(disk=14, frame=42, prestretch=2.5, material=None, mass=280)
SCENES = [
    ("public-full-0V", {}, "1, 3", "0"),
    ("public-full-5kV", {}, "1, 3", "5"),
    ("public-rv1.7-5-6kV", {}, "1, 1.7, 3", "5, 5; 5, 6"),
    ("geometry", dict(disk=10, frame=40, prestretch=3), "1, 4", "4.5"),
    ("material", dict(material=(50, 60, 4.5e-11, 0.5)), "1, 3", "2.8"),
    ("mass-100g", dict(mass=100), "1, 1.5, 3", "4, 4; 4, 5.5"),
    ("mass-500g", dict(mass=500), "1, 3", "6"),
    ("three-rings", {}, "1, 1.5, 2.2, 3", "4, 4, 4; 4, 5, 6"),
    ("three-rings-onset", {}, "1, 1.4, 2, 3", "4.5, 4.5, 4.5; 4.5, 5.5, 7"),
    ("four-rings", dict(prestretch=2), "1, 1.3, 1.8, 2.4, 3", "3, 3, 3, 3; 3, 3.5, 4, 4.5"),
    ("paper-full-5.5kV", {}, "1, 3", "5.5"),
    ("paper-rv1.7-5-7kV", {}, "1, 1.7, 3", "5, 5; 5, 7"),
]


def prm_text(name, changes, edges, path, results_dir):
    s = dict(PAPER, **changes)
    mu, jlim, eps, thickness = s["material"] or (25.1, 270, 3.98e-11, 1)
    return f"""# Validation scene '{name}' (tests/test_validation_agreement.cc)
subsection Geometry
  set Disk radius (mm)    = {s['disk']}
  set Frame radius (mm)   = {s['frame']}
  set Film thickness (mm) = {thickness}
  set Prestretch          = {s['prestretch']}
end
subsection Material
  set Shear modulus (kPa) = {mu}
  set Jlim                = {jlim}
  set Permittivity (F/m)  = {eps}
end
subsection Loading
  set Mass (g)            = {s['mass']}
end
subsection Electrodes
  set Ring edges (r/a)    = {edges}
  set Voltage path (kV)   = {path}
end
subsection Output
  set Directory           = {results_dir}
  set Base name           = {name}
end
"""


def write(prm_dir, results_dir):
    os.makedirs(prm_dir, exist_ok=True)
    for name, changes, edges, path in SCENES:
        with open(os.path.join(prm_dir, name + ".prm"), "w") as f:
            f.write(prm_text(name, changes, edges, path, os.path.abspath(results_dir)))
        print(os.path.join(prm_dir, name + ".prm"))


def compare(old_dir, new_dir):
    import h5py
    import numpy as np

    worst = {}  # column -> [all rows, scene, last row, scene]
    problems = []
    for name, *_ in SCENES:
        paths = [os.path.join(d, name + ".h5") for d in (old_dir, new_dir)]
        if not all(os.path.exists(p) for p in paths):
            problems.append(f"{name}: results missing")
            continue
        with h5py.File(paths[0], "r") as old, h5py.File(paths[1], "r") as new:
            for column in old["summary"]:
                if column not in new["summary"]:
                    problems.append(f"{name}: column {column} missing in the new results")
                    continue
                a = np.asarray(old["summary"][column], dtype=float)
                b = np.asarray(new["summary"][column], dtype=float)
                if a.shape != b.shape:
                    problems.append(f"{name}: {column} has shape {a.shape} old, {b.shape} new")
                    continue
                nan_a, nan_b = np.isnan(a), np.isnan(b)
                if np.any(nan_a != nan_b):
                    problems.append(f"{name}: {column} is NaN in different rows")
                    continue
                a, b = np.where(nan_a, 0.0, a), np.where(nan_b, 0.0, b)
                scale = np.max(np.abs(a)) if a.size else 0.0
                diff = np.abs(a - b)
                all_rows = np.max(diff) / scale if scale > 0 else float(np.max(diff, initial=0))
                last_a, last_b = a[-1], b[-1]
                with np.errstate(invalid="ignore", divide="ignore"):
                    last = np.where(last_a != 0, np.abs(last_b - last_a) / np.abs(last_a),
                                    np.abs(last_b - last_a))
                last = float(np.max(last, initial=0))
                w = worst.setdefault(column, [0.0, "", 0.0, ""])
                if all_rows >= w[0]:
                    w[0], w[1] = all_rows, name
                if last >= w[2]:
                    w[2], w[3] = last, name
    print(f"{'/summary column':<24} {'all rows':>10}  {'scene':<20} {'last row':>10}  scene")
    for column, (all_rows, s_all, last, s_last) in sorted(worst.items()):
        print(f"{column:<24} {all_rows:10.2e}  {s_all:<20} {last:10.2e}  {s_last}")
    print("(all rows: max |new - old| over the scene's rows / max |old| of the column; last row:"
          " |new - old| / |old| at the end state; largest over the 12 scenes)")
    for p in problems:
        print("MISMATCH:", p)
    return 1 if problems else 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "write":
        write(sys.argv[2], sys.argv[3])
        return 0
    if len(sys.argv) == 4 and sys.argv[1] == "compare":
        return compare(sys.argv[2], sys.argv[3])
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())
