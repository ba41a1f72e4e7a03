"""cdea.fit_viscoelastic: the DMA fit of prm/fit-dma.prm in-process gives the
numbers of `cdea fit` (doc/materials.md, "Fits") from a path and from CSV
text, and its file; bad data raise ValueError with the command's message. Run
by ctest (python3-pytest, python3-h5py, PYTHONPATH=build/python)."""

import os

import h5py
import numpy as np
import pytest

import cdea

SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
PRM = os.path.join(SRC, "prm", "fit-dma.prm")
CSV = os.path.join(SRC, "prm", "fit-dma.csv")
TRUE = {"shear modulus (Pa)": 25.1e3, "Branch 1 shear modulus (Pa)": 25e3,
        "Branch 1 relaxation time (s)": 0.2, "Branch 2 shear modulus (Pa)": 15e3,
        "Branch 2 relaxation time (s)": 2.0, "Branch 3 shear modulus (Pa)": 5e3,
        "Branch 3 relaxation time (s)": 20.0}


def test_dma_fit_recovers_the_constants(tmp_path):
    r = cdea.fit_viscoelastic(PRM, CSV)
    assert r.converged and r.kind == "dma"
    assert r.values["shear modulus (Pa)"] == pytest.approx(25114.689, rel=1e-6)
    for name, truth in TRUE.items():
        assert abs(r.values[name] - truth) < 2 * r.standard_errors[name], name
    assert r.correlation.shape == (7, 7)
    assert np.allclose(np.diag(r.correlation), 1.)
    assert r.data["fitted_storage_kPa"].shape == (41,)
    assert repr(r).startswith("<cdea.ViscousFitResult dma, converged, shear modulus (Pa) 25114.6")
    assert all(name in repr(r) for name in TRUE), repr(r)
    with open(CSV) as f:
        again = cdea.fit_viscoelastic(PRM, f.read())
    assert again.values == r.values
    r.write(str(tmp_path / "fit.h5"))
    with h5py.File(tmp_path / "fit.h5") as f:
        assert np.allclose(f.attrs["fitted_values"], list(r.values.values()))
        assert f["data/frequency_Hz"].shape == (41,)


def test_bad_data_are_named():
    with pytest.raises(ValueError, match="data, line 3, column loss_kPa"):
        cdea.fit_viscoelastic(PRM, "frequency_Hz, storage_kPa, loss_kPa\n1, 80, 2\n2, 81, -1\n")
    with pytest.raises(ValueError, match="do not depend on it"):
        cdea.fit_viscoelastic(PRM, CSV, {"Calibration/Free parameters": "shear modulus, mass"})
