#!/bin/bash
# postprocess/plot_run.py on small made-up results files with the layout of
# cdea::ResultsFile (written here with h5py): the three PNGs must exist and be
# non-empty, for one and for two rings and both z sign conventions; a missing
# file and a file without /summary must give a non-zero exit and a message.
# Needs CDEA_SOURCE_DIR; python3 with h5py, numpy and matplotlib, whose
# calls fork from one loaded interpreter (tests/python_forks.bash).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
SCRIPT="$src/postprocess/plot_run.py"
TMP=$work

if ! "$PYTHON" -c "import h5py, numpy, matplotlib" 2>/dev/null; then
  echo "FAIL python3 lacks h5py, numpy or matplotlib"
  exit 1
fi

cat > "$TMP/make_h5.py" <<'EOF'
"""A results file with the cdea::ResultsFile layout and made-up, plausible data.
usage: make_h5.py PATH N_RINGS N_VOLTAGE_STEPS Z_SIGN(+1 down / -1 up)"""
import sys
import numpy as np
import h5py

path, n_rings, n_volt, z_sign = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
mu, Jlim, eps, H = 25.1e3, 270.0, 3.98e-11, 1e-3
a, b, lam = 14e-3, 42e-3, 2.5
A, B = a / lam, b / lam
edges_over_a = np.linspace(1.0, 3.0, n_rings + 1) if n_rings > 1 else np.array([1.0, 3.0])
if n_rings == 2:
    edges_over_a = np.array([1.0, 1.7, 3.0])
edges_R = edges_over_a * a / lam

def fields(defl, volts):
    R, ring = [], []
    for k in range(n_rings):
        seg = np.linspace(edges_R[k], edges_R[k + 1], 25)
        R.append(seg); ring.append(np.full(len(seg), k))
    R, ring = np.concatenate(R), np.concatenate(ring)
    x = (R - A) / (B - A)
    r = a + (b - a) * x ** 0.85
    zdown = defl * np.log(b / r) / np.log(b / a)
    l1, theta = np.empty_like(R), np.empty_like(R)
    for k in range(n_rings):
        m = ring == k
        dr, dz = np.gradient(r[m], R[m]), np.gradient(zdown[m], R[m])
        l1[m], theta[m] = np.hypot(dr, dz), np.arctan2(-dz, dr)
    l2 = r / R
    phi = np.asarray(volts)[ring]
    g = 1.0 - (l1**2 + l2**2 + (l1 * l2) ** -2 - 3.0) / Jlim
    e = eps * (phi / H) ** 2
    s1 = mu * (l1 - l1**-3 * l2**-2) / g - e * l1 * l2**2
    s2 = mu * (l2 - l2**-3 * l1**-2) / g - e * l2 * l1**2
    E = phi * l1 * l2 / H
    return dict(R=R, r=r, z=z_sign * zdown, theta=theta, lambda1=l1, lambda2=l2,
                s1=s1, s2=s2, E=E, Phi=phi, ring=ring)

# stage, load factor, voltages (V), displacement (m)
steps = [(0, 1.0, [0.0] * n_rings, 0.0)]
for lf in (0.25, 0.5, 1.0):
    steps.append((1, lf, [0.0] * n_rings, 18.25e-3 * lf ** 0.6))
for t in np.linspace(1.0 / n_volt, 1.0, n_volt):
    if n_rings == 1:
        v = [6000.0 * t]
    else:
        v = [5000.0 * min(2 * t, 1.0)] * n_rings
        v[-1] += 1500.0 * max(2 * t - 1.0, 0.0)
    steps.append((2, t, v, 18.25e-3 + 7e-3 * (np.mean(v) / 6000.0) ** 2))

prm = ("subsection Material\n  set Shear modulus (kPa) = 25.1\n"
       "  set Jlim = 270\nend\n")
