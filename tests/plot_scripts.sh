#!/usr/bin/env bash
# The plotting scripts on real runs of cdea: plot_stability.py on a run that
# passes no fold (no limit points: an empty attribute; also into a folder
# that does not exist yet) and on the arc-length
# run through both folds with the relaxed run on top; plot_run.py on that run
# (its far branch reaches r = 100 mm: non-physical states are drawn, not cut
# off) and on two-ring runs, whose displacement is plotted against the outer
# ring's voltage, or against t where the path holds the outer voltage.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

for prm in default fold-full relaxed-full partitioned-rv1.7; do
  "$exe" run "$src/prm/$prm.prm" > "$prm.out" 2>&1
done
sed -e 's/set Voltage path (kV)   = 5, 5; 5, 6.5/set Voltage path (kV)   = 5, 5; 6, 5/' \
    -e 's/set Base name           = partitioned-rv1.7/set Base name           = inner-raised/' \
    "$src/prm/partitioned-rv1.7.prm" > inner-raised.prm
"$exe" run inner-raised.prm > inner-raised.out 2>&1

"$PYTHON" "$src/postprocess/plot_stability.py" nofold.png results/default.h5 > s1.txt 2>&1 &&
  [ -s nofold.png ] && ok "plot_stability.py on a run without limit points" ||
  { fail "plot_stability.py without a fold:"; cat s1.txt; }
"$PYTHON" "$src/postprocess/plot_stability.py" new/folder/nofold.png results/default.h5 > s3.txt 2>&1 &&
  [ -s new/folder/nofold.png ] && ok "plot_stability.py creates the output folder" ||
  { fail "plot_stability.py into a new folder:"; cat s3.txt; }
"$PYTHON" "$src/postprocess/plot_stability.py" folds.png results/fold-full.h5 \
  results/relaxed-full.h5 > s2.txt 2>&1 && [ -s folds.png ] &&
  ok "plot_stability.py through both folds, relaxed run on top" ||
  { fail "plot_stability.py with folds:"; cat s2.txt; }
"$PYTHON" "$src/postprocess/plot_run.py" results/fold-full.h5 --out plots --steps all > r1.txt 2>&1 &&
  [ -s plots/fold-full_profiles.png ] && ok "plot_run.py on the arc-length run, all steps" ||
  { fail "plot_run.py on fold-full:"; cat r1.txt; }

"$PYTHON" - "$src/postprocess" <<'PY' && ok "plot_run.py: axes, wrinkled samples and non-physical states" || fail "plot_run.py checks"
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
import plot_run

bad = 0
def check(cond, what):
    global bad
    print(("  ok   " if cond else "  FAIL ") + what)
    bad += not cond

r = plot_run.Run("results/partitioned-rv1.7.h5")
rows = r.rows(plot_run.STAGE_VOLTAGE)
x, label = r.x_axis(rows)
check(label.startswith("voltage of the outer ring") and x[-1] == 6.5 and np.all(np.diff(x) > 0),
      f"two rings, outer raised last: x = outer voltage ({label})")
last = r.n_steps - 1
f = r.fields(last)
w = r.wrinkled_points(last, f)
idx = np.flatnonzero(w)
check(w.any() and np.all(f["s2"][w] < 0) and np.all(f["ring"][w] == 1) and
      idx[0] == np.flatnonzero(f["ring"] == 1)[0] and np.all(np.diff(idx) == 1),
      f"wrinkled samples at 6.5 kV: s2 < 0 on {len(idx)} samples from the outer ring's inner edge")

q = plot_run.Run("results/inner-raised.h5")
x, label = q.x_axis(q.rows(plot_run.STAGE_VOLTAGE))
check(label.startswith("voltage path parameter"), f"outer held while the inner rises: x = t ({label})")

s = plot_run.Run("results/fold-full.h5")
far = np.flatnonzero(s.nonphysical)
check(len(far) > 10 and s.nonphysical[-1] == 1 and
      s.nonphysical_reason(far[0]) == "r beyond the frame or the axis",
      f"fold-full: {len(far)} non-physical states, reason '{s.nonphysical_reason(far[-1])}'")
check(max(s.fields(i)["r"].max() for i in far) > 90, "their meridians reach beyond r = 90 mm")
sys.exit(1 if bad else 0)
PY

finish
