"""Seeded fuzzer of the Python module's inputs, in-process (a worker process
runs the cases one after another; this parent watches it).

  csv  mutated copies of prm/fit-example.csv (numbers replaced by extremes,
       negative, NaN or huge ones, lines deleted, repeated, swapped or cut,
       bytes and byte order marks inserted, separators and columns added,
       points beyond the fold) given as CSV text to cdea.fit() (at most 2
       iterations); every 10th case also to `cdea fit` as a file.
  prm  mutated copies of the files in prm/ given as prm text to
       cdea.parameters() with mutated overrides (wrong types, '#', NaN, lists,
       huge values, unknown keys), then, if they are valid, to cdea.run().

A case passes when the call returns or raises ValueError, TypeError, OSError
or IndexError with a message of one line; it fails on a crash of the worker,
any other exception, a message with a stack trace, or a case that takes more
than LIMIT seconds (then checked again by the command line: `cdea run` must
stop on SIGINT). `cdea fit` must exit 0, 1 or 2 without a stack trace or a
lock left behind.
Usage: fuzz_python.py SOURCE_DIR CDEA_EXECUTABLE csv|prm CASES SEED [LIMIT]
(the module from PYTHONPATH)
"""
import math
import os
import random
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

BAD_TEXT = re.compile(r"[Ss]tacktrace|An error occurred in line|terminate called|"
                      r"Segmentation fault|Traceback|what\(\):|Unable to cast")
NUMBERS = ["0", "-0", "-1", "-18.2", "1e-320", "1e306", "-1e306", "1e400", "nan", "NaN", "inf",
           "-inf", "", " ", "abc", "1,5", "0x10", "1e", "+", "7.2", "9", "1600", "1601", "99999",
           "1" * 400, "\xff", "5.00.1", "--1", "1_000", "٣", "1, " * 200000]


def csv_case(rng, text):
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(["number", "number", "number", "delete", "repeat", "swap", "cut",
                           "bytes", "bom", "separator", "column", "fold", "crlf", "many"])
        data = [i for i, l in enumerate(lines) if l and l[0].isdigit()]
        i = rng.randrange(len(lines)) if lines else 0
        if kind == "number" and data:
            i = rng.choice(data)
            fields = lines[i].split(",")
            fields[rng.randrange(len(fields))] = " " + rng.choice(NUMBERS)
            lines[i] = ",".join(fields)
        elif kind == "delete" and lines:
            del lines[i]
        elif kind == "repeat" and lines:
            lines.insert(rng.randrange(len(lines) + 1), lines[i])
        elif kind == "swap" and len(lines) > 1:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind == "cut":
            joined = "\n".join(lines)
            lines = joined[:rng.randrange(len(joined) + 1)].split("\n")
        elif kind == "bom":
            lines.insert(0, "\ufeff" + (lines.pop(0) if lines else ""))
        elif kind == "separator" and lines:
            lines[i] += rng.choice([",", ";", ",,", "\t", " ,"])
        elif kind == "column" and lines:
            lines[i] = lines[i] + rng.choice([", weight", ", 1", ", V3_kV", ", displacement_mm"])
        elif kind == "fold":
            lines.append(rng.choice(["5.00, 7.20, 31.0", "8, 8, 40", "0, 9, 25", "7, 0, 30"]))
        elif kind == "crlf":
            lines = [l + "\r" for l in lines]
        elif kind == "many" and data:
            lines += [lines[rng.choice(data)]] * rng.choice([50, 300])
        else:
            joined = "\n".join(lines)
            at = rng.randrange(len(joined) + 1)
            noise = "".join(chr(rng.randrange(1, 0x2FF)) for _ in range(rng.randint(1, 6)))
            lines = (joined[:at] + noise + joined[at:]).split("\n")
    return "\n".join(lines) + "\n"


OVERRIDE_VALUES = [300, -1, 0, 1e306, float("nan"), float("inf"), "nan", "inf", "abc", "a#b",
                   "", [1, 2], [[5, 5], [5, 6.5]], [], [[]], True, None, {"a": 1}, (1,),
                   "x" * 100000, 2 ** 70, "1, 1.7, 3", "arc length", "relaxed", 1.5]
