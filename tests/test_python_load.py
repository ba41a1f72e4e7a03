"""cdea.load (python/cdea_load.py) and to_pandas()/to_xarray() (issue 34):
the file `cdea run` writes loads to the numbers cdea.run returns, to the
bit; a response file to cdea.response()'s complex transfer functions; a map
to SweepResult's arrays, with the same named dimensions from either;
missing files raise FileNotFoundError, files of no product ValueError;
`import cdea` imports none of numpy, h5py, pandas or xarray. Run by ctest
(python3-pytest, python3-h5py, python3-pandas, python3-xarray).
"""

import os
import subprocess
import sys

import h5py
import numpy as np
import pytest

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
PRM = os.path.join(SRC, "prm")
MAP = {"Sweep/Ring edge values (r/a)": "1.4, 1.7, 2",
       "Sweep/Outer voltage range (kV)": "5, 6, 0.5"}


def command(tmp, *args):
    subprocess.run([EXE, *args, "--set", f"Output/Directory={tmp}"], check=True,
                   capture_output=True, cwd=PRM)


def test_run_file_loads_to_the_call(tmp_path):
    import cdea
    command(tmp_path, "run", "partitioned-rv1.7.prm")
    run = cdea.run(os.path.join(PRM, "partitioned-rv1.7.prm"))
    loaded = cdea.load(tmp_path / "partitioned-rv1.7.h5")
    assert isinstance(loaded, cdea.RunFile) and loaded.completed
    assert len(loaded) == len(run) and loaded.n_rings == run.n_rings == 2
    assert set(loaded.summary) == set(run.summary)
    for key, value in run.summary.items():
        assert np.array_equal(loaded.summary[key], value, equal_nan=True), key
    assert loaded.columns == run.columns
    for key, value in run.fields(-1).items():
        assert np.array_equal(loaded.fields(-1)[key], value), key
    assert np.array_equal(loaded.onset["voltage_kV"], run.onset["voltage_kV"])
    with pytest.raises(IndexError):
        loaded.fields(len(run))
    frame, dataset = loaded.to_pandas(), loaded.to_xarray()
    assert frame.shape[0] == len(run) and frame.index.name == "step"
    assert np.array_equal(frame["voltage_kV[2]"], run.summary["voltage_kV"][:, 1])
    assert dataset["voltage_kV"].dims == ("step", "ring")
    assert dataset["stroke_mm"].attrs["unit"] == "mm"
    assert list(dataset["ring"].values) == [1, 2]
    # The same tables from the call (its columns in the order the file sorts by name).
    assert run.to_xarray().equals(dataset)
    assert run.to_pandas().sort_index(axis=1).equals(frame.sort_index(axis=1))


def test_response_file_loads_to_the_call(tmp_path):
    import cdea
    command(tmp_path, "response", "response.prm")
    called = cdea.response(os.path.join(PRM, "response.prm"))
    loaded = cdea.load(tmp_path / "response_response.h5")
    assert isinstance(loaded, cdea.ProductFile) and loaded.kind == "response"
    for key in ("disk_mm_per_kV", "drive_disk_mm_per_kV", "volume_mm3_per_kV"):
        assert np.array_equal(loaded[f"transfer/{key}"], called[key]), key
    assert np.array_equal(loaded["modes/frequency_Hz"], called["mode_frequency_Hz"])
    transfer, modes = loaded.to_xarray(), loaded.to_xarray("modes")
    assert transfer["drive_disk_mm_per_kV"].dims == ("frequency",)
    assert np.array_equal(transfer["frequency"], called["frequency_Hz"])
    assert modes["shape_z"].dims == ("mode", "sample")
    assert modes["shape_z"].attrs["unit"] == "1"
    assert loaded.to_pandas().shape[0] == len(called["frequency_Hz"])


def test_map_dimensions_from_file_and_call(tmp_path):
    import cdea
    command(tmp_path, "sweep", "sweep-inner5.prm",
            *[a for k, v in MAP.items() for a in ("--set", f"{k}={v}")])
    loaded = cdea.load(tmp_path / "sweep-inner5_map.h5").to_xarray()
    called = cdea.sweep(os.path.join(PRM, "sweep-inner5.prm"), MAP).to_xarray()
    assert dict(loaded.sizes) == {"rv": 3, "outer_voltage": 3, "edge": 2}
    assert loaded["s2_inner_edge_kPa"].dims == ("rv", "outer_voltage", "edge")
    assert loaded["red_line_s2_inner_edge_kPa"].dims == ("rv", "edge")
    assert np.array_equal(loaded["rv"], [1.4, 1.7, 2])
    for key in ("stroke_mm", "s2_inner_edge_kPa", "red_line_outer_kV"):
        assert np.array_equal(loaded[key], called[key], equal_nan=True), key


def test_errors(tmp_path):
    import cdea
    with pytest.raises(FileNotFoundError):
        cdea.load(tmp_path / "none.h5")
    (tmp_path / "text.h5").write_text("not HDF5\n")
    with pytest.raises(ValueError, match="text.h5: not an HDF5 file"):
        cdea.load(tmp_path / "text.h5")
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f["x"] = [1.0]
    with pytest.raises(ValueError, match="other.h5: not a results file of cdea"):
        cdea.load(tmp_path / "other.h5")


def test_import_stays_light():
    code = ("import sys, cdea; print(sorted(m for m in ('numpy', 'h5py', 'pandas', 'xarray') "
            "if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True)
    assert done.stdout.strip() == "[]"
