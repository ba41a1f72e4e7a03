"""postprocess/sweep_mass.py, the notebook-style example of the Python module,
run as a user runs it: it writes its PNG, and its table holds what cdea.run
gives for the same mass (a heavier weight deflects the disk further); run as a
Jupyter cell (exec, no __file__) it finds the repository from CDEA_SOURCE_DIR
or the working directory, or says how to name it. Run by
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


def run_as_cell(tmp_path, cwd, source_dir):
    """The script run by exec as a Jupyter cell runs it (no __file__), in cwd,
    with CDEA_SOURCE_DIR set to source_dir (None: unset)."""
    out = tmp_path / "cell.png"
    code = ("import sys\nsys.argv = ['kernel', '--out', %r, '--masses', '250']\n"
            "exec(open(%r).read(), {'__name__': '__main__'})\n"
            % (str(out), os.path.join(SRC, "postprocess", "sweep_mass.py")))
    env = dict(os.environ)
    env.pop("CDEA_SOURCE_DIR", None)
    if source_dir:
        env["CDEA_SOURCE_DIR"] = source_dir
    done = subprocess.run([sys.executable, "-c", code], cwd=str(cwd), env=env,
                          capture_output=True, text=True, timeout=300)
    return done, out


def test_sweep_mass_runs_as_a_notebook_cell(tmp_path):
    # The repository from CDEA_SOURCE_DIR, or from the working directory.
    for cwd, source_dir in ((tmp_path, os.path.abspath(SRC)),
                            (os.path.join(SRC, "postprocess"), None)):
        done, out = run_as_cell(tmp_path, cwd, source_dir)
        assert done.returncode == 0, done.stderr
        assert out.stat().st_size > 20000
        out.unlink()
    # Neither: a clear message naming the variable, and nothing written.
    done, out = run_as_cell(tmp_path, tmp_path, None)
    assert done.returncode == 1
    assert "CDEA_SOURCE_DIR" in done.stderr and "prm/default.prm" in done.stderr
    assert not out.exists()
