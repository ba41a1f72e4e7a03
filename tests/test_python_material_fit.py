"""cdea.fit on material tests (doc/python.md, "Fits of material tests"): the
joint fit of prm/fit-material.prm's uniaxial and equibiaxial histories with
the pure-shear one predicted, and the model selection over elastic 0 and 1,
in-process, against the files `cdea fit` writes for the same input: the same
constants, standard errors, covariance (in the prm's units, kPa for moduli),
per-file rms and predicted stresses; the selection's table as the command's
_models.h5; bad candidates and data raise ValueError with the command's
message. Run by ctest (python3-pytest, python3-h5py, PYTHONPATH=build/python)."""

import os
import shutil
import subprocess

import h5py
import numpy as np
import pytest

import cdea

SRC = os.path.abspath(os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..")))
EXE = os.environ.get("CDEA_EXECUTABLE")
NAMES = ["fit-material-uniaxial.csv", "fit-material-equibiaxial.csv", "fit-material-pure-shear.csv"]
KPA = 1e-3  # Pa to kPa, for the files' SI covariance


@pytest.fixture()
def folder(tmp_path, monkeypatch):
    """A folder with the prm (results to out/) and the three histories, the
    current one."""
    with open(os.path.join(SRC, "prm", "fit-material.prm")) as f:
        text = f.read().replace("set Directory           = results", "set Directory = out")
    (tmp_path / "fit.prm").write_text(text)
    for name in NAMES:
        shutil.copy(os.path.join(SRC, "prm", name), tmp_path / name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def command(folder, *arguments):
    subprocess.run([EXE, "fit", "fit.prm", *arguments], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL)


def test_joint_fit_and_prediction_as_the_command(folder):
    r = cdea.fit("fit.prm", NAMES[:2], predict=[NAMES[2]])
    command(folder, NAMES[0], NAMES[1], "--predict", NAMES[2])
    assert r.converged and repr(r).startswith("<cdea.MaterialFitResult converged, shear modulus (kPa) 24.99")
    names = ["shear modulus (kPa)", "Branch 1 shear modulus (kPa)", "Branch 1 relaxation time (s)"]
    assert list(r.values) == names and list(r.standard_errors) == names
    with h5py.File(folder / "out" / "fit-material_fit.h5") as f:
        scale = np.array([KPA, KPA, 1.])
        assert np.allclose(list(r.values.values()), f.attrs["fitted_values"] * scale, rtol=1e-9)
        assert np.allclose(list(r.standard_errors.values()), f.attrs["standard_errors"] * scale,
                           rtol=1e-6)
        assert np.allclose(r.covariance, f["covariance"][()] * np.outer(scale, scale), rtol=1e-6)
        assert np.allclose(np.sqrt(np.diag(r.covariance)), list(r.standard_errors.values()))
        assert np.allclose(r.tests["rms_kPa"], f["tests/rms_kPa"][()], rtol=1e-9)
        assert list(r.tests["fitted"]) == [1, 1, 0]
        predicted = r.predictions[NAMES[2]]
        rows = f["samples/test"][()] == 2
        assert np.allclose(predicted["model_stress_kPa"], f["samples/model_stress_kPa"][()][rows],
                           rtol=1e-9)
    # The truth (25 kPa, 20 kPa, 5 s) within 3 standard errors; 0.1 kPa noise.
    for (name, value), truth in zip(r.values.items(), [25., 20., 5.]):
        assert abs(value - truth) < 3 * r.standard_errors[name], name
    assert 0.08 < r.tests["rms_kPa"][2] < 0.12
    r.write(str(folder / "again.h5"))
    with h5py.File(folder / "again.h5") as f:
        assert list(f["tests/fitted"][()]) == [1, 1, 0]


def test_model_selection_as_the_command(folder):
    r = cdea.fit("fit.prm", NAMES, models=["elastic 0", "elastic 1"])
    command(folder, *NAMES, "--set", "Calibration/Candidate models=elastic 0, elastic 1")
    s = r.models
    assert s.recommended == "elastic 1" and s.decided
    assert repr(s) == "<cdea.ModelSelection 2 models, recommended elastic 1>"
    assert "model elastic 1" in repr(r) and "Jlim" in r.values
    with h5py.File(folder / "out" / "fit-material_models.h5") as f:
        for key in ["aic", "bic", "rss_kPa2", "held_out_error", "held_out_rms_kPa"]:
            assert np.allclose(s.table[key], f["models/" + key][()], rtol=1e-9), key
        assert f.attrs["recommended"] == s.recommended and f.attrs["verdict"] == s.verdict
        assert np.allclose(s.constants["standard_error"], f["constants/standard_error"][()],
                           rtol=1e-6)
    k, n, rss = s.table["constants"], s.table["samples"], s.table["rss_kPa2"]
    assert np.allclose(s.table["aic"], n * np.log(rss / n) + 2 * k)
    s.write(str(folder / "models.h5"))
    with h5py.File(folder / "models.h5") as f:
        assert list(f["models/model"].asstr()[()]) == ["elastic 0", "elastic 1"]
    # cdea.load knows the file: its kind, the table's numbers, named dimensions.
    loaded = cdea.load(folder / "models.h5")
    assert loaded.kind == "model selection"
    assert np.array_equal(loaded["models/aic"], s.table["aic"])
    assert loaded.to_xarray()["rms_kPa"].dims == ("model", "test")


def test_bad_candidates_and_data_are_named(folder):
    with pytest.raises(ValueError, match="Calibration/Candidate models: 'neo-hooke 1' puts branches"):
        cdea.fit("fit.prm", NAMES, models=["neo-hooke 1"])
    bad = "time_s, uniaxial_stretch, nominal_stress_kPa\n0, 1, 0\n1, 0.9, 1\n"
    with pytest.raises(ValueError, match="data 2, line 3, column uniaxial_stretch"):
        cdea.fit("fit.prm", [NAMES[0], bad])
