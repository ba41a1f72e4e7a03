"""`cdea response` (the small-signal frequency response, doc/dynamics.md)
against quasi-static and time runs of the same actuator (prm/default.prm at
5 kV). Run by ctest (python3-pytest, python3-h5py):

- the quasi-static limit: the drive's transfer function at 1e-8 Hz equals
  d(displacement)/dV by central differences of two `cdea run`s at 5 kV +- 2 V
  to 2e-6 (measured 3e-7; +- 10 V leaves 8e-6 of truncation), for the elastic film and for the viscoelastic one (relaxed:
  network A's equilibrium, which the elastic runs with network A's constants
  are);
- the first natural frequency equals sqrt(k/m) / 2 pi with k = g dm / dz from
  two quasi-static runs at disk mass m +- 0.5 % (elastic film, massless
  membrane) to 1e-4 (measured 1.5e-7);
- against a time run: the viscoelastic film without the disk's inertia,
  ramped to 5 kV, held 40 s (20 relaxation times) and then driven by
  5 kV + 5 V sin(2 pi f t) at f = 0.08 Hz (omega tau = 1, where the phase lag
  is largest) as a table of 64 rows per period (ESDIRK4 at relative
  tolerance 1e-9): the fit a + b cos + c sin of the fourth period gives the
  response's amplitude (times sinc^2(pi/64), the fundamental of the
  piecewise-linear drive) to 1e-3 and its phase to 1e-3 rad (measured
  1.8e-4 and 1.7e-5 rad);
- cdea.response() (the Python module) gives the command file's numbers.
"""

import math
import os
import subprocess

import h5py
import numpy as np
import pytest

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))

VISCOUS = ("subsection Material\n  set Model = viscoelastic\n"
           "  set Network B shear modulus (kPa) = 45\n  set Network B Jlim = 270\n"
           "  set Relaxation time (s) = 2\nend\n")
# A viscoelastic film needs Time/Enabled (its prm describes a time run).
VISCOUS_RESPONSE = VISCOUS + "subsection Time\n  set Enabled = true\nend\n"


