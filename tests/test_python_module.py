"""The Python module `cdea` against the command line. For the same parameters,
cdea.run / cdea.shoot / cdea.sweep give every /summary column, every /steps
field and every attribute of the file `cdea run` / `cdea shoot` / `cdea sweep`
writes (same names, units and numbers); overrides act as edits of the file;
bad input raises ValueError with the message the command prints; a run that
stops early returns its steps and says why; nothing is written until write(),
whose file h5py reads back as the command's. Run by ctest (python3-pytest,
python3-h5py, PYTHONPATH=build/python)."""

import os
import re
import subprocess
import sys

import h5py
import numpy as np
import pytest

import cdea

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))


def prm_text(name, base="out", extra=""):
    """prm/<name> writing to out/<base>*.h5, with extra lines appended."""
    with open(os.path.join(SRC, "prm", name)) as f:
        text = f.read()
    return (text + "\nsubsection Output\n  set Directory = out\n  set Base name = " + base
            + "\nend\n" + extra)


def command(tmp, verb, text, base="out"):
    """`cdea VERB` on text (written to tmp/<base>.prm) in tmp; (process, prm path)."""
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    path = os.path.join(str(tmp), base + ".prm")
    with open(path, "w") as f:
        f.write(text)
    done = subprocess.run([EXE, verb, path], cwd=str(tmp), capture_output=True, text=True)
    return done, path


def both(tmp, verb, text, function, returncode):
    """`cdea VERB` and the module's function on the same parameter file."""
    done, path = command(tmp, verb, text)
    assert done.returncode == returncode, done.stderr
    return done, path, function(path)


def cli_message(done):
    """The command's one-line message on stderr without the 'cdea: ' prefix."""
    lines = [l for l in done.stderr.splitlines()
             if l.startswith("cdea: ") and not l.startswith("cdea: warning: ")]
    assert lines, done.stderr
    return lines[0][len("cdea: "):]


def value(x):
    """An HDF5 attribute or dataset value as numpy (h5py.Empty: an empty array)."""
    if isinstance(x, h5py.Empty):
        return np.zeros(0)
    if isinstance(x, bytes):
        return x.decode()
    return x


def assert_same(a, b, what):
    a, b = value(a), value(b)
    if isinstance(a, str) or isinstance(b, str):
        assert a == b, what
        return
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, what
    assert a.dtype.kind == b.dtype.kind, (what, a.dtype, b.dtype)
    np.testing.assert_array_equal(a, b, err_msg=what)  # NaN equals NaN here


def assert_run_equals_file(result, path):
    """Every /summary dataset, attribute and /steps field of the file at path."""
    with h5py.File(path, "r") as f:
        s = f["summary"]
        assert sorted(result.summary) == sorted(s.keys())
        for name, data in s.items():
            assert_same(result.summary[name], data[()], "summary/" + name)
            assert result.columns[name] == (data.attrs["unit"], data.attrs["description"]), name
        attributes = result.attributes
        assert sorted(attributes) == sorted(s.attrs.keys())
        for name in s.attrs:
            assert_same(attributes[name], s.attrs[name], "summary attribute " + name)
        steps = f["steps"]
        assert len(steps) == result.n_steps == len(result)
        for i, key in enumerate(sorted(steps)):
            fields = result.fields(i)
            assert sorted(fields) == sorted(steps[key].keys())
            for name, data in steps[key].items():
                assert_same(fields[name], data[()], "steps/%s/%s" % (key, name))
        assert f.attrs["parameters"] == result.parameters
        assert f.attrs["method"] == result.method
        assert int(f.attrs["n_rings"]) == result.n_rings


# Through the folds: arc length to 8 kV on the outer ring, with the breakdown check.
FOLDS = ("subsection Electrodes\n  set Voltage path (kV) = 5, 5; 5, 8\nend\n"
         "subsection Solver\n  set Continuation = arc length\n"
         "  set Breakdown field (MV/m) = 30\nend\n")


@pytest.mark.parametrize("name,extra", [("default.prm", ""), ("partitioned-rv1.7.prm", ""),
                                        ("partitioned-rv1.7.prm", FOLDS)])
