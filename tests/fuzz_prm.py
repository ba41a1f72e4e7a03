"""Seeded mutational fuzzer of the parameter files in prm/.

Each case takes a file of prm/, applies one to three mutations (a value
replaced by an extreme, malformed or huge one, a line deleted, repeated,
swapped or cut, bytes inserted, a separator added), and runs `cdea run` (or
now and then `cdea shoot`) on it in a directory of its own, for at most
LIMIT seconds; a run still going then gets SIGINT and must stop within GRACE
seconds at its next step. A sweep file (prm/sweep*.prm) is mostly given to
`cdea sweep`, its map cut to 2 x 2 points after the mutations (so that a
case takes seconds): a sweep has SWEEP_LIMIT seconds and no SIGINT, and one
still going then is a hang. prm/frequency-sweep.prm mostly goes to `cdea
frequency-sweep` (two frequencies), prm/response.prm often to `cdea
response`, and any file now and then to `cdea chart`; they get SIGINT after
LIMIT seconds as a run does and must leave no lock, journal or temporary
file. A case fails on
  - a crash (exit by a signal, but for our SIGINT before the first step or
    after the results file was written) or an exit code other than 0, 1, 2;
  - a hang: no exit GRACE seconds after SIGINT, or the last 20 printed steps
    all at the same load (no progress), or a sweep over SWEEP_LIMIT seconds;
  - a deal.II stack trace or an uncaught exception on stderr, or more than
    20 kB of it;
  - anything left in the directory after exit 1 but the input;
  - after exit 0 or 2: no readable results file, or a journal, lock or
    checkpoint left behind.
Usage: fuzz_prm.py CDEA_EXECUTABLE SOURCE_DIR CASES SEED [WORKERS] [LIMIT] [SWEEP_LIMIT]
(CASES: a count, or case numbers separated by ',' to rerun those)
Failing inputs are kept in ./fuzz-failures/.
"""
import concurrent.futures
import glob
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

exe, src = sys.argv[1], sys.argv[2]
seed = int(sys.argv[4])
# The cases start with the default actions of SIGINT and SIGTERM, also when
# this test runs in a background job (which ignores SIGINT, and cdea would keep
# ignoring it): handled here, they are reset to the default at exec, which an
# ignored signal is not. (Not a preexec_fn: without one, subprocess starts a
# case with vfork instead of a fork of this interpreter, 3 ms less per case.)
signal.signal(signal.SIGINT, signal.default_int_handler)
signal.signal(signal.SIGTERM, signal.SIG_DFL)
# CASES is a count, or a comma-separated list of case numbers (to rerun some).
selected = [int(c) for c in sys.argv[3].split(",")] if "," in sys.argv[3] else None
cases = len(selected) if selected else int(sys.argv[3])
workers = int(sys.argv[5]) if len(sys.argv) > 5 else 2
limit = float(sys.argv[6]) if len(sys.argv) > 6 else 2.0
grace = 20.0
sweep_limit = float(sys.argv[7]) if len(sys.argv) > 7 else 300.0
# Appended to a sweep case after its mutations: a 2 x 2 map (the later entry wins).
SMALL_MAP = (b"\nsubsection Sweep\n  set Ring edge values (r/a) = 1.5, 2\n"
             b"  set Outer voltage range (kV) = 5, 5.5, 0.5\nend\n")
# Appended to a frequency-sweep case: two frequencies (seconds).
SHORT_SWEEP = b"\nsubsection Frequency sweep\n  set Frequencies (Hz) = 1, 3\nend\n"
inputs = sorted(glob.glob(os.path.join(src, "prm", "*.prm")))
texts = {os.path.basename(p): open(p, "rb").read() for p in inputs}

EXTREMES = [b"0", b"-1", b"-0", b"1e-320", b"4.9e-324", b"1e306", b"-1e306", b"1.7e308", b"1e400",
            b"nan", b"inf", b"-inf", b"", b"   ", b"abc", b"1,", b"1;", b"1, 2", b"1;2", b",",
            b";", b"...", b"1, ..., 3", b"0x10", b"1e", b"+", b"true", b"2147483648",
            b"-2147483649", b"99999999999999999999", b"1" * 300, b"\xff\xfe", b"\x00",
            b"arc length", b"relaxed", b"Trilinos KLU", b"1 2 3", b"1\\"]
