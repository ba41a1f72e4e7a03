"""SIGINT (or SIGTERM, SIGHUP) at a random moment in every command: run, a
time run, shoot, compare, sweep, frequency-sweep, response, chart, optimize,
fit and recover, each on a case that takes about a second, with an older
complete results file in place (fit: and an older _fit.prm).

A trial passes when the command
  - exits 2 with a line saying "interrupted by SIG..." (compare: no table;
    recover: nothing changed; response, chart: nothing written), the older
    file (and _fit.prm) byte for byte as it was, the results so far readable
    (h5py) beside it in <stem>.partial.h5 (run, time run, shoot: with every
    step printed; sweep, frequency-sweep: the rows or frequencies done),
    its journal and lock gone;
  - or had ended before the signal: exit 0, the complete file;
  - or was killed by the signal during its start-up (before its handlers):
    nothing written, the older file byte for byte as it was, no lock;
  - or was killed by it as it ended (after its handlers were taken down):
    its complete file in place of the older one.
For recover, a killed run's journal is recovered; interrupted, the journal
is kept and nothing is written.
Usage: signal_trials.py CDEA_EXECUTABLE SOURCE_DIR TRIALS SEED [COMMANDS]
(TRIALS per command; COMMANDS separated by ',', default all)
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

exe, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
trials, seed = int(sys.argv[3]), int(sys.argv[4])
STEP = re.compile(r"^\s*(\d+)\s+(pre-stretch|dead load|voltage|time)\s", re.M)

# Each command on a case of about a second: (arguments, results file, kind).
COMMANDS = {
    "run": (["run", "prm/default.prm", "--set", "Solver/Voltage increment (kV)=0.005"],
            "results/default.h5", "steps"),
    "time": (["run", "prm/staircase-full.prm", "--set", "Time/Time step (s)=0.05"],
             "results/staircase-full.h5", "steps"),
    "shoot": (["shoot", "prm/default.prm", "--set", "Solver/Voltage increment (kV)=0.006"],
              "results/default_shooting.h5", "steps"),
    "compare": (["compare", "prm/default.prm", "--set", "Solver/Voltage increment (kV)=0.003"],
                None, "none"),
    "sweep": (["sweep", "prm/sweep-inner5.prm", "--set",
               "Sweep/Outer voltage range (kV)=5, 8, 0.025"], "results/sweep-inner5_map.h5", "map"),
    "frequency-sweep": (["frequency-sweep", "prm/frequency-sweep.prm", "--set",
                         "Frequency sweep/Frequencies (Hz)=0.01, 0.1, 1, 3, 10"],
                        "results/frequency-sweep_frequency_sweep.h5", "frequencies"),
    "response": (["response", "prm/response.prm", "--set", "Solver/Voltage increment (kV)=0.002"],
                 "results/response_response.h5", "whole"),
    "chart": (["chart", "prm/default.prm"], "results/default_chart.h5", "whole"),
    "optimize": (["optimize", "prm/optimize-paper.prm", "--set", "Optimization/Starts=8"],
                 "results/optimize-paper_optimum.h5", "file"),
    "fit": (["fit", "prm/fit-example.prm", "prm/fit-example.csv", "--set",
             "Calibration/Free parameters=shear modulus, Jlim, pre-stretch"],
            "results/fit-example_fit.h5", "file"),
    "recover": (["recover", "results/default.h5"], "results/default.h5", "recover"),
}


def digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest() if os.path.exists(path) else None


def readable(path, kind):
    """Rows of a results file (steps; the map's layouts; 1 for the others), or None."""
    try:
        with h5py.File(path, "r") as f:
            if kind in ("steps", "recover"):
                n = f["summary/stage"].shape[0]
                return n if len(f["steps"]) <= n else None
            if kind == "map":
                return f["displacement_mm"].shape[0]
            if kind == "frequencies":
                return f["sweep/frequency_Hz"].shape[0]
            return len(f.attrs)
    except Exception:  # noqa: BLE001 -- any failure to read is the finding
        return None


def journal_for_recover(work):
    """A killed long run's journal at results/default.h5 (SIGKILL after 1 s)."""
    p = subprocess.Popen([exe, "run", "prm/default.prm", "--set",
                          "Solver/Voltage increment (kV)=0.0005"], cwd=work,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    journal = os.path.join(work, "results/default.h5.journal")
    for _ in range(600):  # a few hundred steps, however loaded the machine
        if os.path.exists(journal) and os.path.getsize(journal) > 2_000_000:
            break
        time.sleep(0.05)
    p.kill()
    p.wait()
    for leftover in ("results/default.partial.h5", "results/default.h5.lock"):
        if os.path.exists(os.path.join(work, leftover)):
            os.remove(os.path.join(work, leftover))
    return os.path.exists(os.path.join(work, "results/default.h5.journal"))


def trial(name, index, work):
    rng = random.Random(seed * 1000003 + index * 31 + sum(map(ord, name)))
    args, target, kind = COMMANDS[name]
    shutil.rmtree(os.path.join(work, "results"), ignore_errors=True)
    os.makedirs(os.path.join(work, "results"))
    older = None
    # an older complete file in its place (a fit: with its parameter file)
    olders = [target] + (["results/fit-example_fit.prm"] if name == "fit" else []) \
        if target else []
    for path in olders:
        with open(os.path.join(work, path), "wb") as f:
            f.write(b"older results " + str(index).encode())
    if target:
        older = [digest(os.path.join(work, path)) for path in olders]
    if kind == "recover":
        os.remove(os.path.join(work, target))
        older, olders = None, []
        if not journal_for_recover(work):
            return ["no journal to recover"], "setup", "-", 0.0
    sig = rng.choice([signal.SIGINT, signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
    delay = rng.uniform(0.0, 1.2)
    with open(os.path.join(work, "out.txt"), "wb") as out, \
         open(os.path.join(work, "err.txt"), "wb") as err:
        p = subprocess.Popen([exe] + args, cwd=work, stdout=out, stderr=err,
                             env=dict(os.environ, CDEA_PROGRESS="off"))
        time.sleep(delay)
        p.send_signal(sig)
        try:
            rc = p.wait(timeout=120)
        except subprocess.TimeoutExpired:
            p.kill()
            return ([f"no exit 120 s after {signal.Signals(sig).name} at {delay:.2f} s"], "hang",
                    signal.Signals(sig).name, delay)
    text = open(os.path.join(work, "out.txt"), errors="replace").read()
    errors = open(os.path.join(work, "err.txt"), errors="replace").read()
    left = sorted(os.listdir(os.path.join(work, "results")))
    problems = []
    kept = [digest(os.path.join(work, path)) for path in olders] == (older or [])
    partial = os.path.join(work, target.replace(".h5", ".partial.h5")) if target else None
    if any(f.endswith((".lock", ".tmp", ".older")) for f in left):
        problems.append(f"left behind: {left}")
    if rc == -sig and not kept and target and kind != "recover" \
            and readable(os.path.join(work, target), kind) is not None:
        # The signal came as the process was ending, after its handling was
        # taken down: its complete file had already replaced the older one.
        outcome = "killed after its file was complete"
    elif rc == -sig:  # killed during the start-up: nothing may have changed
        outcome = "killed at start-up"
        if not kept:
            problems.append("killed at start-up, but the older file changed")
        if kind != "recover" and any(f.endswith(".journal") for f in left):
            problems.append(f"killed at start-up, but a journal exists: {left}")
    elif rc == 0:
        outcome = "ended before the signal"
        if target and kind != "recover" and readable(os.path.join(work, target), kind) is None:
            problems.append("exit 0 without a readable file")
    elif rc == 2:
        outcome = "interrupted"
        if "interrupted by " + signal.Signals(sig).name not in errors:
            problems.append(f"exit 2 without 'interrupted by {signal.Signals(sig).name}'")
        if kind != "recover" and not kept:
            problems.append("interrupted, but the older file changed")
        nothing = re.search(r"before the work began|nothing was written|nothing written", errors)
        if kind == "steps":
            rows = readable(partial, kind)
            printed = len(STEP.findall(text))
            if rows is None or rows < printed:
                problems.append(f"partial file rows {rows}, printed steps {printed}")
            if any(f.endswith(".journal") for f in left):
                problems.append(f"journal left: {left}")
        elif kind in ("map", "file", "frequencies") and not nothing:
            if readable(partial, kind) is None:
                problems.append("exit 2 without a readable partial file")
            if name == "fit" and "fit-example_fit.partial.prm" not in left:
                problems.append(f"the fit's partial pair is incomplete: {left}")
        elif kind == "whole" and (not nothing or os.path.exists(partial)):
            problems.append(f"interrupted, but not 'nothing was written' or a file left: {left}")
        elif kind == "recover" and not os.path.exists(os.path.join(work, target + ".journal")):
            problems.append("recover interrupted, but the journal is gone")
    else:
        outcome = f"exit {rc}"
        problems.append(f"exit {rc}: {errors[-300:]!r}")
    if re.search(r"[Ss]tacktrace|terminate called|what\(\)|Segmentation", errors):
        problems.append("a stack trace or abort message")
    return problems, outcome, signal.Signals(sig).name, delay


def main():
    names = sys.argv[5].split(",") if len(sys.argv) > 5 else list(COMMANDS)
    work = tempfile.mkdtemp(prefix="cdea-signals-")
    shutil.copytree(os.path.join(src, "prm"), os.path.join(work, "prm"))
    failures = 0
    for name in names:
        outcomes = {}
        for i in range(trials):
            problems, outcome, sig, delay = trial(name, i, work)
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
            if problems:
                failures += 1
                print(f"FAIL {name} trial {i} ({sig} at {delay:.2f} s): {'; '.join(problems)}")
        print(f"{name}: {trials} trials: " +
              ", ".join(f"{n} {o}" for o, n in sorted(outcomes.items())))
    shutil.rmtree(work, ignore_errors=True)
    print(f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
