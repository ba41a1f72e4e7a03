"""postprocess/sweep_mass.py, the notebook-style example of the Python module,
run as a user runs it: it writes its PNG, and its table holds what cdea.run
gives for the same mass (a heavier weight deflects the disk further). Run by
ctest (PYTHONPATH=build/python, python3-matplotlib)."""

import os
import subprocess
import sys

import pytest

import cdea

SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))


def test_sweep_mass_example(tmp_path):
    out = tmp_path / "figure" / "mass.png"
    done = subprocess.run([sys.executable, os.path.join(SRC, "postprocess", "sweep_mass.py"),
                           "--out", str(out), "--masses", "150, 250, 350"],
                          cwd=str(tmp_path), capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    with open(out, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert out.stat().st_size > 20000
    assert os.listdir(tmp_path) == ["figure"]  # nothing else written
    rows = [line.split() for line in done.stdout.splitlines()
            if line.split() and line.split()[0] in ("150", "250", "350")]
    assert [r[0] for r in rows] == ["150", "250", "350"]
    deflection = [float(r[1]) for r in rows]
    assert deflection[0] < deflection[1] < deflection[2]
    reference = cdea.run(os.path.join(SRC, "prm", "default.prm"), {"Loading/Mass (g)": 250})
    s = reference.summary
    assert float(rows[1][1]) == pytest.approx(s["displacement_mm"][s["stage"] == 1][-1], abs=1e-6)
    assert float(rows[1][3]) == pytest.approx(s["stroke_mm"][-1], abs=1e-6)
