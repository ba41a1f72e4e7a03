"""cdea.optimize and cdea.fit against `cdea optimize` and `cdea fit`: for the
same parameters the in-process results have every root attribute and
dataset of the command's HDF5 file (same names, units and numbers: the
optimum to 1e-10), nothing is written until write(), whose file reads back as
the command's; bad input raises ValueError with the command's message. Run by
ctest (python3-pytest, python3-h5py, PYTHONPATH=build/python)."""

import os
import subprocess

import h5py
import numpy as np
import pytest

import cdea

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))


def prm_text(name, base):
    """prm/<name> writing to out/<base>*."""
    with open(os.path.join(SRC, "prm", name)) as f:
        text = f.read()
    return text + "\nsubsection Output\n  set Directory = out\n  set Base name = " + base + "\nend\n"


def command(tmp, args):
    """`cdea ARGS` in tmp; the finished process."""
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    return subprocess.run([EXE] + args, cwd=str(tmp), capture_output=True, text=True)


def text_of(value):
    return value.decode() if isinstance(value, bytes) else value


def same(a, b, rtol):
    """Numbers to rtol, text and integers exactly."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind in "fc" or b.dtype.kind in "fc":
        return a.shape == b.shape and np.allclose(a, b, rtol=rtol, atol=0, equal_nan=True)
    if a.dtype.kind in "SUO" or b.dtype.kind in "SUO":
        return text_of(a.item()) == text_of(b.item())
    return np.array_equal(a, b)


def test_optimize_equals_the_command(tmp_path, monkeypatch):
    text = prm_text("optimize-paper.prm", "paper")
    (tmp_path / "paper.prm").write_text(text)
    done = command(tmp_path, ["optimize", "paper.prm"])
    assert done.returncode == 0, done.stderr
    monkeypatch.chdir(tmp_path / "out")  # in-process: nothing may appear here
    before = sorted(os.listdir("."))
    result = cdea.optimize(text)
    assert sorted(os.listdir(".")) == before, "cdea.optimize wrote a file"
    assert result.converged
    with h5py.File(tmp_path / "out" / "paper_optimum.h5", "r") as f:
        for key in f.attrs:
            if key in ("parameters", "code_version"):
                continue
            assert key in result.attributes, key
            assert same(result.attributes[key], f.attrs[key], 1e-10), key
        for key in f["history"]:
            assert np.array_equal(result.history[key], f["history"][key][()], equal_nan=True), key
    a = result.attributes
    assert abs(a["stroke_mm"] - 8.75568) < 2e-5 and a["min_s2_kPa"] >= 0
    assert result.history["free_values"].shape == (a["iterations"], 2)

    result.write(tmp_path / "again.h5")
    with h5py.File(tmp_path / "again.h5", "r") as g, \
            h5py.File(tmp_path / "out" / "paper_optimum.h5", "r") as f:
        assert same(g.attrs["ring_edges_over_a"], f.attrs["ring_edges_over_a"], 1e-10)
        assert same(g["starts/objective"][()], f["starts/objective"][()], 1e-10)

    # write() without a path: where the command writes, Output/Directory made.
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    assert result.results_path == "out/paper_optimum.h5"
    assert result.write() == "out/paper_optimum.h5"
    with h5py.File("out/paper_optimum.h5", "r") as g:
        assert same(g.attrs["stroke_mm"], a["stroke_mm"], 1e-15)


def test_optimize_overrides_and_bad_input(tmp_path):
    text = prm_text("optimize-paper.prm", "paper")
    one = cdea.optimize(text, {"Optimization/Starts": 1, "Optimization/Rings": 1,
                               "Optimization/Fixed voltages (kV)": "free"})
    # One ring, voltage free: the full electrode at its wrinkling onset.
    assert one.attributes["starts"] == 1
    assert abs(one.attributes["voltages_kV"][0] - 5.382378188) < 1e-6
    for overrides, message in [
            ({"Time/Enabled": True}, "Time/Enabled = true is not supported by cdea optimize"),
            ({"Optimization/Fixed voltages (kV)": "5"}, "Optimization/Fixed voltages (kV)")]:
        with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
            cdea.optimize(text, overrides)


def test_fit_equals_the_command(tmp_path, monkeypatch):
    text = prm_text("fit-example.prm", "fit")
    (tmp_path / "fit.prm").write_text(text)
    csv = os.path.join(SRC, "prm", "fit-example.csv")
    done = command(tmp_path, ["fit", "fit.prm", csv])
    assert done.returncode == 0, done.stderr
    monkeypatch.chdir(tmp_path / "out")
    before = sorted(os.listdir("."))
    with open(csv) as f:
        from_text = cdea.fit(text, f.read())
    from_path = cdea.fit(text, csv)
    assert sorted(os.listdir(".")) == before, "cdea.fit wrote a file"
    with h5py.File(tmp_path / "out" / "fit_fit.h5", "r") as f:
        for result in (from_text, from_path):
            for key in f.attrs:
                if key in ("parameters", "code_version", "free_parameters"):
                    continue
                assert same(result.attributes[key], f.attrs[key], 1e-10), key
            assert same(result.correlation, f["correlation"][()], 1e-10)
            for key in f["data"]:
                assert same(result.data[key], f["data"][key][()], 1e-10), key
            for key in f["curve"]:
                assert same(result.curve[key], f["curve"][key][()], 1e-10), key
    mu, jlim = from_path.values["shear modulus (Pa)"], from_path.values["Jlim"]
    e = from_path.standard_errors
    assert abs(mu - 25.1e3) < 2 * e["shear modulus (Pa)"] and abs(jlim - 270) < 2 * e["Jlim"]
    assert any("correlated" in w for w in from_path.warnings)

    from_path.write(tmp_path / "again.h5")
    with h5py.File(tmp_path / "again.h5", "r") as g:
        assert same(g.attrs["fitted_values"], [mu, jlim], 1e-15)

    # write() without a path: where the command writes, Output/Directory made.
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    assert from_path.results_path == "out/fit_fit.h5"
    assert from_path.write() == "out/fit_fit.h5"
    with h5py.File("out/fit_fit.h5", "r") as g:
        assert same(g.attrs["fitted_values"], [mu, jlim], 1e-15)


def test_fit_bad_input():
    text = prm_text("fit-example.prm", "fit")
    with pytest.raises(ValueError, match="data, line 3, column displacement_mm: 'abc' is not a number"):
        cdea.fit(text, "V1_kV, V2_kV, displacement_mm\n1, 1, 18.4\n2, 2, abc\n")
    with pytest.raises(ValueError, match="Material/Model = viscoelastic is not supported by cdea fit"):
        cdea.fit(text, os.path.join(SRC, "prm", "fit-example.csv"),
                 {"Time/Enabled": True, "Material/Model": "viscoelastic"})
    with pytest.raises(ValueError, match="cannot read data file 'missing.csv'"):
        cdea.fit(text, "missing.csv")


def test_fit_of_a_law_constant():
    """A law's own constant by its entry: the same values as `cdea fit`, and
    the refusals of a name the law lacks and of Jlim without the Gent limit."""
    text = prm_text("fit-example.prm", "fit")
    csv = os.path.join(SRC, "prm", "fit-example.csv")
    overrides = {"Material/Model": "mooney-rivlin", "Material/Shear modulus (kPa)": 25,
                 "Calibration/Free parameters": "shear modulus, Mooney-Rivlin C2"}
    result = cdea.fit(text, csv, overrides)
    assert result.converged
    assert list(result.values) == ["shear modulus (Pa)", "Mooney-Rivlin C2 (kPa)"]
    c2, e = result.values["Mooney-Rivlin C2 (kPa)"], result.standard_errors["Mooney-Rivlin C2 (kPa)"]
    assert c2 >= 0 and e > 0
    with pytest.raises(ValueError, match="'ogden alpha 1' is not a parameter that can be fitted "
                       "with Material/Model = mooney-rivlin"):
        cdea.fit(text, csv, dict(overrides, **{"Calibration/Free parameters": "Ogden alpha 1"}))
    with pytest.raises(ValueError, match="'jlim': Material/Model = neo-hooke has no Jlim"):
        cdea.fit(text, csv, {"Material/Model": "neo-hooke"})
