"""Time runs (Time/Enabled = true, doc/time.md) through the Python module
against the command line. For the same parameter file, cdea.run gives every
/summary column (time_s and the other time columns, nonphysical as in the
quasi-static runs) and attribute of the file `cdea run` writes, and the fields
(with the viscous stretches xi1, xi2) of exactly the rows that file has a
/steps group for; write() gives the command's file. Short runs of a few
hundred steps: the pump's square wave with inertia and the water column, and
a viscoelastic ramp-hold with the second-order scheme. Run by ctest
(python3-pytest, python3-h5py, PYTHONPATH=build/python)."""

import os

import h5py
import numpy as np
import pytest

import cdea
from test_python_module import SRC, assert_same, command, prm_text

# Two periods of the pump's 0.5 Hz square wave (prm/pump-time.prm has 30).
PUMP = "subsection Time\n  set Cycles = 2\nend\n"
# The default actuator, viscoelastic, ramped to 5 kV in 1 s and held 1 s
# (without the disk's inertia: no ringing on top of the creep).
RAMP_HOLD = ("subsection Material\n  set Model = viscoelastic\n"
             "  set Network B shear modulus (kPa) = 45\n  set Network B Jlim = 270\n"
             "  set Relaxation time (s) = 0.5\nend\n"
             "subsection Time\n  set Enabled = true\n  set Waveform = ramp-hold\n"
             "  set Ramp time (s) = 1\n  set Hold time (s) = 1\n  set Time step (s) = 0.01\n"
             "  set Scheme = trapezoidal\n  set Fields interval (s) = 0.25\n  set Inertia = false\n"
             "end\n")
CASES = [("pump-time.prm", PUMP), ("default.prm", RAMP_HOLD)]


def assert_time_run_equals_file(result, path):
    """/summary (datasets with unit and description, attributes), /steps and
    the root attributes of the file at path, to the bit."""
    with h5py.File(path, "r") as f:
        s = f["summary"]
        assert sorted(result.summary) == sorted(s.keys())
        for name, data in s.items():
            assert_same(result.summary[name], data[()], "summary/" + name)
            assert result.columns[name] == (data.attrs["unit"], data.attrs["description"]), name
        assert sorted(result.attributes) == sorted(s.attrs.keys())
        for name in s.attrs:
            assert_same(result.attributes[name], s.attrs[name], "summary attribute " + name)
        groups = sorted(f["steps"])
        assert result.field_steps == [int(g) for g in groups]
        for key in groups:
            fields = result.fields(int(key))
            assert sorted(fields) == sorted(f["steps"][key].keys())
            for name, data in f["steps"][key].items():
                assert_same(fields[name], data[()], "steps/%s/%s" % (key, name))
        assert f.attrs["parameters"] == result.parameters
        assert f.attrs["method"] == result.method == "finite elements in time"
        return dict(f.attrs)


@pytest.mark.parametrize("name,extra", CASES)
def test_time_run_equals_the_command_line_file(tmp_path, name, extra):
    done, path = command(tmp_path, "run", prm_text(name, extra=extra))
    assert done.returncode == 0, done.stderr
    result = cdea.run(path)
    assert result.completed and result.message == ""
    file_attributes = assert_time_run_equals_file(result, tmp_path / "out" / "out.h5")

    s = result.summary
    n = len(result)
    assert 200 < n < 1000
    # time_s: NaN in the quasi-static rows (pre-stretch, weight), then rising
    # from 0 to the end of the waveform.
    timed = np.isfinite(s["time_s"])
    assert not timed[s["stage"] < 2].any() and timed[s["stage"] == 2].all()
    t = s["time_s"][timed]
    assert t[0] == 0.0 and np.all(np.diff(t) >= 0)
    assert t[-1] == pytest.approx(4.0 if name == "pump-time.prm" else 2.0, abs=1e-9)
    # The non-physical check runs in time as in the quasi-static runs.
    assert "nonphysical" in s and np.all(s["nonphysical"] == 0)
    # Fields at some rows only, with the viscous stretches; at the start the
    # film is relaxed: xi is the total stretch (xi per cell's quadrature
    # point, lambda at the samples: equal to the cells' variation, 2 %).
    assert 0 < len(result.field_steps) < n
    start = result.fields(int(np.flatnonzero(timed)[0]))
    assert start["xi1"].shape == start["lambda1"].shape
    np.testing.assert_allclose(start["xi1"], start["lambda1"], rtol=0.025)
    np.testing.assert_allclose(start["xi2"], start["lambda2"], rtol=0.025)
    without = next(i for i in range(n) if i not in set(result.field_steps))
    with pytest.raises(IndexError, match="has no fields"):
        result.fields(without)

    # Nothing written until write(); then the command's file, root attributes too.
    again = tmp_path / "again.h5"
    assert result.write(again) == str(again)
    assert_time_run_equals_file(result, again)
    with h5py.File(again, "r") as f:
        assert sorted(f.attrs.keys()) == sorted(file_attributes)
        for key in file_attributes:
            assert_same(f.attrs[key], file_attributes[key], "root attribute " + key)


def test_time_run_physics(tmp_path):
    """The ramp-hold run creeps: during the hold at 5 kV the displacement
    grows as network B relaxes, towards the elastic network-A equilibrium,
    which is where a quasi-static run of the same actuator ends."""
    result = cdea.run(prm_text("default.prm", extra=RAMP_HOLD))
    s = result.summary
    t, d = s["time_s"], s["displacement_mm"]
    hold = t >= 1.0
    assert np.all(np.diff(d[hold]) > 0)
    elastic = cdea.run(os.path.join(SRC, "prm", "default.prm")).summary["displacement_mm"][-1]
    assert d[hold][0] < d[hold][-1] < elastic
    # After a hold of two relaxation times (of network B alone) about a
    # quarter of the creep is left.
    left = (elastic - d[hold][-1]) / (elastic - d[hold][0])
    assert 0.1 < left < 0.35
