"""`cdea frequency-sweep` (periodic steady states, doc/dynamics.md) and its
Python twin: cdea.frequency_sweep() gives the numbers of the command's file
(prm/frequency-sweep.prm on a coarse mesh at one frequency), and
postprocess/plot_frequency_sweep.py plots that file. Run by ctest
(python3-pytest, python3-h5py). The steady states themselves are checked
in-process by tests/test_steady_state.cc, bad input by
tests/frequency_sweep_input.sh.
"""

import os
import subprocess

import h5py
import numpy as np

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))

OVERRIDES = {"Frequency sweep/Frequencies (Hz)": "6",
             "Discretization/Polynomial degree": "2",
             "Discretization/Elements per ring": "2"}


def test_python_equals_the_command_file(tmp_path):
    import cdea
    prm = os.path.join(SRC, "prm", "frequency-sweep.prm")
    sets = [a for k, v in OVERRIDES.items() for a in ("--set", f"{k}={v}")]
    subprocess.run([EXE, "frequency-sweep", prm, "--set", f"Output/Directory={tmp_path}"] + sets,
                   check=True, capture_output=True)
    path = tmp_path / "frequency-sweep_frequency_sweep.h5"
    d = cdea.frequency_sweep(prm, OVERRIDES)
    with h5py.File(path) as f:
        s = f["sweep"]
        for name in ("frequency_Hz", "stroke_amplitude_mm", "mean_displacement_mm",
                     "swept_volume_mm3", "dissipated_energy_mJ", "s2_min_kPa", "usable",
                     "loss_of_tension"):
            assert np.array_equal(d[name], s[name][...]), name
        assert np.array_equal(d["harmonic_mm"].real, s["harmonic_real_mm"][...])
        assert f.attrs["quasi_static_amplitude_mm"] == d["quasi_static_amplitude_mm"]
    out = tmp_path / "sweep.png"
    subprocess.run(["/usr/bin/python3", os.path.join(SRC, "postprocess", "plot_frequency_sweep.py"),
                    str(path), "--out", str(out)], check=True, capture_output=True)
    assert out.stat().st_size > 0
