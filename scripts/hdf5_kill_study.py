"""How plain HDF5 files survive SIGKILL: the measurement behind the choice of
crash-safe output in doc/usage.md ("Why a journal and whole-file writes").

Two writers append one step after another until killed at a random moment:
  flush   the old layout of cdea: a /summary row (datasets extended) and a
          group /steps/NNNNNN with 11 small datasets per step, H5Fflush after
          every step (HDF5 file locking off, as cdea had it);
  swmr    HDF5's single-writer/multiple-reader mode: fixed datasets created
          first (SWMR allows no new groups or datasets afterwards), then rows
          appended and flushed per step.
With a cdea executable of the former writer (commit bdeb671, which flushed
after every step) as third argument, its own 5007-step run is killed as well.
After each kill the file is checked with h5dump and h5py (as is, and for SWMR
also after `h5clear -s`, which clears the "open for writing" flag). Prints the
count of unreadable files and of files missing the last flushed step.

    /usr/bin/python3 scripts/hdf5_kill_study.py [KILLS] [SEED] [OLD_CDEA]
"""
import os
import random
import signal
import subprocess
import sys
import tempfile
import time

kills = int(sys.argv[1]) if len(sys.argv) > 1 else 40
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
old_cdea = sys.argv[3] if len(sys.argv) > 3 else None
rng = random.Random(seed)

WRITER = r'''
import sys, h5py, numpy as np
mode, path, log = sys.argv[1], sys.argv[2], sys.argv[3]
samples = np.linspace(0, 1, 17)
out = open(log, "w", buffering=1)
if mode == "flush":
    f = h5py.File(path, "w", locking=False)
    s = f.create_group("summary"); steps = f.create_group("steps")
    cols = [s.create_dataset(n, (0,), maxshape=(None,), chunks=(128,), dtype="f8")
            for n in ("load_factor", "displacement_mm", "s2_min_kPa", "volume_mm3")]
    for i in range(10 ** 9):
        for c in cols:
            c.resize((i + 1,)); c[i] = i
        g = steps.create_group("%06d" % i)
        g.attrs["load_factor"] = i
        for n in ("R", "r", "z", "theta", "lambda1", "lambda2", "s1", "s2", "E", "Phi", "ring"):
            d = g.create_dataset(n, data=samples + i)
            d.attrs["unit"] = "mm"
        f.flush(); out.write("%d\n" % i)
else:
    f = h5py.File(path, "w", libver="latest")
    cols = [f.create_dataset(n, (0,), maxshape=(None,), chunks=(128,), dtype="f8")
            for n in ("load_factor", "displacement_mm", "s2_min_kPa", "volume_mm3")]
    fields = f.create_dataset("fields", (0, 11, 17), maxshape=(None, 11, 17),
                              chunks=(8, 11, 17), dtype="f8")
    f.swmr_mode = True
    for i in range(10 ** 9):
        for c in cols:
            c.resize((i + 1,)); c[i] = i
        fields.resize((i + 1, 11, 17)); fields[i] = samples + i
        f.flush(); out.write("%d\n" % i)
'''


def rows(path, mode):
    """Rows readable by h5py, or None; the file must also pass h5dump -H."""
    if subprocess.run(["h5dump", "-H", path], capture_output=True).returncode != 0:
        return None
    check = ("import h5py,sys; f=h5py.File(sys.argv[1],'r',locking=False); "
             + ("n=f['summary/load_factor'].shape[0]; assert len(f['steps'])>=n; "
                "[f['steps'][k]['z'][:] for k in f['steps']]; print(n)" if mode == "flush" else
                "n=f['load_factor'].shape[0]; f['fields'][:]; print(n)"))
    r = subprocess.run([sys.executable, "-c", check, path], capture_output=True, text=True)
    return int(r.stdout) if r.returncode == 0 else None


work = tempfile.mkdtemp(prefix="hdf5-kill-")
writer = os.path.join(work, "writer.py")
open(writer, "w").write(WRITER)
if old_cdea:
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    text = open(os.path.join(src, "prm", "default.prm")).read()
    text = text.replace("set Directory           = results", "set Directory           = " + work)
    open(os.path.join(work, "long.prm"), "w").write(
        text + "\nsubsection Solver\n  set Voltage increment (kV) = 0.001\nend\n")
    unreadable = 0
    for k in range(kills):
        with open(os.path.join(work, "log"), "w") as log:
            p = subprocess.Popen([old_cdea, "run", os.path.join(work, "long.prm")], stdout=log)
            time.sleep(rng.uniform(1.0, 3.5))
            p.send_signal(signal.SIGKILL)
            p.wait()
        path = os.path.join(work, "default.h5")
        unreadable += os.path.exists(path) and rows(path, "flush") is None
        if os.path.exists(path):
            os.remove(path)
    print(f"cdea (flush after every step): {kills} SIGKILLs, {unreadable} files unreadable")
for mode in ("flush", "swmr"):
    unreadable = unreadable_cleared = short = 0
    for k in range(kills):
        path, log = os.path.join(work, f"{mode}{k}.h5"), os.path.join(work, "log")
        p = subprocess.Popen([sys.executable, writer, mode, path, log])
        time.sleep(rng.uniform(0.8, 2.5))
        p.send_signal(signal.SIGKILL)
        p.wait()
        flushed = len(open(log).read().split())
        n = rows(path, mode)
        if n is None and mode == "swmr":
            unreadable += 1
            subprocess.run(["h5clear", "-s", path], capture_output=True)
            n = rows(path, mode)
            unreadable_cleared += n is None
        elif n is None:
            unreadable += 1
        if n is not None and n < flushed:
            short += 1
        os.remove(path)
    extra = f", {unreadable_cleared} still unreadable after h5clear -s" if mode == "swmr" else ""
    print(f"{mode:6s}: {kills} SIGKILLs, {unreadable} files unreadable as left{extra}, "
          f"{short} readable files missing flushed steps")
