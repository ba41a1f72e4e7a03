"""Kill test: a long (1700-step) `cdea run` stopped at random moments by SIGKILL, SIGINT or
SIGTERM, with checkpoints due every step, every 0.05 s or every second.

After every kill, with older complete results at the same path:
  SIGKILL   the older file is unchanged byte for byte; the checkpoint, if any,
            is readable (h5py, h5dump) and agrees with the printed steps;
            `cdea recover` rebuilds a readable file beside it holding every
            step printed before the kill;
  SIGINT,   the run exits 2 saying "interrupted"; its file replaced the older
  SIGTERM   one and holds every printed step; no journal, lock or checkpoint
            is left.
A run that ended before its signal must have exit code 0 and a complete file;
one killed after writing its file whole (while shutting down) a complete file.
Usage: kill_runs.py CDEA_EXECUTABLE SOURCE_DIR [KILLS] [SEED] [HELPER]
(HELPER: what runs the short run that makes the older results and `cdea
recover`, by default CDEA_EXECUTABLE; tests/kill_runs.sh gives the fork
client of tests/cdea_forks.bash. The killed runs are always the executable
itself: SIGKILL reaches only a real process.)
"""
import hashlib
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

exe, src = sys.argv[1], sys.argv[2]
kills = int(sys.argv[3]) if len(sys.argv) > 3 else 32
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 20251123
helper = sys.argv[5] if len(sys.argv) > 5 else exe
rng = random.Random(seed)
work = tempfile.mkdtemp(prefix="cdea-kill-")
os.chdir(work)
failures = []

STEP = re.compile(r"^\s*(\d+)\s+(pre-stretch|dead load|voltage)\s+(\S+)\s+(\S+)\s+(\S+)\s")


def prm(name, increment):
    text = open(os.path.join(src, "prm", "default.prm")).read()
    text = text.replace("set Directory           = results", "set Directory           = out")
    text = text.replace("set Base name           = default", "set Base name           = long")
    text += "\nsubsection Solver\n  set Voltage increment (kV) = %s\nend\n" % increment
    open(name, "w").write(text)


def printed_steps(path):
    """(index, t, displacement) of every complete step line on stdout."""
    rows = []
    data = open(path, "rb").read().decode(errors="replace")
    for line in data.split("\n")[:-1]:  # the last piece has no newline yet
        m = STEP.match(line)
        if m:
            rows.append((int(m.group(1)), float(m.group(3)), float(m.group(5))))
    return rows


