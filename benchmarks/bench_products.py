"""Benchmark: reading and drawing the products (doc/python.md, issue 34's goals:
cdea.load of a 1000-step run file at most 50 ms, postprocess/plot.py on any
product at most 3 s).

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/bench_products.py \\
        [VOLTAGE_INCREMENT_KV] [REPEATS]

Makes, with the program (CDEA_EXECUTABLE, default build/cdea) in a
temporary folder, prm/default.prm's run with Solver/Voltage increment (kV)
= VOLTAGE_INCREMENT_KV (default 0.005: 1006 steps), its response, the
viscoelastic chart and the DMA fit of prm/fit-dma.prm; then prints the median
over REPEATS (default 7) of the wall time of cdea.load of the run file, and
of a `plot.py FILE -o OUT.png` process on each file (interpreter start-up
included, as a user pays it), with its CPU time. Fails (exit 1) if the loaded run differs from
the file's step count or a picture is not written. ctest smoke-runs it with
`0.25 1` (label bench-smoke)."""

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import cdea

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, ".."))
PRM = os.path.join(REPO, "prm")


def median_seconds(f, repeats):
    """Median wall time of f, and median CPU time of the processes f ran
    (user + system; on a shared machine the wall time waits for the cores)."""
    times, cpu = [], []
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return statistics.median(times), statistics.median(cpu)


def main():
    increment = sys.argv[1] if len(sys.argv) > 1 else "0.005"
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    exe = os.path.abspath(os.environ.get("CDEA_EXECUTABLE", os.path.join(REPO, "build", "cdea")))
    with tempfile.TemporaryDirectory() as folder:
        def command(*args):
            subprocess.run([exe, *args, "--set", f"Output/Directory={folder}"], check=True,
                           capture_output=True, cwd=PRM)
        command("run", "default.prm", "--set", f"Solver/Voltage increment (kV)={increment}")
        command("response", "response.prm")
        command("chart", "fit-dma.prm")
        command("fit", "fit-dma.prm", "fit-dma.csv")
        run_file = os.path.join(folder, "default.h5")
        loaded = cdea.load(run_file)
        steps = len(loaded)
        if steps != len(loaded.summary["displacement_mm"]) or not loaded.completed:
            print("bench_products: the loaded run does not hold its file's steps")
            return 1
        print(f"cdea.load of a run file of {steps} steps: "
              f"{1e3 * median_seconds(lambda: cdea.load(run_file), repeats)[0]:.1f} ms "
              f"(median of {repeats}; goal: at most 50 ms for 1000 steps)")
        for name in ("default.h5", "response_response.h5", "fit-dma_chart.h5",
                     "fit-dma_fit.h5"):
            out = os.path.join(folder, name + ".png")

            def draw():
                subprocess.run(["/usr/bin/python3", os.path.join(REPO, "postprocess", "plot.py"),
                                os.path.join(folder, name), "-o", out],
                               check=True, capture_output=True)
            seconds, cpu = median_seconds(draw, repeats)
            if not os.path.getsize(out):
                print(f"bench_products: plot.py wrote no picture of {name}")
                return 1
            print(f"plot.py {name}: {seconds:.2f} s, CPU {cpu:.2f} s (medians of {repeats} "
                  "processes; goal: at most 3 s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
