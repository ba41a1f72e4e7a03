"""A full disk at random sizes: a small tmpfs (needs root; without it the
trials are skipped with a message) holds an older complete results file,
and a run that cannot fit is written into it.

Each trial mounts a tmpfs of a random size, writes an older complete file
there with a short run (or map, optimum, fit), then runs a longer one of the
same name, and requires:
  - exit 2 and a message naming what could not be written;
  - the older complete file byte for byte as it was;
  - the partial result readable: <Base name>.partial.h5 (the leading steps
    that fit) or, where not even those fit, the journal, which `cdea recover`
    turns into a file with every printed step once there is room (checked on
    a copy outside the tmpfs);
  - no lock file left.
The frequency sweep, the response and the chart write files of about the
same size each time: their trials fill the disk after the older file, leaving
less room than it takes, and require the older file kept, exit 2 and no
partial file (those commands keep nothing of a file that does not fit).
Usage: disk_full_trials.py CDEA_EXECUTABLE SOURCE_DIR TRIALS SEED [CASES]
(CASES: names of CASES below separated by ',', default all)
"""
import hashlib
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

import h5py

exe, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
trials, seed = int(sys.argv[3]), int(sys.argv[4])
STEP = re.compile(r"^\s*(\d+)\s+(pre-stretch|dead load|voltage|time)\s", re.M)

# name: (older: the short run; newer: the long one; the file; kind)
CASES = {
    "run": (["run", "prm/default.prm", "--set", "Solver/Voltage increment (kV)=0.5"],
            ["run", "prm/default.prm", "--set", "Solver/Voltage increment (kV)=%s"],
            "default.h5", "steps"),
    "time": (["run", "prm/pump-time.prm", "--set", "Time/Cycles=1", "--set", "Time/Time step (s)=0.05"],
             ["run", "prm/pump-time.prm", "--set", "Time/Cycles=2", "--set", "Time/Time step (s)=%s"],
             "pump-time.h5", "steps"),
    "sweep": (["sweep", "prm/sweep-inner5.prm", "--set", "Sweep/Ring edge values (r/a)=1.5, 2"],
              ["sweep", "prm/sweep-inner5.prm", "--set", "Sweep/Outer voltage range (kV)=5, 8, %s"],
              "sweep-inner5_map.h5", "map"),
    "frequency-sweep": (["frequency-sweep", "prm/frequency-sweep.prm", "--set",
                         "Frequency sweep/Frequencies (Hz)=0.01, 0.1"], None,
                        "frequency-sweep_frequency_sweep.h5", "fill"),
    "response": (["response", "prm/response.prm"], None, "response_response.h5", "fill"),
    "chart": (["chart", "prm/fit-creep.prm"], None, "fit-creep_chart.h5", "fill"),
}


def digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def rows(path):
    try:
        with h5py.File(path, "r") as f:
            return f["summary/stage"].shape[0] if "summary" in f else f["displacement_mm"].shape[0]
    except Exception:  # noqa: BLE001 -- unreadable is the finding
        return None


def run(args, cwd):
    done = subprocess.run([exe] + args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          env=dict(os.environ, CDEA_PROGRESS="off"), timeout=600)
    return done.returncode, done.stdout.decode(errors="replace"), done.stderr.decode(errors="replace")


def fill(disk, rng, room):
    """A file filling the disk up to fewer than @p room bytes free."""
    with open(os.path.join(disk, "filler"), "wb") as f:
        try:
            while True:
                free = os.statvfs(disk).f_bavail * os.statvfs(disk).f_frsize
                if free < room:
                    return
                f.write(b"\0" * min(free - rng.randint(0, room - 1), 1 << 20))
                f.flush()
        except OSError:
            return


