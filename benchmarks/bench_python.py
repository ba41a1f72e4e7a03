"""Benchmark: the in-process cost of the Python module `cdea` (doc/python.md,
doc/performance.md).

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/bench_python.py \
        [FILE.prm] [CALLS] [PROCESS_RUNS]

In one interpreter it calls, CALLS times each (default 51), and prints the
median wall and CPU time per call of:
  - cdea.parameters(prm): reading and validating the parameter file alone;
  - cdea.run(prm): reading, model set-up, all load stages, every step's
    summary and fields kept in memory (nothing written);
  - the same plus reading the result as a script does (the summary dict and
    the fields of every step as numpy arrays);
  - result.write(): the HDF5 file of the run, as `cdea run` writes it.
Then, PROCESS_RUNS times each (default 7), what the same costs without the
module: a `cdea run` process (output to a temporary folder) and reading its
/summary with h5py; and the one-off cost of `import cdea` in a fresh
interpreter (loading deal.II and its libraries) against an interpreter that
imports nothing. The goal of the module: at most 5 ms per cdea.run of the
default case.

Fails (exit code 1) if a run does not complete or a time is not finite;
ctest runs it with `prm/default.prm 3 1` (label bench-smoke)."""

import os
import statistics
import subprocess
import sys
import tempfile
import time

import h5py

import cdea

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, ".."))


def timed(f, calls):
    """Median wall and CPU time (s) of calls of f, and f's last result."""
    wall, cpu, result = [], [], None
    for _ in range(calls):
        w, c = time.perf_counter(), time.process_time()
        result = f()
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
    return statistics.median(wall), statistics.median(cpu), result


def read_everything(result):
    summary = result.summary
    return sum(len(result.fields(i)["r"]) for i in range(result.n_steps)) + len(summary)


def main():
    prm = sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, "prm", "default.prm")
    calls = int(sys.argv[2]) if len(sys.argv) > 2 else 51
    process_runs = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    exe = os.environ.get("CDEA_EXECUTABLE", os.path.join(REPO, "build", "cdea"))
    if calls < 1:
        raise SystemExit("bench_python: CALLS must be positive")

    first = cdea.run(prm)  # warm-up, and the figures of the case
    if not first.completed:
        print("bench_python: the run did not complete:", first.message)
        return 1
    rows = []
    rows.append(("cdea.parameters(prm)",) + timed(lambda: cdea.parameters(prm), calls)[:2])
    wall, cpu, result = timed(lambda: cdea.run(prm), calls)
    rows.append(("cdea.run(prm)", wall, cpu))
    run_wall = wall
    rows.append(("cdea.run(prm), summary and all fields read",)
                + timed(lambda: read_everything(cdea.run(prm)), calls)[:2])
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench.h5")
        rows.append(("result.write(path)",) + timed(lambda: result.write(path), calls)[:2])

    print("case: %s (%d steps, %d Newton iterations, %d rings), %d calls each"
          % (prm, result.n_steps, result.newton_iterations, result.n_rings, calls))
    print("%-46s %12s %12s" % ("in-process, median per call", "wall (ms)", "CPU (ms)"))
    for name, w, c in rows:
        print("%-46s %12.3f %12.3f" % (name, w * 1e3, c * 1e3))
    for name, w, c in rows:
        if not (w == w and c == c and w > 0):
            print("bench_python: the time of %s is not finite" % name)
            return 1
    if os.path.basename(prm) == "default.prm":
        print("goal: cdea.run of the default case at most 5 ms per call: %s (median %.3f ms)"
              % ("met" if run_wall <= 5e-3 else "NOT met", run_wall * 1e3))
    if process_runs <= 0:
        return 0

    # The same without the module: a process per run, and its file read back.
    with tempfile.TemporaryDirectory() as folder:
        with open(prm) as f:
            text = f.read()
        copy = os.path.join(folder, "bench.prm")
        with open(copy, "w") as f:
            f.write(text + "\nsubsection Output\n  set Directory = out\n  set Base name = bench\n"
                    "  set ParaView = false\nend\n")

        def process():
            done = subprocess.run([exe, "run", copy], cwd=folder, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL)
            if done.returncode != 0:
                raise SystemExit("bench_python: cdea run failed (status %d)" % done.returncode)
            with h5py.File(os.path.join(folder, "out", "bench.h5"), "r") as f:
                return {k: v[()] for k, v in f["summary"].items()}

        process_wall, _, _ = timed(process, process_runs)
    bare, _, _ = timed(lambda: subprocess.run([sys.executable, "-c", "pass"], check=True),
                       process_runs)
    loaded, _, _ = timed(lambda: subprocess.run([sys.executable, "-c", "import cdea"],
                                                check=True), process_runs)
    print("%-46s %12s" % ("one process per run, median of %d" % process_runs, "wall (ms)"))
    print("%-46s %12.1f" % ("`cdea run` process + h5py read of /summary", process_wall * 1e3))
    print("%-46s %12.1f" % ("python3 -c 'import cdea' (once per session)", loaded * 1e3))
    print("%-46s %12.1f" % ("python3 -c 'pass'", bare * 1e3))
    print("ratio: a process per run / cdea.run in-process = %.0f" % (process_wall / run_wall))
    return 0


if __name__ == "__main__":
    sys.exit(main())
