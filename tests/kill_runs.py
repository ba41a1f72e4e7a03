"""Kill test: a long (1700-step) `cdea run` stopped at random moments by SIGKILL, SIGINT or
SIGTERM, with checkpoints due every step, every 0.05 s or every second.

After every kill, with older complete results at the same path:
  SIGKILL   the older file is unchanged byte for byte; the checkpoint, if any,
            is readable (h5py, h5dump) and agrees with the printed steps;
            `cdea recover` rebuilds a readable file beside it holding every
            step printed before the kill;
  SIGINT,   the run exits 2 saying "interrupted"; the older file is unchanged
  SIGTERM   byte for byte and the run's steps, every printed one, are beside
            it in out/long.partial.h5; no journal or lock is left.
A run that ended before its signal must have exit code 0 and a complete file;
one killed after writing its file whole (while shutting down) a complete file;
one killed during its start (before its handlers) must have left the older
file as it was.

The moments are fractions of the run's duration, timed once on a whole run
first, so that a fast machine does not spend its trials on runs that end
before their signal. The first trials follow a plan (PLANNED below): each
signal during the steps and during the start, one after the end, and SIGKILL
while the finished run shuts down; the test asserts that every one of these
outcome classes occurred. The others are random (15 % during the start).
Usage: kill_runs.py CDEA_EXECUTABLE SOURCE_DIR [KILLS] [SEED] [HELPER]
(KILLS: the number of trials, default 12, of which the first 8 are the plan;
HELPER: what runs the timing run, the short run that makes the older results
and `cdea recover`, by default CDEA_EXECUTABLE; tests/kill_runs.sh gives the
fork client of tests/cdea_forks.bash. The killed runs are always the
executable itself: SIGKILL reaches only a real process.)
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
kills = int(sys.argv[3]) if len(sys.argv) > 3 else 12
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


def first_step_seen(p, deadline=12.0):
    """Waits for the first printed step (or the end of the run); its moment."""
    for _ in range(int(deadline / 0.01)):
        if printed_steps("run.out") or p.poll() is not None:
            break
        time.sleep(0.01)
    return time.monotonic()


def default_actions():
    # Default signal actions, also when this test runs in a background job
    # (which ignores SIGINT and cdea would keep ignoring it).
    for s in (signal.SIGINT, signal.SIGTERM):
        signal.signal(s, signal.SIG_DFL)


def run_duration():
    """Seconds from the first printed step of the long run to its exit, timed
    on one whole run through HELPER (the same computation as the real
    executable's, without its start-up); the delays below are fractions of it,
    so that their outcomes do not depend on the machine's speed."""
    with open("run.out", "wb") as out:
        p = subprocess.Popen([helper, "run", "long.prm"], stdout=out, stderr=subprocess.DEVNULL)
        first = first_step_seen(p)
        rc = p.wait()
    if rc != 0:
        sys.exit("the timing run failed")
    for f in os.listdir("out"):
        os.remove(os.path.join("out", f))
    return max(time.monotonic() - first, 0.05)


# What a trial asks for: the signal, and when it comes:
#   start     0 to 0.05 s after the process began: while the program loads,
#             before its handlers and its journal (no step printed);
#   steps     at a random fraction of the run after its first printed step;
#   complete  as soon as the run has renamed its file into place and removed
#             its journal (it then prints its summary and shuts down: a
#             window of a few tenths of a second), SIGKILL only;
#   after     past the run's end (1.4 times its duration after its first step);
#   random    as the draw of earlier versions: 15 % during the start (0 to
#             0.6 s after it began), else 0 to 1.1 times the run's duration
#             after the first step.
# The first trials are the plan below, one per outcome class that must occur
# (PLANNED: signal, moment, the class it gives); a planned trial whose class
# did not occur (a run much slower or faster than the timed one) is tried
# again with its moment moved, at most twice. The rest are random. One run
# that ends before its signal, of a signal drawn at random: to a process that
# has ended, Popen.send_signal() sends nothing, so that this class is the same
# whatever the signal (a whole run each).
PLANNED = [
    (signal.SIGKILL, "steps", "killed, journal recovered"),
    (signal.SIGINT, "steps", "stopped cleanly"),
    (signal.SIGTERM, "steps", "stopped cleanly"),
    (signal.SIGKILL, "complete", "killed after its file was complete"),
    (signal.SIGKILL, "start", "killed during the start"),
    (signal.SIGINT, "start", "killed during the start"),
    (signal.SIGTERM, "start", "killed during the start"),
    (None, "after", "finished before the signal"),
]


def trial(number, sig, moment, interval, fraction):
    """One killed run and every check of its outcome; the outcome's class."""
    env = dict(os.environ, CDEA_CHECKPOINT_SECONDS=interval)
    during_start = moment == "start" or (moment == "random" and fraction < 0)
    with open("run.out", "wb") as out, open("run.err", "wb") as err:
        p = subprocess.Popen([exe, "run", "long.prm"], stdout=out, stderr=err, env=env,
                             preexec_fn=default_actions)
        if during_start:
            delay = abs(fraction)
            time.sleep(delay)
        elif moment == "complete":
            # (copied in place, the older file keeps its inode; the run's rename gives a new one)
            older_inode = os.stat(target).st_ino
            first = first_step_seen(p)
            time.sleep(0.6 * duration)
            while p.poll() is None and (os.stat(target).st_ino == older_inode or
                                        os.path.exists(target + ".journal")):
                time.sleep(0.002)
            delay = time.monotonic() - first
        else:
            first = first_step_seen(p)
            delay = fraction * duration
            time.sleep(delay)
        p.send_signal(sig)
        try:
            rc = p.wait(timeout=60)
        except subprocess.TimeoutExpired:
            p.kill()
            rc = p.wait()
            fail(f"trial {number}: no exit 60 s after {sig.name}")
    printed = printed_steps("run.out")
    err = open("run.err", errors="replace").read()
    when = "after the start" if during_start else "after the first step"
    tag = f"trial {number:2d}: {sig.name:7s} {delay:4.2f} s {when} (checkpoints {interval:>4s} s), " \
          f"{len(printed)} steps printed, exit {rc}"
    left = sorted(os.listdir("out"))
    if rc == 0:
        outcome = kind = "finished before the signal"
        data = readable(target)
        if not (holds(data, printed) and data["status"] == "complete"):
            fail(tag + ": the finished run's file is incomplete")
    elif sig == signal.SIGKILL or rc < 0:
        outcome = f"killed ({signal.Signals(-rc).name})" if rc < 0 else f"exit {rc}"
        kind = "killed during the start" if not printed else "killed"
        if sha(target) != older:
            # Killed after the run had written its file whole (while it
            # printed its summary or shut down): that file must be complete.
            # A journal may remain when the kill fell between the file's
            # rename and the journal's removal; recovery then rebuilds the
            # same steps beside the file, which stays as it is.
            data = readable(target)
            if data is None or data["status"] != "complete" or not holds(data, printed):
                fail(tag + ": the older results changed, and not into a complete file")
            else:
                outcome = kind = "killed after its file was complete"

        checkpoint = "out/long.partial.h5"
        if os.path.exists(checkpoint):
            data = readable(checkpoint)
            n = 0 if data is None else len(data["t"])
            if data is None or not holds(data, [r for r in printed if r[0] < n]):
                fail(tag + ": the checkpoint is unreadable or disagrees with stdout")
            else:
                outcome += f", checkpoint {n} steps"
        if os.path.exists(target + ".journal"):
            if kind != "killed after its file was complete":
                kind = "killed, journal recovered"
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
        if sha(target) != older and kind != "killed after its file was complete":
            fail(tag + ": recovery changed the older results")
    else:
        outcome = kind = "stopped cleanly"
        data = readable("out/long.partial.h5")
        if rc != 2 or "interrupted" not in err:
            fail(tag + f": expected exit 2 and 'interrupted', stderr: {err.strip()}")
        elif sha(target) != older:
            fail(tag + ": the interrupted run changed the older results")
        elif not holds(data, printed):
            fail(tag + ": long.partial.h5 lacks printed steps or is unreadable")
        rest = [f for f in os.listdir("out") if f not in ("long.h5", "long.partial.h5")]
        if rest:
            fail(tag + f": left behind {rest}")
    print(f"  {tag}: {outcome}; files before clean-up: {', '.join(left)}")
    for f in os.listdir("out"):
        if f != "long.h5":
            os.remove(os.path.join("out", f))
    shutil.copy("older.h5", target)
    return kind


prm("short.prm", 0.25)
prm("long.prm", 0.003)
target = "out/long.h5"
duration = run_duration()
print(f"  the long run: {duration:.2f} s from its first printed step to its exit (timed once)")
if subprocess.run([helper, "run", "short.prm"], stdout=subprocess.DEVNULL).returncode != 0:
    sys.exit("the short run failed")
shutil.copy(target, "older.h5")
older = sha(target)
outcomes = {}
number = 0
PLANNED = [(sig or rng.choice([signal.SIGKILL, signal.SIGINT, signal.SIGTERM]), moment, expected)
           for sig, moment, expected in PLANNED]
for sig, moment, expected in PLANNED[:kills]:
    for attempt in range(3):
        # a retry moves the moment: earlier within the steps, later past the end
        draw = {"start": rng.uniform(0.0, 0.05),
                "steps": rng.uniform(0.05, 0.8) / 1.5 ** attempt,
                "after": 1.4 * 1.5 ** attempt}.get(moment, 0.0)
        kind = trial(number, sig, moment, rng.choice(["0", "0.05", "1"]), draw)
        number += 1
        outcomes[(sig.name, kind)] = outcomes.get((sig.name, kind), 0) + 1
        if kind == expected:
            break
while number < kills:
    sig = rng.choice([signal.SIGKILL, signal.SIGKILL, signal.SIGINT, signal.SIGTERM])
    interval = rng.choice(["0", "0.05", "1"])
    # during the start: a negative fraction, its size the delay in seconds
    draw = -rng.uniform(0.0, 0.6) if rng.random() < 0.15 else rng.uniform(0.0, 1.1)
    kind = trial(number, sig, "random", interval, draw)
    number += 1
    outcomes[(sig.name, kind)] = outcomes.get((sig.name, kind), 0) + 1

print("\noutcomes (signal, what happened: trials):")
for k, v in sorted(outcomes.items()):
    print(f"  {k[0]:8s} {k[1]:34s} {v}")
for sig, moment, expected in PLANNED[:kills]:
    if (sig.name, expected) not in outcomes:
        fail(f"no trial of {sig.name} ended as '{expected}' (planned: {moment})")
print(f"{number} kills, seed {seed}: {len(failures)} failures")
shutil.rmtree(work)
sys.exit(1 if failures else 0)
