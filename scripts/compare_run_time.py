"""Wall time of `cdea run` on the default scene with 0.001 kV voltage steps
(5007 steps, a 38 MB results file) for two builds, interleaved, medians of
REPEATS runs each: what the crash-safe output costs against the old writer
(flush after every step).

    /usr/bin/python3 scripts/compare_run_time.py OLD_CDEA NEW_CDEA [REPEATS]
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

old, new = sys.argv[1], sys.argv[2]
repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 5
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
work = tempfile.mkdtemp(prefix="cdea-time-")
prm = os.path.join(work, "long.prm")
text = open(os.path.join(src, "prm", "default.prm")).read()
text = text.replace("set Directory           = results", "set Directory           = " + work)
open(prm, "w").write(text + "\nsubsection Solver\n  set Voltage increment (kV) = 0.001\nend\n")
times = {old: [], new: []}
for _ in range(repeats):
    for exe in (old, new):
        start = time.monotonic()
        subprocess.run([exe, "run", prm], stdout=subprocess.DEVNULL, check=True)
        times[exe].append(time.monotonic() - start)
        os.remove(os.path.join(work, "default.h5"))
a, b = statistics.median(times[old]), statistics.median(times[new])
print(f"old {a:.2f} s, new {b:.2f} s (medians of {repeats}), new/old = {b / a:.2f}")
print("old runs:", " ".join(f"{t:.2f}" for t in times[old]))
print("new runs:", " ".join(f"{t:.2f}" for t in times[new]))