def readable(path):
    """Rows of a results file read whole by h5py and listed by h5dump, or None."""
    if subprocess.run(["h5dump", "-H", path], stdout=subprocess.DEVNULL,
                      stderr=subprocess.DEVNULL).returncode != 0:
        return None
    try:
        with h5py.File(path, "r") as f:
            s = f["summary"]
            n = s["stage"].shape[0]
            if len(f["steps"]) != n:
                return None
            for k in sorted({0, n // 2, n - 1}) if n else []:
                g = f["steps"]["%06d" % k]
                _ = [g[d][:] for d in g]
            return {"t": s["load_factor"][:], "disp": s["displacement_mm"][:],
                    "status": str(f.attrs["run_status"])}
    except Exception as e:  # noqa: BLE001 -- any failure to read is the finding
        print("    h5py:", e)
        return None


def holds(data, printed):
    """Every printed step is a row of the file with the printed values."""
    if data is None or len(data["t"]) < len(printed):
        return False
    for i, t, d in printed:
        if abs(data["t"][i] - t) > 6e-6 or abs(data["disp"][i] - d) > 6e-7:
            return False
    return True


def sha(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def fail(what):
    failures.append(what)
    print("  FAIL", what)


prm("short.prm", 0.25)
prm("long.prm", 0.003)
target = "out/long.h5"
if subprocess.run([helper, "run", "short.prm"], stdout=subprocess.DEVNULL).returncode != 0:
    sys.exit("the short run failed")
shutil.copy(target, "older.h5")
older = sha(target)
outcomes = {}
for trial in range(kills):
    sig = rng.choice([signal.SIGKILL, signal.SIGKILL, signal.SIGINT, signal.SIGTERM])
    interval = rng.choice(["0", "0.05", "1"])
    # Mostly while steps are computed and written (counted from the first
    # printed step, so that a slow start on a busy machine does not matter),
    # sometimes during the start.
    during_start = rng.random() < 0.15
    delay = rng.uniform(0.0, 0.6) if during_start else rng.uniform(0.0, 1.3)
    env = dict(os.environ, CDEA_CHECKPOINT_SECONDS=interval)
    with open("run.out", "wb") as out, open("run.err", "wb") as err:
        # Default signal actions, also when this test runs in a background job
        # (which ignores SIGINT and cdea would keep ignoring it).
        p = subprocess.Popen([exe, "run", "long.prm"], stdout=out, stderr=err, env=env,
                             preexec_fn=lambda: [signal.signal(s, signal.SIG_DFL)
                                                 for s in (signal.SIGINT, signal.SIGTERM)])
        if not during_start:
            for _ in range(600):
                if printed_steps("run.out") or p.poll() is not None:
                    break
                time.sleep(0.02)
        time.sleep(delay)
        p.send_signal(sig)
        try:
            rc = p.wait(timeout=60)
        except subprocess.TimeoutExpired:
            p.kill()
            rc = p.wait()
            fail(f"trial {trial}: no exit 60 s after {sig.name}")
    printed = printed_steps("run.out")
    err = open("run.err", errors="replace").read()
    when = "after the start" if during_start else "after the first step"
    tag = f"trial {trial:2d}: {sig.name:7s} {delay:4.2f} s {when} (checkpoints {interval:>4s} s), " \
          f"{len(printed)} steps printed, exit {rc}"
    left = sorted(os.listdir("out"))
    if rc == 0:
        outcome = "finished before the signal"
        data = readable(target)
        if not (holds(data, printed) and data["status"] == "complete"):
            fail(tag + ": the finished run's file is incomplete")
    elif sig == signal.SIGKILL or rc < 0:
        outcome = f"killed ({signal.Signals(-rc).name})" if rc < 0 else f"exit {rc}"
        if sha(target) != older:
            # Killed after the run had written its file whole (while it
            # printed its summary or shut down): that file must be complete.
            data = readable(target)
            if data is None or data["status"] != "complete" or not holds(data, printed) or \
               os.path.exists(target + ".journal"):
                fail(tag + ": the older results changed, and not into a complete file")
            else:
                outcome = "killed after its file was complete"

        checkpoint = "out/long.partial.h5"
        if os.path.exists(checkpoint):
            data = readable(checkpoint)
            n = 0 if data is None else len(data["t"])
            if data is None or not holds(data, [r for r in printed if r[0] < n]):
                fail(tag + ": the checkpoint is unreadable or disagrees with stdout")
            else:
                outcome += f", checkpoint {n} steps"
        if os.path.exists(target + ".journal"):
            r = subprocess.run([helper, "recover", target], capture_output=True, text=True)
            m = re.search(r"are in (\S+)", r.stdout)
            if r.returncode != 0 or not m:
                fail(tag + f": cdea recover failed: {r.stdout} {r.stderr}")
            else:
                rebuilt = m.group(1)
                data = readable(rebuilt)
                if not holds(data, printed):
                    fail(tag + f": {rebuilt} lacks printed steps or is unreadable")
                else:
                    outcome += f", recovered {len(data['t'])} steps"
                os.remove(rebuilt)
        elif printed and sha(target) == older:
            fail(tag + ": steps were printed but there is no journal")
        if sha(target) != older and outcome != "killed after its file was complete":
            fail(tag + ": recovery changed the older results")
    else:
        outcome = "stopped cleanly"
        data = readable(target)
        if rc != 2 or "interrupted" not in err:
            fail(tag + f": expected exit 2 and 'interrupted', stderr: {err.strip()}")
        elif not holds(data, printed):
            fail(tag + ": the file lacks printed steps or is unreadable")
        rest = [f for f in os.listdir("out") if f != "long.h5"]
        if rest:
            fail(tag + f": left behind {rest}")
    print(f"  {tag}: {outcome}; files before clean-up: {', '.join(left)}")
    outcomes[(sig.name, outcome.split(",")[0])] = outcomes.get((sig.name, outcome.split(",")[0]), 0) + 1
    for f in os.listdir("out"):
        if f != "long.h5":
            os.remove(os.path.join("out", f))
    shutil.copy("older.h5", target)

print("\noutcomes (signal, what happened: trials):")
for k, v in sorted(outcomes.items()):
    print(f"  {k[0]:8s} {k[1]:28s} {v}")
print(f"{kills} kills, seed {seed}: {len(failures)} failures")
shutil.rmtree(work)
sys.exit(1 if failures else 0)