def test_run_equals_the_command_line_file(tmp_path, name, extra):
    done, path, result = both(tmp_path, "run", prm_text(name, extra=extra), cdea.run, 0)
    assert result.completed and result.message == ""
    assert_run_equals_file(result, tmp_path / "out" / "out.h5")
    s = result.summary
    if extra:
        # Two folds, where the path parameter t turns back and forth: the outer
        # voltage is largest at the first of all steps before it, smallest at the
        # second of all steps between them.
        limits = result.attributes["limit_point_voltage_kV"]
        assert limits.shape == (2, 2) and result.end
        on_path = s["stage"] == 2
        t, outer = s["load_factor"][on_path], s["voltage_kV"][on_path, 1]
        turns = np.nonzero(np.diff(np.sign(np.diff(t))))[0] + 1
        assert len(turns) == 2
        assert outer[:turns[0] + 1].max() <= limits[0, 1] + 1e-9
        assert outer[turns[0]:turns[1] + 1].min() >= limits[1, 1] - 1e-9
        assert limits[1, 1] < limits[0, 1] < 8
        assert "breakdown_voltage_kV" in result.attributes
        return
    # The run's physics, not only its bookkeeping: the stroke grows with the voltage.
    voltage = s["stage"] == 2
    assert np.all(np.diff(s["stroke_mm"][voltage]) > 0)
    if name == "partitioned-rv1.7.prm":
        # Both rings to 5 kV, then the outer to 6.5 kV: the outer ring's inner edge loses tension.
        assert result.onset is not None
        assert result.onset["voltage_kV"][0] == pytest.approx(5.0)
        assert 5.0 < result.onset["voltage_kV"][1] < 6.5
        assert result.onset["radius_mm"] == pytest.approx(1.7 * 14, rel=1e-6)