with h5py.File(path, "w") as f:
    f.attrs["parameters"] = prm
    f.attrs["code_version"] = "test"
    f.attrs["n_rings"] = np.int32(n_rings)
    s, st = f.create_group("summary"), f.create_group("steps")
    rows = {k: [] for k in ("stage", "load_factor", "voltage_kV", "mass_g", "displacement_mm",
                            "stroke_mm", "s2_min_kPa", "s2_ring_inner_kPa", "wrinkled",
                            "newton_iterations")}
    onset = None
    d_ref = None
    for i, (stage, lf, v, d) in enumerate(steps):
        fl = fields(d, v)
        inner = [fl["s2"][fl["ring"] == k][0] for k in range(n_rings)]
        wr = int(fl["s2"].min() < 0)
        if stage == 1 and lf == 1.0:
            d_ref = d
        if wr and onset is None:
            onset = (v, lam * fl["R"][np.argmin(fl["s2"])])
        for key, val in (("stage", stage), ("load_factor", lf),
                         ("voltage_kV", np.array(v) * 1e-3), ("mass_g", 280.0),
                         ("displacement_mm", d * 1e3),
                         ("stroke_mm", np.nan if d_ref is None else (d - d_ref) * 1e3),
                         ("s2_min_kPa", fl["s2"].min() * 1e-3),
                         ("s2_ring_inner_kPa", np.array(inner) * 1e-3), ("wrinkled", wr),
                         ("newton_iterations", 4)):
            rows[key].append(val)
        g = st.create_group(f"{i:06d}")
        g.attrs["stage"] = np.int32(stage)
        g.attrs["load_factor"] = lf
        g.attrs["voltage_kV"] = np.array(v) * 1e-3
        g.attrs["displacement_mm"] = d * 1e3
        scale = dict(R=1e3, r=1e3, z=1e3, s1=1e-3, s2=1e-3, E=1e-6, Phi=1e-3)
        for key, val in fl.items():
            if key == "ring":
                g.create_dataset(key, data=val.astype(np.int32))
            else:
                g.create_dataset(key, data=val * scale.get(key, 1.0))
    for key, val in rows.items():
        arr = np.array(val)
        if key in ("stage", "wrinkled", "newton_iterations"):
            arr = arr.astype(np.int32)
        s.create_dataset(key, data=arr, maxshape=(None,) + arr.shape[1:], chunks=True)
    s.attrs["onset_found"] = np.int32(onset is not None)
    s.attrs["onset_voltage_kV"] = (np.array(onset[0]) * 1e-3 if onset
                                   else np.full(n_rings, np.nan))
    s.attrs["onset_radius_mm"] = onset[1] * 1e3 if onset else np.nan
EOF

check_pngs() { # label dir base
  local label=$1 dir=$2 base=$3 kind
  for kind in profiles displacement distributions; do
    if [ -s "$dir/${base}_$kind.png" ]; then
      ok "$label: ${base}_$kind.png written"
    else
      fail "$label: ${base}_$kind.png missing or empty"
    fi
  done
}

# Two rings, z positive up, default output directory (next to the file).
if "$PYTHON" "$TMP/make_h5.py" "$TMP/two_rings.h5" 2 24 -1 &&
   "$PYTHON" "$SCRIPT" "$TMP/two_rings.h5" > "$TMP/log1" 2>&1; then
  check_pngs "two rings" "$TMP" two_rings
else
  fail "two rings: plot_run.py failed"; cat "$TMP/log1"
fi

# One ring, z positive down, --out and --steps.
if "$PYTHON" "$TMP/make_h5.py" "$TMP/one_ring.h5" 1 12 1 &&
   "$PYTHON" "$SCRIPT" "$TMP/one_ring.h5" --out "$TMP/plots" --steps 3,-1 > "$TMP/log2" 2>&1; then
  check_pngs "one ring" "$TMP/plots" one_ring
else
  fail "one ring: plot_run.py failed"; cat "$TMP/log2"
fi

# --steps all and last
for spec in all last; do
  if "$PYTHON" "$SCRIPT" "$TMP/one_ring.h5" --out "$TMP/$spec" --steps $spec > "$TMP/log3" 2>&1; then
    check_pngs "--steps $spec" "$TMP/$spec" one_ring
  else
    fail "--steps $spec: plot_run.py failed"; cat "$TMP/log3"
  fi
done

# Errors: missing file, file without /summary, step out of range.
expect_error() { # label pattern args...
  local label=$1 pattern=$2; shift 2
  if "$PYTHON" "$SCRIPT" "$@" > "$TMP/err" 2>&1; then
    fail "$label: exit status 0"
  elif grep -q -- "$pattern" "$TMP/err"; then
    ok "$label: non-zero exit, message: $(head -n 1 "$TMP/err")"
  else
    fail "$label: message lacks '$pattern':"; cat "$TMP/err"
  fi
}
expect_error "missing file" "no such file" "$TMP/does_not_exist.h5"
"$PYTHON" -c "import h5py, sys; h5py.File(sys.argv[1], 'w').create_group('other')" "$TMP/no_summary.h5"
expect_error "file without /summary" "no /summary" "$TMP/no_summary.h5"
echo "not hdf5" > "$TMP/text.h5"
expect_error "not an HDF5 file" "cannot open" "$TMP/text.h5"
expect_error "step out of range" "does not exist" "$TMP/one_ring.h5" --steps 999

if [ "$failures" -ne 0 ]; then
  echo "checks failed: $failures"
  exit 1
fi
echo "all checks passed"
