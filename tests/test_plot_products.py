"""postprocess/plot.py and the pictures it draws (issue 34): files made by
`cdea` here (a run and its shooting twin, a response, two frequency sweeps,
creep, DMA and material-test fits, a viscoelastic chart), each recognised as
its product and drawn in-process (Agg) with matplotlib's savefig watched, so
that each figure's axes are checked against the file: titles, axis labels
with units, and the curves' data equal to the file's datasets. Refusals: a
missing file, a file that is not HDF5, an HDF5 file of no product and a mix
of kinds exit 1 naming the file and write nothing. Run by ctest
(python3-pytest, python3-h5py, python3-matplotlib).
"""

import os
import subprocess
import sys

import h5py
import numpy as np
import pytest

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(SRC, "postprocess"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
from matplotlib.figure import Figure  # noqa: E402

import plot  # noqa: E402

COARSE = ["--set", "Discretization/Polynomial degree=2",
          "--set", "Discretization/Elements per ring=2"]


def cdea(tmp, *args):
    prm_dir = os.path.join(SRC, "prm")
    subprocess.run([EXE, *args, "--set", f"Output/Directory={tmp}"], check=True,
                   capture_output=True, cwd=prm_dir)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("products")
    cdea(tmp, "run", "default.prm")
    cdea(tmp, "shoot", "default.prm")
    cdea(tmp, "response", "response.prm")
    for name, frequencies in (("one", "6"), ("two", "2, 6")):
        cdea(tmp, "frequency-sweep", "frequency-sweep.prm", *COARSE,
             "--set", f"Frequency sweep/Frequencies (Hz)={frequencies}",
             "--set", f"Output/Base name={name}")
    cdea(tmp, "fit", "fit-dma.prm", "fit-dma.csv")
    cdea(tmp, "chart", "fit-dma.prm")
    cdea(tmp, "fit", "fit-material.prm", "fit-material-uniaxial.csv",
         "fit-material-equibiaxial.csv", "--predict", "fit-material-pure-shear.csv")
    return tmp


@pytest.fixture
def drawn(monkeypatch):
    """The figures plot.py saves, by path."""
    figures = {}
    save = Figure.savefig

    def watched(fig, path, *args, **kwargs):
        figures[str(path)] = fig
        return save(fig, path, *args, **kwargs)
    monkeypatch.setattr(Figure, "savefig", watched)
    return figures


def draw(drawn, paths, out):
    assert plot.main([str(p) for p in paths] + ["-o", str(out)]) == 0
    assert out.stat().st_size > 10000
    return drawn[str(out)]


def lines(ax):
    return {line.get_label(): line for line in ax.get_lines()}


def test_run_and_shooting_overlaid(files, drawn, tmp_path):
    fig = draw(drawn, [files / "default.h5", files / "default_shooting.h5"], tmp_path / "r.png")
    ax = fig.axes[0]
    assert ax.get_xlabel() == "voltage Φ (kV)" and ax.get_ylabel() == "displacement (mm)"
    shown = lines(ax)
    for name in ("default.h5", "default_shooting.h5"):
        with h5py.File(files / name) as f:
            voltage = f["summary/stage"][()] == 2
            assert np.array_equal(shown[name].get_ydata(), f["summary/displacement_mm"][voltage])
            assert np.array_equal(shown[name].get_xdata(), f["summary/voltage_kV"][voltage, 0])


def test_response_bode_plot(files, drawn, tmp_path):
    path = files / "response_response.h5"
    fig = draw(drawn, [path], tmp_path / "b.png")
    amplitude, phase, shapes = fig.axes
    assert amplitude.get_ylabel() == "disk displacement per kV (mm/kV)"
    assert amplitude.get_xscale() == "log" and amplitude.get_yscale() == "log"
    assert phase.get_xlabel() == "drive frequency (Hz)" and phase.get_ylabel() == "phase (deg)"
    with h5py.File(path) as f:
        t, modes = f["transfer"], f["modes"]
        drive = lines(amplitude)["response_response.h5: drive"]
        assert np.array_equal(drive.get_xdata(), t["frequency_Hz"][()])
        assert np.array_equal(drive.get_ydata(), t["drive_disk_amplitude_mm_per_kV"][()])
        # The phase unwrapped: equal to the file's modulo 360 deg, no jump of 180 deg or more.
        shown = lines(phase)["response_response.h5"].get_ydata()
        assert np.allclose(np.mod(shown - t["drive_disk_phase_deg"][()] + 180, 360), 180)
        assert np.max(np.abs(np.diff(shown))) < 180
        for k, fn in enumerate(modes["frequency_Hz"][()]):
            marker = lines(amplitude)[f"response_response.h5: mode {k + 1}, {fn:.3g} Hz"]
            assert marker.get_xdata()[0] == fn
            # The resonance peak lies at the mode's frequency (within the grid's spacing).
            peak = t["frequency_Hz"][np.argmax(t["drive_disk_amplitude_mm_per_kV"][()])]
            assert abs(np.log(peak / fn)) < np.log(t["frequency_Hz"][1] / t["frequency_Hz"][0])
            assert np.array_equal(lines(shapes)[marker.get_label()].get_ydata(),
                                  modes["shape_z"][k])


def test_frequency_sweeps_overlaid(files, drawn, tmp_path):
    paths = [files / "one_frequency_sweep.h5", files / "two_frequency_sweep.h5"]
    fig = draw(drawn, paths, tmp_path / "s.png")
    stroke, dissipated = fig.axes
    assert stroke.get_ylabel() == "stroke amplitude (mm)"
    assert dissipated.get_xlabel() == "drive frequency (Hz)"
    for path in paths:
        with h5py.File(path) as f:
            line = lines(stroke)[path.name]
            assert np.array_equal(line.get_xdata(), f["sweep/frequency_Hz"][()])
            assert np.array_equal(line.get_ydata(), f["sweep/stroke_amplitude_mm"][()])
            qs = f.attrs["quasi_static_amplitude_mm"]
            assert f"{path.name}: quasi-static {qs:.3g} mm" in lines(stroke)
    assert len(lines(stroke)[paths[1].name].get_xdata()) == 2


def test_dma_fit_measured_fitted_residuals(files, drawn, tmp_path):
    path = files / "fit-dma_fit.h5"
    fig = draw(drawn, [path], tmp_path / "d.png")
    ax, residuals = fig.axes
    assert ax.get_title().startswith("(a) DMA") and ax.get_ylabel() == "modulus (kPa)"
    assert residuals.get_ylabel() == "model - measured (kPa)"
    with h5py.File(path) as f:
        d = f["data"]
        assert np.array_equal(lines(ax)["E' (storage) measured"].get_ydata(), d["storage_kPa"])
        assert np.array_equal(lines(ax)["E'' (loss) fitted"].get_ydata(), d["fitted_loss_kPa"])
        assert np.allclose(lines(residuals)["E' (storage)"].get_ydata(),
                           d["residual_storage_kPa"], atol=1e-12)
    assert any("rms residual" in t.get_text() and "kPa" in t.get_text() for t in ax.texts)


def test_material_fit_predicted_dashed(files, drawn, tmp_path):
    path = files / "fit-material_fit.h5"
    fig = draw(drawn, [path], tmp_path / "m.png")
    shown = lines(fig.axes[0])
    assert shown["uniaxial, model (fitted)"].get_linestyle() == "-"
    assert shown["pure shear, model (predicted)"].get_linestyle() == "--"
    with h5py.File(path) as f:
        rows = f["samples/test"][()] == 2
        assert np.array_equal(shown["pure shear, measured"].get_ydata(),
                              f["samples/measured_stress_kPa"][rows])


def test_chart_dma_csv_with_comment_lines(files, tmp_path):
    """prm/fit-dma.csv: its header follows three '#' lines."""
    out = tmp_path / "c.png"
    done = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "postprocess", "plot_chart.py"),
                           str(files / "fit-dma_chart.h5"), "--dma",
                           os.path.join(SRC, "prm", "fit-dma.csv"), "--out", str(out)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert out.stat().st_size > 10000


@pytest.mark.parametrize("case", ["missing", "not hdf5", "no product", "mixed"])
def test_refusals(files, tmp_path, case):
    other = tmp_path / "other.h5"
    if case == "not hdf5":
        other.write_text("no HDF5\n")
    elif case == "no product":
        with h5py.File(other, "w") as f:
            f["x"] = [1.0]
    args = [str(files / "default.h5"), str(other if case != "mixed"
                                           else files / "fit-dma_fit.h5")]
    out = tmp_path / "x.png"
    done = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "postprocess", "plot.py"),
                           *args, "-o", str(out)], capture_output=True, text=True)
    assert done.returncode == 1
    assert done.stderr.startswith("plot.py: error: ")
    assert (args[1] if case != "mixed" else "fit-dma_fit.h5") in done.stderr
    assert not out.exists()