def test_nothing_written_until_write(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = cdea.run(prm_text("default.prm", base="quiet", extra="subsection Output\n"
                               "  set ParaView = true\nend\n"))
    assert os.listdir(tmp_path) == []
    assert result.results_path == "out/quiet.h5"
    assert result.write() == "out/quiet.h5"
    assert sorted(os.listdir(tmp_path / "out")) == ["quiet.h5"]


def test_write_round_trip(tmp_path):
    result = cdea.run(os.path.join(SRC, "prm", "partitioned-rv1.7.prm"))
    path = tmp_path / "sub" / "again.h5"
    assert result.write(path) == str(path)
    assert_run_equals_file(result, path)
    with pytest.raises(OSError, match="no-such-dir-parent"):
        blocker = tmp_path / "no-such-dir-parent"
        blocker.write_text("a file, not a folder")
        result.write(blocker / "x.h5")


def test_overrides_act_as_edits_of_the_file():
    default = os.path.join(SRC, "prm", "default.prm")
    edited = cdea.run(prm_text("default.prm", extra="subsection Loading\n  set Mass (g) = 300\n"
                               "end\nsubsection Electrodes\n  set Voltage path (kV) = 4\nend\n"))
    overridden = cdea.run(default, overrides={"Loading/Mass (g)": 300,
                                              "Electrodes/Voltage path (kV)": "4",
                                              "Output/Directory": "out",
                                              "Output/Base name": "out"})
    assert overridden.parameters == edited.parameters
    assert re.search(r"set Mass \(g\) *= 300\n", overridden.parameters)
    for name in edited.summary:
        assert_same(overridden.summary[name], edited.summary[name], name)
    assert overridden.summary["mass_g"][-1] == 300
    assert overridden.summary["voltage_kV"][-1, 0] == pytest.approx(4.0)
    # A two-ring layout from lists: the same run as prm/partitioned-rv1.7.prm.
    listed = cdea.run(default, overrides={"Electrodes/Ring edges (r/a)": [1, 1.7, 3],
                                          "Electrodes/Voltage path (kV)": [[5, 5], [5, 6.5]]})
    reference = cdea.run(os.path.join(SRC, "prm", "partitioned-rv1.7.prm"))
    for name in reference.summary:
        assert_same(listed.summary[name], reference.summary[name], name)
    # Heavier weights pull the disk further down (zero voltage, end of the load stage).
    loaded = [cdea.run(default, {"Loading/Mass (g)": m, "Electrodes/Voltage path (kV)": 0})
              for m in (100, 200, 300)]
    deflection = [r.summary["displacement_mm"][r.summary["stage"] == 1][-1] for r in loaded]
    assert deflection[0] < deflection[1] < deflection[2]
    # Overrides come after the file and have the last word.
    text = cdea.parameters(default, {"Loading/Mass (g)": 123})
    assert re.search(r"set Mass \(g\) *= 123\n", text)


BAD_FILES = [
    # (edit of prm/default.prm, override doing the same or None)
    (("Frame radius (mm)   = 42", "Frame radius (mm)   = 10"), ("Geometry/Frame radius (mm)", 10)),
    (("Jlim                = 270", "Jlim                = 9"), ("Material/Jlim", "9")),
    (("Voltage path (kV)   = 5", "Voltage path (kV)   = 5, 6"),
     ("Electrodes/Voltage path (kV)", [5, 6])),
    (("Ring edges (r/a)    = 1, 3", "Ring edges (r/a)    = 1, two, 3"),
     ("Electrodes/Ring edges (r/a)", "1, two, 3")),
    (("Mass (g)            = 280", "Mass (g)            = -5"), ("Loading/Mass (g)", -5)),
    (("set Mass (g)            = 280", "set Mass (kg) = 0.28"), None),
    (("Mass (g)            = 280", "Mass (g)            = heavy"), None),
    (("subsection Loading", "subsection Load"), None),
]


@pytest.mark.parametrize("edit,override", BAD_FILES)
def test_bad_input_raises_the_command_line_message(tmp_path, edit, override):
    with open(os.path.join(SRC, "prm", "default.prm")) as f:
        text = f.read()
    assert edit[0] in text
    text = text.replace(edit[0], edit[1]).replace("= results", "= out")
    done, path = command(tmp_path, "run", text, base="bad")
    assert done.returncode == 1
    message = cli_message(done)
    with pytest.raises(ValueError) as raised:
        cdea.run(path)
    assert str(raised.value) == message
    if override:
        with pytest.raises(ValueError) as raised:
            cdea.run(os.path.join(SRC, "prm", "default.prm"), overrides=dict([override]))
        assert str(raised.value) == message
    assert not os.path.exists(tmp_path / "out")


def test_bad_overrides_name_the_key():
    default = os.path.join(SRC, "prm", "default.prm")
    cases = {("Loading/Mass (kg)", "1"): "override 'Loading/Mass (kg)': subsection Loading has "
                                          "no entry 'Mass (kg)'",
             ("Load/Mass (g)", "1"): "override 'Load/Mass (g)': there is no subsection 'Load'",
             ("Mass (g)", "1"): "override 'Mass (g)': expected 'Subsection/Entry'",
             ("Loading/Mass (g)", "heavy"): "override 'Loading/Mass (g)' = 'heavy': "
                                            "Loading/Mass (g) must be a number, got 'heavy'",
             ("Discretization/Polynomial degree", "1.5"):
                 "override 'Discretization/Polynomial degree' = '1.5': Discretization/Polynomial "
                 "degree must be a whole number from 1 to 8, got '1.5'"}
    for (key, val), start in cases.items():
        with pytest.raises(ValueError) as raised:
            cdea.run(default, overrides={key: val})
        assert str(raised.value).startswith(start), str(raised.value)
    with pytest.raises(TypeError, match="override 'Loading/Mass \\(g\\)'"):
        cdea.run(default, overrides={"Loading/Mass (g)": {"not": "a value"}})
    with pytest.raises(FileNotFoundError) as raised:
        cdea.run("no-such-file.prm")
    assert str(raised.value) == ("cannot read parameter file 'no-such-file.prm': it does not "
                                 "exist, is not a regular file or is not readable")
    with pytest.raises(ValueError) as raised:
        cdea.run("subsection Loading\n  set Mass (kg) = 1\nend\n")
    assert str(raised.value) == ("in parameter text: line 2: subsection Loading has no entry "
                                 "'Mass (kg)' (cdea print-parameters lists every parameter)")


def test_early_stop_returns_its_steps(tmp_path):
    # Load stepping past the fold of the full electrode (about 6.9 kV).
    text = prm_text("default.prm", extra="subsection Electrodes\n  set Voltage path (kV) = 8\n"
                    "end\nsubsection Solver\n  set Stability check = false\nend\n")
    done, path, result = both(tmp_path, "run", text, cdea.run, 2)
    assert not result.completed
    assert "cdea: the run stopped early: " + result.message in done.stderr
    assert result.message and result.n_steps > 10
    assert_run_equals_file(result, tmp_path / "out" / "out.h5")
    last = result.summary["voltage_kV"][-1, 0]
    assert 6.0 < last < 8.0


def test_shoot_equals_the_command_line_file(tmp_path):
    text = prm_text("default.prm", extra="subsection Solver\n  set Continuation = arc length\n"
                    "end\n")
    done, path, result = both(tmp_path, "shoot", text, cdea.shoot, 0)
    assert result.method == "shooting" and result.completed
    assert result.results_path == "out/out_shooting.h5"
    assert result.notes and result.notes[0] in done.stdout
    assert_run_equals_file(result, tmp_path / "out" / "out_shooting.h5")
    # The two solvers of one scene agree (doc/validation.md: 1e-5 in displacement).
    fe = cdea.run(path, {"Solver/Continuation": "load stepping"})
    np.testing.assert_allclose(result.summary["displacement_mm"], fe.summary["displacement_mm"],
                               rtol=1e-5)
    # FE-only options: the command's refusal.
    bad = prm_text("default.prm", extra="subsection Wrinkling\n  set Model = relaxed\nend\n")
    done, path = command(tmp_path, "shoot", bad, base="relaxed")
    assert done.returncode == 1
    with pytest.raises(ValueError) as raised:
        cdea.shoot(path)
    assert str(raised.value) == cli_message(done)


SMALL_MAP = ("subsection Sweep\n  set Ring edge values (r/a) = 1.5, 1.6, 1.7\n"
             "  set Outer voltage range (kV) = 5, 6.75, 0.25\nend\n")


def test_sweep_equals_the_command_line_map(tmp_path):
    done, path, result = both(tmp_path, "sweep", prm_text("sweep-inner5.prm", extra=SMALL_MAP),
                              cdea.sweep, 0)
    with h5py.File(tmp_path / "out" / "out_map.h5", "r") as f:
        arrays = result.arrays
        assert sorted(arrays) == sorted(f.keys())
        for name, data in f.items():
            if name == "stop_message":
                assert list(arrays[name]) == [m.decode() for m in data[()]]
            else:
                assert_same(arrays[name], data[()], name)
            assert result.columns[name] == (data.attrs["unit"], data.attrs["description"])
        assert sorted(result.attributes) == sorted(f.attrs.keys())
        for name in f.attrs:
            assert_same(result.attributes[name], f.attrs[name], name)
    # The red line lies inside the grid and moves up with r_v (doc/design-maps.md).
    red = arrays["red_line_outer_kV"]
    assert np.all((red > 5) & (red < 6.75)) and np.all(np.diff(red) > 0)
    written = result.write(tmp_path / "again_map.h5")
    with h5py.File(written, "r") as f, h5py.File(tmp_path / "out" / "out_map.h5", "r") as g:
        for name in g:
            if name != "stop_message":
                assert_same(f[name][()], g[name][()], name)
    bad = prm_text("sweep-inner5.prm", extra="subsection Sweep\n"
                   "  set Ring edge values (r/a) = 0.5\nend\n")
    done, path = command(tmp_path, "sweep", bad, base="badmap")
    assert done.returncode == 1
    with pytest.raises(ValueError) as raised:
        cdea.sweep(path)
    assert str(raised.value) == cli_message(done)


def test_fields_are_indexed_like_a_list():
    result = cdea.run(os.path.join(SRC, "prm", "default.prm"))
    last = result.fields(-1)
    np.testing.assert_array_equal(last["z"], result.fields(result.n_steps - 1)["z"])
    # The disk end of the meridian sits at the reported displacement.
    assert abs(last["z"][0] - last["z"][-1]) == pytest.approx(
        result.summary["displacement_mm"][-1], rel=1e-12)
    with pytest.raises(IndexError):
        result.fields(result.n_steps)


def test_mpi_only_for_trilinos():
    """In a fresh interpreter: no MPI for the default solver; Trilinos KLU starts it
    in-process and gives the banded LU's results."""
    script = (
        "import cdea, numpy as np\n"
        "a = cdea.run(%r)\n"
        "assert not cdea.mpi_initialized()\n"
        "b = cdea.run(%r, {'Solver/Linear solver': 'Trilinos KLU'})\n"
        "assert cdea.mpi_initialized()\n"
        "for k in a.summary:\n"
        "    np.testing.assert_allclose(b.summary[k], a.summary[k], rtol=1e-9, atol=1e-12)\n"
        "print('ok', len(b))\n") % ((os.path.join(SRC, "prm", "default.prm"),) * 2)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("ok ")


def test_threads_give_the_serial_results():
    """Runs release the GIL while they compute: two threads, the serial numbers."""
    from concurrent.futures import ThreadPoolExecutor
    prm = os.path.join(SRC, "prm", "partitioned-rv1.7.prm")
    masses = [200, 250, 300, 350]
    serial = [cdea.run(prm, {"Loading/Mass (g)": m}) for m in masses]
    with ThreadPoolExecutor(2) as pool:
        threaded = list(pool.map(lambda m: cdea.run(prm, {"Loading/Mass (g)": m}), masses))
    for a, b in zip(serial, threaded):
        for name in a.summary:
            assert_same(b.summary[name], a.summary[name], name)

