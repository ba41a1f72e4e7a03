#!/usr/bin/env bash
# Real runs read back with h5py: the /summary and /steps layout, units, the
# onset attributes, stroke and wrinkled semantics; and a run that stops at the
# fold of the full-electrode curve: exit code 2, every converged step readable.
set -eu
exe="${CDEA_EXECUTABLE:?}"
src="${CDEA_SOURCE_DIR:?}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" run "$src/prm/default.prm" > default.out
"$exe" run "$src/prm/partitioned-rv1.7.prm" > partitioned.out
sed -e 's/set Voltage path (kV)   = 5/set Voltage path (kV)   = 8/' \
    -e 's/set Base name           = default/set Base name           = fold/' \
    "$src/prm/default.prm" > fold.prm
set +e
"$exe" run fold.prm > fold.out 2> fold.err
rc=$?
set -e
[ $rc -eq 2 ] || { echo "FAIL: the run past the fold exited with $rc, expected 2"; exit 1; }
grep -q "no equilibrium found" fold.err || { echo "FAIL: no reason given"; cat fold.err; exit 1; }
h5dump -H results/default.h5 > /dev/null || { echo "FAIL: h5dump cannot read the file"; exit 1; }

/usr/bin/python3 - <<'PY'
import math, sys
import h5py
import numpy as np

failures = 0
def check(cond, what):
    global failures
    print(("  ok   " if cond else "  FAIL ") + what)
    if not cond:
        failures += 1

columns = ["stage", "load_factor", "voltage_kV", "mass_g", "displacement_mm", "stroke_mm",
           "s2_min_kPa", "s2_ring_inner_kPa", "wrinkled", "newton_iterations"]
fields = ["R", "r", "z", "theta", "lambda1", "lambda2", "s1", "s2", "E", "Phi", "ring"]

for name, rings in [("default", 1), ("partitioned-rv1.7", 2), ("fold", 1)]:
    with h5py.File(f"results/{name}.h5", "r") as f:
        print(name)
        check("parameters" in f.attrs and "Ring edges" in str(f.attrs["parameters"]),
              "root attribute 'parameters' holds the prm text")
        check("code_version" in f.attrs, "root attribute 'code_version'")
        s = f["summary"]
        n = s["stage"].shape[0]
        for c in columns:
            check(c in s, f"/summary/{c} exists")
        check(s["voltage_kV"].shape == (n, rings), "voltage_kV is steps x rings")
        check(s["s2_ring_inner_kPa"].shape == (n, rings), "s2_ring_inner_kPa is steps x rings")
        check(len(f["steps"]) == n, f"one /steps group per summary row ({n})")
        stage = s["stage"][:]
        check(list(stage[:2]) == [0, 0] and stage[-1] == 2 and np.all(np.diff(stage) >= 0),
              "stages run 0, 1, 2 in order")
        mass = s["mass_g"][:]
        check(abs(mass[-1] - 280.0) < 1e-9 and mass[0] == 0.0, "mass ramps to 280 g")
        last_load = np.where(stage == 1)[0][-1]
        stroke, disp = s["stroke_mm"][:], s["displacement_mm"][:]
        check(np.all(np.isnan(stroke[:last_load])) and stroke[last_load] == 0.0,
              "stroke is NaN before the end of the load stage and 0 at its end")
        check(np.allclose(stroke[stage == 2], disp[stage == 2] - disp[last_load], atol=1e-12),
              "stroke = displacement - displacement at the end of the load stage")
        check(np.array_equal(s["wrinkled"][:] == 1, (s["s2_min_kPa"][:] < 0) & (stage > 0)),
              "wrinkled marks exactly the steps with s2 < 0")
        step = f["steps"][f"{n - 1:06d}"]
        for c in fields:
            check(c in step, f"last step has field {c}")
        R, r, z = step["R"][:], step["r"][:], step["z"][:]
        check(np.all(np.diff(R) >= 0), "R increases along the meridian")
        check(abs(R[0] - 14 / 2.5) < 1e-9 and abs(R[-1] - 42 / 2.5) < 1e-9,
              "R spans a/lam_pre .. b/lam_pre (mm)")
        check(abs(r[0] - 14) < 1e-9 and abs(r[-1] - 42) < 1e-9 and abs(z[-1]) < 1e-12,
              "r(A) = a, r(B) = b, z(B) = 0 (mm)")
        check(abs(abs(z[0] - z[-1]) - disp[-1]) < 1e-9, "displacement = |z(A) - z(B)|")
        phi = step["Phi"][:]
        check(np.allclose(phi[step["ring"][:] == rings - 1], s["voltage_kV"][-1][-1]),
              "Phi (kV) of the outer ring equals its summary voltage")
        E = step["E"][:]
        lam = step["lambda1"][:] * step["lambda2"][:]
        check(np.allclose(E, phi * 1e3 * lam / 1e-3 * 1e-6, rtol=1e-12),
              "E (MV/m) = Phi l1 l2 / H")
        onset = s.attrs["onset_found"]
        if name == "default":
            check(onset == 0, "no onset up to 5 kV with the full electrode")
            check(abs(disp[-1] - 23.79359) < 1e-4, "5 kV displacement near 23.79359 mm")
        elif name == "partitioned-rv1.7":
            v = s.attrs["onset_voltage_kV"]
            check(onset == 1 and abs(v[0] - 5.0) < 1e-9 and 6.4 < v[1] < 6.5,
                  f"onset on the outer ring between 6.4 and 6.5 kV ({v})")
            check(abs(s.attrs["onset_radius_mm"] - 1.7 * 14) < 1e-6,
                  "onset at the outer ring's inner edge r = 1.7 a")
            t = s.attrs["onset_load_factor"]
            check(1.0 < t < 2.0 and abs(5.0 + 1.5 * (t - 1.0) - v[1]) < 1e-9,
                  f"onset_load_factor {t} is the path parameter of the onset voltages")
        else:
            v = s.attrs["onset_voltage_kV"][0]
            check(onset == 1 and 5.0 < v < 5.5, f"full-electrode onset between 5.0 and 5.5 kV ({v})")
            check(s["voltage_kV"][-1][0] > 6.5, "the failed run got past 6.5 kV before stopping")
sys.exit(1 if failures else 0)
PY
echo "all checks passed"
