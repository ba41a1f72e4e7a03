"""The Python module's answers to inputs it cannot use (issues 22, 31): fields()
names the steps it has, overrides must be a dict, include loops are refused,
write(path) creates no folder and replaces only a regular file, a fit whose start cannot reach a point returns (not converged, the
point named, standard errors NaN); plot_run.py puts a time run over time."""
import math
import os
import subprocess
import sys

import pytest

import cdea

SRC = os.environ["CDEA_SOURCE_DIR"]
DEFAULT = os.path.join(SRC, "prm", "default.prm")


def test_fields_names_the_range():
    r = cdea.run(DEFAULT)
    assert len(r.fields(-26)["r"]) > 0 and len(r.fields(25)["r"]) > 0
    for step in (-27, 26):
        with pytest.raises(IndexError) as raised:
            r.fields(step)
        assert str(raised.value) == (f"step {step} is not one of the 26 steps (0 to 25, or -26 "
                                     "to -1 from the end)")


def test_overrides_must_be_a_dict():
    with pytest.raises(TypeError, match=r"overrides must be a dict \{'Subsection/Entry': value\}"
                       r".*got str 'Loading/Mass \(g\)=300'"):
        cdea.run(DEFAULT, overrides="Loading/Mass (g)=300")
    with pytest.raises(TypeError, match="overrides must be a dict"):
        cdea.parameters("", overrides=[("Loading/Mass (g)", 300)])
    assert cdea.run(DEFAULT, overrides={"Loading/Mass (g)": 300}).completed


def test_override_values_refused_with_the_entry():
    with pytest.raises(ValueError, match=r"Material/Jlim must be a finite number, got 'inf'"):
        cdea.parameters("", overrides={"Material/Jlim": float("inf")})
    with pytest.raises(ValueError, match="'#' starts a comment"):
        cdea.parameters("", overrides={"Output/Base name": "a#b"})
    with pytest.raises(ValueError, match="in parameter text: line 3: 'end' without a subsection"):
        cdea.parameters("subsection Loading\nend\nend\n")


def test_write_creates_no_chain_of_folders(tmp_path):
    r = cdea.run(DEFAULT)
    missing = tmp_path / "nonexistent" / "dir"
    with pytest.raises(FileNotFoundError, match="the directory '.*nonexistent' does not exist"):
        r.write(str(missing / "x.h5"))
    assert not (tmp_path / "nonexistent").exists()
    with pytest.raises(FileNotFoundError):
        r.write("/nonexistent-cdea-test/dir/x.h5")
    assert not os.path.exists("/nonexistent-cdea-test")
    assert r.write(str(tmp_path / "sub" / "x.h5")) == str(tmp_path / "sub" / "x.h5")


def test_include_loops_refused(tmp_path, monkeypatch):
    """Issue 31, item 2: an include loop is a ValueError with the chain, not a
    stack overflow of the interpreter; an include is read as the main file."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "self.prm").write_text("include self.prm\n")
    with pytest.raises(ValueError, match=r"cannot include 'self.prm': it is this file itself, "
                       r"an include loop: self.prm line 1 -> self.prm"):
        cdea.parameters("self.prm")
    with pytest.raises(ValueError, match=r"in parameter file 'self.prm' \(included from the "
                       r"parameter text line 2\): line 1: cannot include 'self.prm'"):
        cdea.parameters("# a loop\ninclude self.prm\n")
    (tmp_path / "mass.prm").write_text("set Mass (g) = 300\r\n")
    text = cdea.parameters("subsection Loading\r\n  include mass.prm\rend\n")
    assert "set Mass (g)        = 300" in text


def test_write_refuses_what_is_not_a_file_of_its_own(tmp_path):
    """Issue 31, items 3 and 4: write() replaces a regular file or nothing;
    an empty name, a FIFO or a link is refused and left as it was."""
    r = cdea.run(DEFAULT, overrides={"Solver/Voltage increment (kV)": 1})
    with pytest.raises(OSError, match="'' names no file"):
        r.write("")
    fifo, link, target = tmp_path / "fifo.h5", tmp_path / "link.h5", tmp_path / "target"
    os.mkfifo(fifo)
    target.write_text("someone else's")
    os.symlink(target, link)
    for path, kind in ((fifo, "a FIFO"), (link, "a symbolic link")):
        with pytest.raises(OSError, match=f"it is {kind}"):
            r.write(str(path))
    assert fifo.is_fifo() and link.is_symlink() and target.read_text() == "someone else's"
    assert sorted(os.listdir(tmp_path)) == ["fifo.h5", "link.h5", "target"]


def test_fit_start_beyond_the_fold(tmp_path):
    data = open(os.path.join(SRC, "prm", "fit-example.csv")).read() + "5.00, 7.20, 31.0\n"
    f = cdea.fit(os.path.join(SRC, "prm", "fit-example.prm"), data)
    assert not f.converged
    status = f.attributes["status"]
    assert status.startswith("the fit cannot start: data point 21 (5, 7.2 kV) cannot be reached")
    assert "nor from data point 20 (5, 6.5 kV)" in status
    assert all(math.isnan(e) for e in f.standard_errors.values())
    assert f.values == {"shear modulus (Pa)": 20000.0, "Jlim": 150.0}


def test_fit_data_checked():
    prm = os.path.join(SRC, "prm", "fit-example.prm")
    for csv, message in [("\ufeffV1_kV, V2_kV, displacement_mm\n1, 1, -18\n",
                          "data, line 2, column displacement_mm: a displacement is the distance"),
                         ("V1_kV, V2_kV, displacement_mm\n1, 1700, 18\n",
                          "data, line 2, column V2_kV: 1700 kV is above the ceiling"),
                         ("V1_kV, V2_kV, displacement_mm\n1, 1\n",
                          "data, line 2: 2 fields, but the header has 3")]:
        with pytest.raises(ValueError, match=message.replace("(", r"\(").replace("|", r"\|")):
            cdea.fit(prm, csv)


def test_plot_run_puts_a_time_run_over_time(tmp_path):
    text = open(os.path.join(SRC, "prm", "pump-time.prm")).read()
    r = cdea.run(text, overrides={"Time/Cycles": 1, "Time/Time step (s)": 0.05})
    path = r.write(str(tmp_path / "pump-time.h5"))
    sys.path.insert(0, os.path.join(SRC, "postprocess"))
    import plot_run
    run = plot_run.Run(path)
    rows = run.rows(plot_run.STAGE_VOLTAGE)
    x, label = run.x_axis(rows)
    assert label == "time t (s)" and x[-1] == pytest.approx(2.0)
    done = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "postprocess", "plot_run.py"),
                           path, "--out", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