OVERRIDE_KEYS = ["Loading/Mass (g)", "Material/Jlim", "Electrodes/Ring edges (r/a)",
                 "Electrodes/Voltage path (kV)", "Output/Base name", "Output/Directory",
                 "Solver/Continuation", "Wrinkling/Model", "Loading/Mass (kg)", "Mass (g)",
                 "/", "Loading/", "", "Time/Enabled", "Geometry/Prestretch",
                 "Discretization/Polynomial degree", "Solver/Voltage increment (kV)"]


def prm_case(rng, texts):
    name = rng.choice(sorted(texts))
    lines = texts[name].split("\n")
    for _ in range(rng.randint(0, 3)):
        kind = rng.choice(["value", "value", "delete", "repeat", "swap", "bytes", "end"])
        sets = [i for i, l in enumerate(lines) if "=" in l and l.strip().startswith("set")]
        i = rng.randrange(len(lines)) if lines else 0
        if kind == "value" and sets:
            i = rng.choice(sets)
            lines[i] = lines[i].split("=", 1)[0] + "= " + rng.choice(NUMBERS + ["a#b", "1 # x",
                                                                                "inf", "-nan"])
        elif kind == "delete" and lines:
            del lines[i]
        elif kind == "repeat" and lines:
            lines.insert(rng.randrange(len(lines) + 1), lines[i])
        elif kind == "swap" and len(lines) > 1:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind == "end":
            lines.insert(rng.randrange(len(lines) + 1), rng.choice(["end", "subsection Loading",
                                                                    "END", "subsection X"]))
        else:
            joined = "\n".join(lines)
            at = rng.randrange(len(joined) + 1)
            noise = "".join(chr(rng.randrange(1, 0x2FF)) for _ in range(rng.randint(1, 6)))
            lines = (joined[:at] + noise + joined[at:]).split("\n")
    text = "\n".join(lines) + "\n"
    overrides = None
    roll = rng.random()
    if roll < 0.5:
        overrides = {rng.choice(OVERRIDE_KEYS): rng.choice(OVERRIDE_VALUES)
                     for _ in range(rng.randint(1, 3))}
    elif roll < 0.6:
        overrides = rng.choice(["Loading/Mass (g)=300", [("a", 1)], 5, b"x"])
    return name, text, overrides


def one_line(e):
    message = str(e)
    return "\n" not in message.strip() and not BAD_TEXT.search(message)


def worker(src, mode, seed):
    """Reads case numbers from stdin, answers 'N ok|error ...' per case."""
    import cdea
    csv = open(os.path.join(src, "prm", "fit-example.csv")).read()
    fit_prm = open(os.path.join(src, "prm", "fit-example.prm")).read()
    texts = {}
    for f in sorted(os.listdir(os.path.join(src, "prm"))):
        if f.endswith(".prm"):
            texts[f] = open(os.path.join(src, "prm", f), errors="replace").read()
    for line in sys.stdin:
        index = int(line)
        rng = random.Random(seed * 1000003 + index)
        try:
            if mode == "csv":
                cdea.fit(fit_prm, csv_case(rng, csv), {"Calibration/Max iterations": 2})
            else:
                _, text, overrides = prm_case(rng, texts)
                cdea.parameters(text, overrides)
                r = cdea.run(text, overrides)
                assert isinstance(r.completed, bool) and math.isfinite(r.seconds)
            verdict = "ok"
        except (ValueError, TypeError, OSError, IndexError) as e:
            verdict = "ok " + type(e).__name__ if one_line(e) else \
                "FAIL message: " + repr(str(e))[:300]
        except Exception as e:  # noqa: BLE001 -- anything else is the finding
            verdict = "FAIL " + type(e).__name__ + ": " + repr(str(e))[:300]
        print(index, verdict, flush=True)