def cdea(tmp, verb, extra, base):
    """`cdea VERB` on prm/default.prm + extra in tmp; the results file's path."""
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    with open(os.path.join(SRC, "prm", "default.prm")) as f:
        text = f.read()
    text += extra + "\nsubsection Output\n  set Directory = .\n  set Base name = " + base + \
        "\n  set ParaView = false\nend\n"
    path = os.path.join(str(tmp), base + ".prm")
    with open(path, "w") as f:
        f.write(text)
    done = subprocess.run([EXE, verb, path], cwd=str(tmp), capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    suffix = "_response" if verb == "response" else ""
    return os.path.join(str(tmp), base + suffix + ".h5")


def end_displacement(tmp, extra, base):
    """Displacement (mm) at the end of a quasi-static `cdea run`."""
    with h5py.File(cdea(tmp, "run", extra, base), "r") as f:
        return float(f["summary/displacement_mm"][-1])


def voltage(kV):
    return "subsection Electrodes\n  set Voltage path (kV) = %.6f\nend\n" % kV


def response(tmp, extra, base):
    """(frequencies, drive transfer function in mm/kV, mode frequencies)."""
    with h5py.File(cdea(tmp, "response", extra, base), "r") as f:
        t = f["transfer"]
        h = t["drive_disk_mm_per_kV_real"][()] + 1j * t["drive_disk_mm_per_kV_imag"][()]
        return t["frequency_Hz"][()], h, f["modes/frequency_Hz"][()]


LOW = "subsection Response\n  set Lowest frequency (Hz) = 1e-8\nend\n"


@pytest.mark.parametrize("material", ["elastic", "viscoelastic"])
def test_quasi_static_limit(tmp_path, material):
    _, h, _ = response(tmp_path, LOW + (VISCOUS_RESPONSE if material == "viscoelastic" else ""),
                        "r")
    dV = 0.002  # kV
    up = end_displacement(tmp_path, voltage(5 + dV), "up")
    down = end_displacement(tmp_path, voltage(5 - dV), "down")
    derivative = (up - down) / (2 * dV)
    print(material, h[0], derivative)
    assert abs(h[0] - derivative) < 2e-6 * abs(derivative)


def test_natural_frequency(tmp_path):
    _, _, modes = response(tmp_path, "", "r")
    m = 0.280
    dm = 0.005 * m
    z = [end_displacement(tmp_path, "subsection Loading\n  set Mass (g) = %.9f\nend\n"
                          % ((m + s * dm) * 1e3), "m%d" % i) for i, s in enumerate((1, -1))]
    k = 9.81 * 2 * dm / ((z[0] - z[1]) * 1e-3)
    f = math.sqrt(k / m) / (2 * math.pi)
    print(modes[0], f)
    assert abs(modes[0] - f) < 1e-4 * f


def test_against_time_run(tmp_path):
    f, tau, rows, periods = 0.08, 2.0, 64, 4
    bias, amplitude, hold = 5.0, 0.005, 40.0  # kV, kV, s
    start = 1.0 + hold
    times = [0.0, 1.0] + [start + i / (rows * f) for i in range(rows * periods + 1)]
    volts = [0.0, bias] + [bias + amplitude * math.sin(2 * math.pi * f * (t - start))
                           for t in times[2:]]
    with open(os.path.join(str(tmp_path), "drive.csv"), "w") as out:
        for t, v in zip(times, volts):
            out.write("%.15g, %.15g\n" % (t, v))
    time_prm = ("subsection Time\n  set Enabled = true\n  set Waveform = table\n"
                "  set Table file = drive.csv\n  set Time step (s) = 1\n"
                "  set Scheme = ESDIRK4\n  set Step control = error\n"
                "  set Relative tolerance = 1e-9\n  set Absolute tolerance (mm) = 1e-9\n"
                "  set Internal variable tolerance = 1e-12\n  set Inertia = false\nend\n")
    with h5py.File(cdea(tmp_path, "run", VISCOUS + time_prm, "time"), "r") as h5:
        t = h5["summary/time_s"][()]
        z = h5["summary/displacement_mm"][()]
    last = (t >= start + (periods - 1) / f - 1e-9) & (t <= start + periods / f + 1e-9)
    phase = 2 * math.pi * f * (t[last] - start)
    fit = np.linalg.lstsq(np.column_stack([np.ones(phase.size), np.cos(phase), np.sin(phase)]),
                          z[last], rcond=None)[0]
    # z = a + |H| e sin(phase + arg H): c = e Re H, b = e Im H.
    measured = (fit[2] + 1j * fit[1]) / amplitude
    assert np.count_nonzero(last) >= rows

    frequency_prm = ("subsection Time\n  set Inertia = false\nend\n"
                     "subsection Response\n  set Lowest frequency (Hz) = %g\n"
                     "  set Highest frequency (Hz) = %g\n  set Frequencies = 2\nend\n"
                     % (f, 2 * f))
    _, h, _ = response(tmp_path, VISCOUS_RESPONSE + frequency_prm, "r")
    sinc = math.sin(math.pi / rows) / (math.pi / rows)
    expected = h[0] * sinc ** 2
    print("time run", measured, abs(measured), np.angle(measured),
          "response", expected, abs(expected), np.angle(expected), "omega tau", 2 * math.pi * f * tau)
    assert abs(abs(measured) / abs(expected) - 1) < 1e-3
    assert abs(np.angle(measured / expected)) < 1e-3



def test_python_module(tmp_path):
    """cdea.response() gives the numbers of the command's file, to the bit."""
    module = pytest.importorskip("cdea")
    d = module.response(os.path.join(SRC, "prm", "default.prm"), {"Response/Frequencies": 20})
    path = cdea(tmp_path, "response", "subsection Response\n  set Frequencies = 20\nend\n", "d")
    with h5py.File(path, "r") as f:
        t = f["transfer"]
        assert np.array_equal(d["frequency_Hz"], t["frequency_Hz"][()])
        for name in ("drive_disk_mm_per_kV", "disk_mm_per_kV", "volume_mm3_per_kV"):
            assert np.array_equal(d[name], t[name + "_real"][()] + 1j * t[name + "_imag"][()])
        assert np.array_equal(d["mode_frequency_Hz"], f["modes/frequency_Hz"][()])
        assert d["displacement_mm"] == f.attrs["displacement_mm"]
