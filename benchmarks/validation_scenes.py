#!/usr/bin/python3
"""The twelve scenes of tests/test_validation_agreement.cc as parameter files,
and the comparison of two sets of `cdea run` results on them.

Usage:
  validation_scenes.py write PRM_DIR RESULTS_DIR
      writes PRM_DIR/<scene>.prm (default discretization and solver settings)
      whose results go to RESULTS_DIR/<scene>.h5
  validation_scenes.py compare OLD_DIR NEW_DIR
      for every floating-point /summary column: the largest difference
      between the two results of a scene over all its rows (relative to the
      column's largest magnitude in the old file; where, with both values)
      and at the last row (relative to the old value), the largest over the
      scenes; for every integer column the rows that differ; exit 1 if a
      scene is missing or the rows differ in number.

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

    # column -> worst over the scenes: [all rows, scene, row, old, new, last row, scene]
    worst = {}
    differing = {}  # integer column -> [rows that differ, rows, where]
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
                a, b = np.asarray(old["summary"][column]), np.asarray(new["summary"][column])
                if a.shape != b.shape:
                    problems.append(f"{name}: {column} has shape {a.shape} old, {b.shape} new")
                    continue
                if a.dtype.kind in "iub":
                    d = differing.setdefault(column, [0, 0, []])
                    rows = np.nonzero(np.any((a != b).reshape(len(a), -1), axis=1))[0]
                    d[0] += len(rows)
                    d[1] += len(a)
                    d[2] += [f"{name} row {r}: {a[r]} -> {b[r]}" for r in rows]
                    continue
                a, b = a.reshape(len(a), -1), b.reshape(len(b), -1)
                if np.any(np.isnan(a) != np.isnan(b)):
                    problems.append(f"{name}: {column} is NaN in different rows")
                    continue
                a, b = np.nan_to_num(a), np.nan_to_num(b)
                scale = np.max(np.abs(a), initial=0.0)
                diff = np.abs(a - b) / (scale if scale > 0 else 1.0)
                row, k = np.unravel_index(np.argmax(diff), diff.shape) if diff.size else (0, 0)
                with np.errstate(invalid="ignore", divide="ignore"):
                    last = np.where(a[-1] != 0, np.abs(b[-1] - a[-1]) / np.abs(a[-1]),
                                    np.abs(b[-1] - a[-1]))
                last = float(np.max(last, initial=0.0))
                w = worst.setdefault(column, [-1.0, "", 0, 0.0, 0.0, -1.0, ""])
                if diff.size and diff[row, k] > w[0]:
                    w[:5] = [float(diff[row, k]), name, int(row), a[row, k], b[row, k]]
                if last > w[5]:
                    w[5:] = [last, name]
    print(f"{'/summary column':<23}{'all rows':>10}  {'where: scene, row, old -> new':<55}"
          f"{'last row':>10}  scene")
    for column, (all_rows, s_all, row, a, b, last, s_last) in sorted(worst.items()):
        where = f"{s_all}, {row}, {a:.6g} -> {b:.6g}"
        print(f"{column:<23}{all_rows:10.2e}  {where:<55}{last:10.2e}  {s_last}")
    print("(all rows: largest |new - old| over the rows of a scene over the largest |old| of the"
          " column there;\n last row: |new - old| / |old| at the end of the path; both the"
          " largest over the 12 scenes)")
    for column, (n, total, where) in sorted(differing.items()):
        print(f"{column}: {n} of {total} rows differ" + (": " + "; ".join(where) if where else ""))
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
