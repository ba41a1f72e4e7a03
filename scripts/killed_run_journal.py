"""The journal a killed `cdea run` leaves, made the same for every build: the
run is started, copied from while it writes, killed once its journal holds
STEPS steps, and the copy is cut after the record of step STEPS (the records
before it are what the run wrote by then, whichever build wrote them). For
scripts/product_outputs.sh's case of `cdea recover`.

    killed_run_journal.py CDEA PRM STEPS RESULTS JOURNAL [cdea run arguments ...]

RESULTS is the run's results file (its journal is RESULTS.journal); the cut
copy goes to JOURNAL. Exits 1 if the run ends before its journal holds
STEPS steps.
"""
import signal
import struct
import subprocess
import sys
import time

MAGIC = 8  # bytes of the journal's magic ("CDEAJNL" and the format digit)
FRAME = 9  # a record's type (1 byte), payload length (4) and CRC-32 (4)
STEP = 3   # the type of a step's record


def step_end(data, steps):
    """The byte offset just after the record of step `steps`, or None."""
    at, seen = MAGIC, 0
    while at + FRAME <= len(data):
        (length,) = struct.unpack_from("=I", data, at + 1)
        end = at + FRAME + length
        if end > len(data):
            return None
        seen += data[at] == STEP
        if seen == steps:
            return end
        at = end
    return None


def main():
    cdea, prm, steps = sys.argv[1], sys.argv[2], int(sys.argv[3])
    journal, target = sys.argv[4] + ".journal", sys.argv[5]
    run = subprocess.Popen([cdea, "run", prm] + sys.argv[6:], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
    end, data = None, b""
    while end is None and run.poll() is None:
        try:
            with open(journal, "rb") as f:
                data = f.read()
            end = step_end(data, steps)
        except FileNotFoundError:
            pass
        if end is None:
            time.sleep(0.002)
    run.send_signal(signal.SIGKILL)
    run.wait()
    if end is None:
        sys.exit(f"killed_run_journal: the run ended before its journal held {steps} steps")
    with open(target, "wb") as f:
        f.write(data[:end])


if __name__ == "__main__":
    main()
