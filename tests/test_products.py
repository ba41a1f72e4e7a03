"""The printed tables, the HDF5 files and the Python results agree on every
value they share (doc/architecture.md, "One table of quantities, one product
per study"): all three are made from one product by the rows of one table,
so each Python value is its file object bit for bit, and each printed cell
is the file's number as the table prints it. Cheap examples of a run, a DMA
fit and the small-signal response; tests/test_products.cc and
tests/test_run_products.cc check every product's file against the table.
Run by ctest (python3-pytest, python3-h5py)."""

import os
import re
import subprocess

import h5py
import numpy as np
import pytest

import cdea

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))


def prm(name):
    return os.path.join(SRC, "prm", name)


def same(python_value, file_value):
    """Bit for bit, whatever the container (a Python number, a numpy array);
    an empty list is an attribute with a null dataspace in the file."""
    if isinstance(file_value, h5py.Empty):
        return np.asarray(python_value).size == 0
    a, b = np.asarray(python_value), np.asarray(file_value)
    return a.shape == b.shape and a.astype(b.dtype).tobytes() == b.tobytes()


def test_run(tmp_path):
    r = cdea.run(prm("partitioned-rv1.7.prm"))
    with h5py.File(r.write(str(tmp_path / "run.h5")), "r") as f:
        summary = f["summary"]
        assert set(r.summary) == set(summary)
        for key, values in r.summary.items():
            assert same(values, summary[key][()]), key
            assert r.columns[key] == (summary[key].attrs["unit"], summary[key].attrs["description"])
        assert set(r.attributes) == set(summary.attrs)
        for key, value in r.attributes.items():
            assert same(value, summary.attrs[key]), key
        assert r.onset is not None and same(r.onset["radius_mm"], summary.attrs["onset_radius_mm"])
        for step in (0, -1):
            group = f["steps"][sorted(f["steps"])[step]]
            for key, values in r.fields(step).items():
                assert same(values, group[key][()]), key


def test_dma_fit(tmp_path):
    r = cdea.fit_viscoelastic(prm("fit-dma.prm"), prm("fit-dma.csv"))
    path = str(tmp_path / "dma.h5")
    r.write(path)
    with h5py.File(path, "r") as f:
        assert set(r.data) == set(f["data"])
        for key, values in r.data.items():
            assert same(values, f["data"][key][()]), key
        assert same(r.correlation, f["correlation"][()])
        names = f.attrs["free_parameters"].split("; ")
        assert [r.values[n] for n in names] == list(f.attrs["fitted_values"])


def transfer_rows(text):
    """The transfer table `cdea response` prints: (f, amplitude, phase) texts."""
    return re.findall(r"^\s+(\S+)\s+(\S+)\s+(-?\d+\.\d\d)\s+\S+$", text, re.M)


def test_response(tmp_path):
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    done = subprocess.run([EXE, "response", prm("response.prm"), "--set",
                           f"Output/Directory={tmp_path}"], cwd=SRC, capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    r = cdea.response(prm("response.prm"))
    with h5py.File(str(tmp_path / "response_response.h5"), "r") as f:
        where = {"mode_frequency_Hz": "modes/frequency_Hz", "mode_damping_ratio":
                 "modes/damping_ratio", "frequency_Hz": "transfer/frequency_Hz"}
        for key, value in r.items():
            if key in where:
                assert same(value, f[where[key]][()]), key
            elif key in f.attrs:
                assert same(value, f.attrs[key]), key
            else:  # a transfer function: its real and imaginary parts
                re_part, im_part = f["transfer/" + key + "_real"], f["transfer/" + key + "_imag"]
                assert same(value.real, re_part[()]) and same(value.imag, im_part[()]), key
        # The printed table: the file's numbers as it prints them.
        rows = transfer_rows(done.stdout)
        frequency, amplitude = f["transfer/frequency_Hz"][()], f["transfer/drive_disk_amplitude_mm_per_kV"][()]
        phase = f["transfer/drive_disk_phase_deg"][()]
        n = len(frequency)
        picked = [j * (n - 1) // (len(rows) - 1) for j in range(len(rows))]
        for (f_text, a_text, p_text), i in zip(rows, picked):
            assert f_text == f"{frequency[i]:.5g}" and a_text == f"{amplitude[i]:.6g}"
            assert p_text == f"{phase[i]:.2f}"
        for k, value in enumerate(f["modes/frequency_Hz"][()]):
            assert f"mode {k + 1}: natural frequency {value:.8g} Hz" in done.stdout