def trial(index, work, disk, cases):
    rng = random.Random(seed * 1000003 + index)
    older_args, newer_args, name, kind = CASES[cases[index % len(cases)]]
    size_kb = {"map": rng.randint(40, 120), "fill": 1024}.get(kind, rng.randint(300, 1200))
    subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size_kb}k", "tmpfs", disk], check=True)
    try:
        out = ["--set", "Output/Directory=" + disk]
        rc, _, err = run(older_args + out, work)
        if rc != 0:
            return None, f"the older file does not fit in {size_kb} kB"
        target = os.path.join(disk, name)
        before = digest(target)
        if kind == "fill":  # the same command again, with less room than its file
            fill(disk, rng, os.path.getsize(target))
            newer_args, value = older_args, ""
        # From runs whose journal fits (the file does not) to runs whose
        # journal fills the disk.
        value = {"steps": rng.choice(["0.25", "0.1", "0.05", "0.01", "0.002"]) if "pump" not in name
                 else rng.choice(["0.02", "0.01", "0.005"]), "map": rng.choice(["0.01", "0.02"]),
                 "fill": ""}[kind]
        rc, text, err = run([a.replace("%s", value) for a in newer_args] + out, work)
        problems = []
        if rc == 0:
            return None, f"the newer run fit into {size_kb} kB"
        if rc != 2:
            problems.append(f"exit {rc}: {err[-300:]!r}")
        if not re.search(r"cannot write|No space left|disk", err):
            problems.append(f"no message about the disk: {err[-300:]!r}")
        if digest(target) != before:
            problems.append("the older file changed")
        left = os.listdir(disk)
        if any(f.endswith(".lock") for f in left):
            problems.append(f"a lock left: {left}")
        partial = os.path.join(disk, name.replace(".h5", ".partial.h5"))
        where = "nothing"
        if kind == "steps":
            where = check_partial(partial, target, text, work, problems)
        elif kind == "fill" and os.path.exists(partial):
            problems.append("a partial file of a command that keeps none")
        return problems, f"{cases[index % len(cases)]}, {size_kb} kB: {where}"
    finally:
        subprocess.run(["umount", disk], check=True)


def check_partial(partial, target, text, work, problems):
    """The leading steps beside the older file, or all of them through the journal."""
    printed = len(STEP.findall(text))
    journal = target + ".journal"
    if os.path.exists(partial) and (rows(partial) or 0) == 0:
        problems.append("an unreadable partial file")
    if not os.path.exists(journal):
        problems.append("no journal kept")
        return "no journal"
    room = os.path.join(work, "room")
    shutil.rmtree(room, ignore_errors=True)
    os.makedirs(room)
    shutil.copy(journal, os.path.join(room, os.path.basename(journal)))
    rc, _, err = run(["recover", os.path.join(room, os.path.basename(target))], work)
    recovered = rows(os.path.join(room, os.path.basename(target)))
    if rc != 0 or recovered is None or recovered < printed:
        problems.append(f"recover with room: exit {rc}, {recovered} rows of {printed} printed")
    steps = rows(partial) if os.path.exists(partial) else None
    return (f"{steps} leading steps in .partial.h5, " if steps else "") + \
        f"{recovered} steps through the journal"


def main():
    if os.geteuid() != 0:
        print("skipped: a small tmpfs needs root (run as root to test a full disk)")
        return 0
    work = tempfile.mkdtemp(prefix="cdea-disk-full-")
    shutil.copytree(os.path.join(src, "prm"), os.path.join(work, "prm"))
    disk = os.path.join(work, "disk")
    os.makedirs(disk)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", disk]).returncode:
        print("skipped: cannot mount a tmpfs here")
        return 0
    subprocess.run(["umount", disk], check=True)
    cases = sys.argv[5].split(",") if len(sys.argv) > 5 else list(CASES)
    failures = done = 0
    index = 0
    while done < trials and index < 5 * trials:
        problems, what = trial(index, work, disk, cases)
        index += 1
        if problems is None:
            continue  # not a full-disk trial at this size; draw another
        done += 1
        print(("FAIL " if problems else "ok   ") + f"trial {index - 1}: {what}"
              + (": " + "; ".join(problems) if problems else ""))
        failures += bool(problems)
    shutil.rmtree(work, ignore_errors=True)
    print(f"{done} full-disk trials, {failures} failed")
    return 1 if failures or done < trials else 0


if __name__ == "__main__":
    sys.exit(main())