BAD_STACKS = re.compile(rb"[Ss]tacktrace|-{20}|An error occurred in line|terminate called|"
                        rb"Segmentation fault|Aborted|what\(\):")
STEP = re.compile(rb"^\s*\d+\s+(pre-stretch|dead load|voltage)\s+(\S+)\s+(\S+)", re.M)
WRITING = re.compile(rb"writing (\S+\.h5)\s*$", re.M)
RESULTS = re.compile(rb"^results: \d+ steps in ", re.M)


def mutate(rng, data):
    lines = data.split(b"\n")
    what = []
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(["value", "value", "value", "scale", "delete", "repeat", "swap",
                           "cut", "bytes", "separator", "huge"])
        sets = [i for i, l in enumerate(lines) if b"=" in l and l.strip().startswith(b"set")]
        i = rng.randrange(len(lines)) if lines else 0
        if kind in ("value", "scale", "separator", "huge") and sets:
            i = rng.choice(sets)
            head, value = lines[i].split(b"=", 1)
            value = value.strip()
            if kind == "value":
                value = rng.choice(EXTREMES)
            elif kind == "scale":
                try:
                    value = repr(float(value) * 10.0 ** rng.randint(-15, 15)).encode()
                except ValueError:
                    value = rng.choice(EXTREMES)
            elif kind == "separator":
                value += rng.choice([b",", b";", b", ", b" ;", b",,", b";;"])
            else:
                value = rng.choice([b"7", b"1, ", b"x"]) * rng.choice([10000, 200000])
            lines[i] = head + b"= " + value
        elif kind == "delete" and lines:
            del lines[i]
        elif kind == "repeat" and lines:
            lines.insert(rng.randrange(len(lines) + 1), lines[i])
        elif kind == "swap" and len(lines) > 1:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind == "cut":
            joined = b"\n".join(lines)
            lines = joined[:rng.randrange(len(joined) + 1)].split(b"\n")
        else:
            joined = b"\n".join(lines)
            at = rng.randrange(len(joined) + 1)
            noise = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
            lines = (joined[:at] + noise + joined[at:]).split(b"\n")
        what.append(kind)
    return b"\n".join(lines), what