def command_line_fit(exe, src, rng_seed, index, work):
    """`cdea fit` on the case's CSV as a file: exit 0, 1 or 2, one-line
    messages, no lock left."""
    rng = random.Random(rng_seed * 1000003 + index)
    with open(os.path.join(work, "data.csv"), "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write(csv_case(rng, open(os.path.join(src, "prm", "fit-example.csv")).read()))
    shutil.copy(os.path.join(src, "prm", "fit-example.prm"), os.path.join(work, "fit.prm"))
    done = subprocess.run([exe, "fit", "fit.prm", "data.csv", "--set", "Calibration/Max iterations=2"],
                          cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    err = done.stderr.decode(errors="replace")
    left = [f for f in os.listdir(os.path.join(work, "results"))] \
        if os.path.isdir(os.path.join(work, "results")) else []
    problems = []
    if done.returncode not in (0, 1, 2):
        problems.append(f"cdea fit exit {done.returncode}")
    if BAD_TEXT.search(err):
        problems.append("a stack trace on stderr")
    if any(f.endswith(".lock") for f in left):
        problems.append(f"a lock left: {left}")
    if done.returncode == 1 and left:
        problems.append(f"exit 1 but left {left}")
    shutil.rmtree(os.path.join(work, "results"), ignore_errors=True)
    return problems, err


def interrupted_on_command_line(exe, src, seed, index, work):
    """A prm case that ran longer than the limit in-process: as `cdea run` it
    must stop on SIGINT within 20 s (a long run, not a hang)."""
    rng = random.Random(seed * 1000003 + index)
    texts = {f: open(os.path.join(src, "prm", f), errors="replace").read()
             for f in sorted(os.listdir(os.path.join(src, "prm"))) if f.endswith(".prm")}
    _, text, _ = prm_case(rng, texts)
    with open(os.path.join(work, "case.prm"), "w", errors="surrogateescape") as f:
        f.write(text)
    p = subprocess.Popen([exe, "run", "case.prm"], cwd=work, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    try:
        return p.wait(timeout=20) in (0, 1, 2, -signal.SIGINT)
    except subprocess.TimeoutExpired:
        p.kill()
        return False


def main(argv):
    src, exe = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    mode, cases, seed = argv[2], int(argv[3]), int(argv[4])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p))
    limit = float(argv[5]) if len(argv) > 5 else 10.0
    work = tempfile.mkdtemp(prefix="cdea-fuzz-py-")
    failures, counts, slow = [], {}, 0
    start = time.time()
    index = 0
    while index < cases:
        w = subprocess.Popen([sys.executable, __file__, "--worker", src, mode, str(seed)],
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE, cwd=work, text=True,
                             env=env)
        while index < cases:
            w.stdin.write(f"{index}\n")
            w.stdin.flush()
            ready, _, _ = select.select([w.stdout], [], [], limit)
            answer = w.stdout.readline() if ready else ""
            if not answer:
                w.kill()
                w.wait()
                if not ready and mode == "prm" and interrupted_on_command_line(exe, src, seed,
                                                                               index, work):
                    slow += 1  # a long run: the command line stops it on SIGINT
                else:
                    failures.append(f"case {index}: " + ("hang" if not ready else
                                                         f"worker died ({w.returncode})"))
                index += 1
                break
            verdict = answer.split(" ", 1)[1].strip()
            counts[verdict.split(":")[0]] = counts.get(verdict.split(":")[0], 0) + 1
            if verdict.startswith("FAIL"):
                failures.append(f"case {index}: {verdict}")
            if mode == "csv" and index % 10 == 0:
                problems, err = command_line_fit(exe, src, seed, index, work)
                failures += [f"case {index} (cdea fit): {p}: {err[-300:]!r}" for p in problems]
            index += 1
        else:
            w.stdin.close()
            w.wait()
    shutil.rmtree(work, ignore_errors=True)
    print(f"{cases} {mode} cases (seed {seed}) in {time.time() - start:.1f} s: "
          + ", ".join(f"{v} {k}" for k, v in sorted(counts.items()))
          + (f", {slow} longer than {limit} s in-process (stopped by SIGINT as commands)"
             if slow else ""))
    for f in failures:
        print("FAIL", f)
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    if sys.argv[1] == "--worker":
        worker(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    else:
        sys.exit(main(sys.argv[1:]))