def run_case(index):
    rng = random.Random(seed * 1000003 + index)
    name = rng.choice(sorted(texts))
    data, what = mutate(rng, texts[name])
    command = "shoot" if rng.random() < 0.15 else "run"
    if name.startswith("sweep") and rng.random() < 0.7:
        command = "sweep"
        data += SMALL_MAP
    # The commands added last, as run is: a short frequency sweep, the
    # response, and now and then the material chart of any file.
    other = rng.random()
    if name == "frequency-sweep.prm" and other < 0.7:
        command = "frequency-sweep"
        data += SHORT_SWEEP
    elif name == "response.prm" and other < 0.5:
        command = "response"
    elif other < 0.04:
        command = "chart"
    work = tempfile.mkdtemp(prefix="cdea-fuzz-")
    with open(os.path.join(work, "case.prm"), "wb") as f:
        f.write(data)
    problems, outcome = [], ""
    start = time.monotonic()
    with open(os.path.join(work, "out.log"), "wb") as out, \
         open(os.path.join(work, "err.log"), "wb") as err:
        p = subprocess.Popen([exe, command, "case.prm"], cwd=work, stdout=out, stderr=err,
                             env=dict(os.environ, CDEA_PROGRESS="off"))
        try:
            rc = p.wait(timeout=sweep_limit if command == "sweep" else limit)
        except subprocess.TimeoutExpired:
            if command == "sweep":
                p.kill()
                rc = p.wait()
                problems.append(f"hang: the sweep of a 2 x 2 map still ran after {sweep_limit} s")
                outcome = "killed "
            else:
                p.send_signal(signal.SIGINT)
                outcome = "interrupted "
                try:
                    rc = p.wait(timeout=grace)
                except subprocess.TimeoutExpired:
                    p.kill()
                    rc = p.wait()
                    problems.append(f"hang: still running {grace} s after SIGINT")
    seconds = time.monotonic() - start
    stdout = open(os.path.join(work, "out.log"), "rb").read()
    stderr = open(os.path.join(work, "err.log"), "rb").read()
    steps = STEP.findall(stdout)
    finished = RESULTS.search(stdout) is not None
    if rc == -signal.SIGINT and outcome and (not steps or finished):
        pass  # our SIGINT came before the run started or after its file was written
    elif rc < 0 and outcome != "killed ":
        problems.append(f"crash: killed by {signal.Signals(-rc).name}")
    elif rc not in (0, 1, 2):
        problems.append(f"exit code {rc}")
    if BAD_STACKS.search(stderr):
        problems.append("stack trace or uncaught exception on stderr")
    if len(stderr) > 20000:
        problems.append(f"{len(stderr)} bytes on stderr")
    if outcome and len(steps) >= 20 and len(set(steps[-20:])) == 1:
        problems.append("no progress: the last 20 steps are at the same load")
    if command not in ("run", "shoot") and rc in (0, 2):
        for root, _, files in os.walk(work):
            for f in files:
                if f.endswith((".lock", ".journal", ".tmp", ".older")):
                    problems.append(f"{command} left {f} behind")
    left = sorted(set(os.listdir(work)) - {"case.prm", "out.log", "err.log"})
    if rc == 1 and left:
        problems.append(f"exit 1 left {left} behind")
    if rc in (0, 2):
        m = WRITING.search(stdout)
        if m:
            path = os.path.join(os.fsencode(work), m.group(1))  # names may be any bytes
            for extra in (b".journal", b".lock"):
                if os.path.exists(path + extra):
                    problems.append(f"{extra} left behind")
            if steps and os.path.exists(path):
                try:
                    with h5py.File(path, "r") as f:
                        if f["summary/stage"].shape[0] < len(steps):
                            problems.append("the results file lacks printed steps")
                except Exception as e:  # noqa: BLE001 -- unreadable is the finding
                    problems.append(f"unreadable results file: {e}")
            elif steps:
                problems.append("steps printed but no results file")
    outcome += {0: "exit 0", 1: "exit 1", 2: "exit 2"}.get(rc, f"exit {rc}")
    if problems:
        keep = os.path.join(os.getcwd(), "fuzz-failures", f"case-{seed}-{index}")
        os.makedirs(keep, exist_ok=True)
        for f in ("case.prm", "out.log", "err.log"):
            shutil.copy(os.path.join(work, f), keep)
    shutil.rmtree(work, ignore_errors=True)
    return index, name, command, what, outcome, seconds, problems


counts, failed, slowest = {}, [], 0.0
t0 = time.monotonic()
with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
    for index, name, command, what, outcome, seconds, problems in pool.map(run_case, selected or range(cases)):
        counts[outcome] = counts.get(outcome, 0) + 1
        slowest = max(slowest, seconds)
        if problems:
            failed.append(index)
            print(f"FAIL case {index} ({command} {name}, {'+'.join(what)}): {'; '.join(problems)}",
                  flush=True)
        if not selected and (index + 1) % 500 == 0 and index + 1 < cases:
            print(f"  {index + 1} cases, {len(failed)} failing, {time.monotonic() - t0:.0f} s",
                  flush=True)
print(f"{cases} cases from {len(texts)} files, seed {seed}, {workers} workers, "
      f"{limit} s each before SIGINT: {time.monotonic() - t0:.0f} s, slowest case {slowest:.1f} s")
for outcome, n in sorted(counts.items()):
    print(f"  {outcome:20s} {n}")
print(f"{len(failed)} failing cases: crashes, hangs, stack traces or leftovers")
sys.exit(1 if failed else 0)
