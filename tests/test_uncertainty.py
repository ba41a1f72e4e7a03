"""Subsection Uncertainty of `cdea run` (doc/uncertainty.md). Run by ctest
(python3-pytest, python3-h5py), on prm/default.prm driven to 6 kV (past the
onset of wrinkling at 5.38 kV):

- the linear standard deviations of the final displacement, stroke, volume
  change and onset voltage against central differences of the answers
  (relative steps of 1e-4 in each constant) propagated through the same
  covariance, 3 % on mu, Jlim and eps with a correlation of mu and Jlim;
- the same for the voltages of the two folds of prm/fold-full.prm (arc
  length): the null vector of the fold's tangent, dt*/dp = -(phi^T dR/dp) /
  (phi^T dR/dt);
- a one-parameter case against its closed form: the state depends on the
  permittivity only through eps Phi^2, so V_onset ~ eps^(-1/2) and
  sd(V_onset) = V_onset sd(eps) / (2 eps);
- Monte-Carlo (300 samples, 1 % on each constant: a nearly linear answer)
  against the linear values; the same seed draws the same samples;
- a fit's _fit.prm run as it is with Mode = linear gives the same answers
  as its _fit.h5 named as Covariance file;
- cdea.run() returns the rows the command writes;
- bad input: a clear message naming the entry, exit 1, no results file.
"""

import math
import os
import subprocess

import h5py
import numpy as np
import pytest

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))

# A tight onset location, so that the differences see the onset's derivative.
SCENE = ("subsection Electrodes\n  set Voltage path (kV) = 6\nend\n"
         "subsection Wrinkling\n  set Onset tolerance (V) = 1e-7\nend\n")
NOMINAL = {"Shear modulus (kPa)": 25.1, "Jlim": 270.0, "Permittivity (F/m)": 3.98e-11}
NAMES = {"Shear modulus (kPa)": "shear modulus", "Jlim": "Jlim",
         "Permittivity (F/m)": "permittivity"}
SI = {"Shear modulus (kPa)": 1e3, "Jlim": 1.0, "Permittivity (F/m)": 1.0}


def prm_text(tmp, base, extra, source="default.prm"):
    """A parameter file in tmp: prm/SOURCE, then extra, writing tmp/BASE.h5."""
    path = os.path.join(str(tmp), base + ".prm")
    with open(path, "w") as f:
        f.write("include %s\n%s\nsubsection Output\n  set Directory = .\n"
                "  set Base name = %s\nend\n" % (os.path.join(SRC, "prm", source), extra, base))
    return path


def cdea(tmp, base, extra, verb="run", expect=0, args=()):
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    path = prm_text(tmp, base, extra)
    done = subprocess.run([EXE, verb, path, *args], cwd=str(tmp), capture_output=True,
                          text=True)
    assert done.returncode == expect, done.stdout + done.stderr
    return done


def answers(tmp, base, extra):
    """The final displacement, stroke, volume change and onset voltage of a run."""
    cdea(tmp, base, SCENE + extra)
    with h5py.File(os.path.join(str(tmp), base + ".h5"), "r") as f:
        s = f["summary"]
        return np.array([s["displacement_mm"][-1], s["stroke_mm"][-1],
                         s["volume_change_mm3"][-1], s.attrs["onset_voltage_kV"][0]]), \
            dict(s.attrs)


def material(values):
    return "subsection Material\n" + "".join(
        "  set %s = %r\n" % (k, v) for k, v in values.items()) + "end\n"


def uncertainty(mode, deviations, correlations="", samples=None):
    text = "subsection Uncertainty\n  set Mode = %s\n  set Standard deviations = %s\n" % (
        mode, deviations)
    if correlations:
        text += "  set Correlations = %s\n" % correlations
    if samples:
        text += "  set Samples = %d\n" % samples
    return text + "end\n"


STD_ROWS = ["displacement_std_mm", "stroke_std_mm", "volume_change_std_mm3"]


def linear_sd(attrs):
    return np.array([attrs[r] for r in STD_ROWS] + [attrs["onset_voltage_std_kV"][0]])


def propagated_differences(tmp, outputs, correlation):
    """sqrt(G^T C G) of the central differences G (relative steps 1e-4) of
    outputs(tmp, base, extra) in each constant, C from 3 % on each and
    @p correlation."""
    sd = np.array([0.03 * NOMINAL[k] * SI[k] for k in NOMINAL])
    C = np.diag(sd) @ np.array(correlation) @ np.diag(sd)
    gradient = []
    for k, value in NOMINAL.items():
        h = 1e-4 * value
        up, _ = outputs(tmp, "up", material({**NOMINAL, k: value + h}))
        down, _ = outputs(tmp, "down", material({**NOMINAL, k: value - h}))
        gradient.append((up - down) / (2 * h * SI[k]))
    G = np.array(gradient)  # constants x outputs
    return np.sqrt(np.einsum("ia,ij,ja->a", G, C, G))


def test_linear_against_central_differences(tmp_path):
    deviations = ", ".join("%s: 3%%" % NAMES[k] for k in NOMINAL)
    _, attrs = answers(tmp_path, "linear",
                       uncertainty("linear", deviations, "shear modulus, Jlim: 0.5"))
    differences = propagated_differences(tmp_path, answers, [[1, 0.5, 0], [0.5, 1, 0],
                                                            [0, 0, 1]])
    linear = linear_sd(attrs)
    print("linear", linear, "central differences", differences)
    assert np.all(linear > 0)
    assert np.allclose(linear, differences, rtol=2e-5, atol=0)


def fold_voltages(tmp, base, extra):
    """The ring voltages of each limit point of prm/fold-full.prm (arc length to 8 kV)."""
    path = prm_text(tmp, base, extra, source="fold-full.prm")
    done = subprocess.run([EXE, "run", path], cwd=str(tmp), capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    with h5py.File(os.path.join(str(tmp), base + ".h5"), "r") as f:
        return np.ravel(f["summary"].attrs["limit_point_voltage_kV"]), dict(f["summary"].attrs)


def test_fold_voltages_against_central_differences(tmp_path):
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    deviations = ", ".join("%s: 3%%" % NAMES[k] for k in NOMINAL)
    _, attrs = fold_voltages(tmp_path, "linear",
                             uncertainty("linear", deviations, "Jlim, permittivity: -0.4"))
    differences = propagated_differences(tmp_path, fold_voltages, [[1, 0, 0], [0, 1, -0.4],
                                                                  [0, -0.4, 1]])
    linear = np.ravel(attrs["limit_point_voltage_std_kV"])
    print("folds", np.ravel(attrs["limit_point_voltage_kV"]), "linear sd", linear,
          "central differences", differences)
    assert len(linear) == 2 and np.all(linear > 0.05)
    assert np.allclose(linear, differences, rtol=1e-5, atol=0)


def test_one_parameter_closed_form(tmp_path):
    values, attrs = answers(tmp_path, "permittivity",
                            uncertainty("linear", "permittivity: 2%"))
    onset = values[3]
    assert 5.3 < onset < 5.5
    closed_form = 0.5 * onset * 0.02
    print("onset", onset, "sd", attrs["onset_voltage_std_kV"][0], "closed form", closed_form)
    assert abs(attrs["onset_voltage_std_kV"][0] - closed_form) < 1e-7 * closed_form + 1e-9


def test_monte_carlo_converges_to_linear(tmp_path):
    deviations = ", ".join("%s: 1%%" % NAMES[k] for k in NOMINAL)
    nominal, linear = answers(tmp_path, "linear", uncertainty("linear", deviations))
    _, mc = answers(tmp_path, "mc", uncertainty("monte carlo", deviations, samples=300))
    assert mc["uncertainty_samples"] == 300 and mc["uncertainty_onset_samples"] == 300
    rows = STD_ROWS + ["onset_voltage_std_kV"]
    for row, mean_row in zip(rows, ["displacement_mean_mm", "stroke_mean_mm",
                                    "volume_change_mean_mm3", "onset_voltage_mean_kV"]):
        sd_linear, sd_mc = np.ravel(linear[row])[0], np.ravel(mc[row])[0]
        mean = np.ravel(mc[mean_row])[0]
        print(row, "linear", sd_linear, "Monte-Carlo", sd_mc, "mean", mean)
        # The sd of 300 samples scatters by 1/sqrt(2 * 299) = 4 %.
        assert abs(sd_mc / sd_linear - 1) < 0.15
        # The mean scatters by sd/sqrt(300); the curvature shifts it less.
        i = rows.index(row)
        assert abs(mean - nominal[i]) < 4 * sd_linear / math.sqrt(300)
    p = np.ravel(mc["displacement_percentiles_mm"])
    assert p[0] < p[1] < p[2] and abs(p[1] - nominal[0]) < 0.2 * np.ravel(mc[rows[0]])[0]
    # Normal: the 5 and 95 % percentiles lie 1.645 sd from the median.
    assert abs((p[2] - p[0]) / (2 * 1.645 * mc["displacement_std_mm"]) - 1) < 0.15
    _, again = answers(tmp_path, "again", uncertainty("monte carlo", deviations, samples=20))
    _, same = answers(tmp_path, "same", uncertainty("monte carlo", deviations, samples=20))
    assert again["displacement_std_mm"] == same["displacement_std_mm"]


def test_fit_covariance_carried_into_the_run(tmp_path):
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    fit = prm_text(tmp_path, "fitted", "", source="fit-example.prm")
    done = subprocess.run([EXE, "fit", fit, os.path.join(SRC, "prm", "fit-example.csv")],
                          cwd=str(tmp_path), capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(tmp_path / "fitted_fit.prm") as f:
        text = f.read()
    assert "set Standard deviations = Shear modulus (kPa): " in text
    assert "set Correlations        = Shear modulus (kPa), Jlim: " in text
    with h5py.File(tmp_path / "fitted_fit.h5", "r") as f:
        covariance = f["covariance"][()]
        errors = f.attrs["standard_errors"]
    assert np.allclose(np.sqrt(np.diag(covariance)), errors, rtol=1e-12)
    results = []
    for base, overrides in [("from_prm", []),
                            ("from_h5", ["--set", "Uncertainty/Standard deviations=",
                                         "--set", "Uncertainty/Correlations=",
                                         "--set", "Uncertainty/Covariance file=fitted_fit.h5"])]:
        done = subprocess.run([EXE, "run", "fitted_fit.prm", "--set", "Uncertainty/Mode=linear",
                               "--set", "Output/Base name=" + base, *overrides],
                              cwd=str(tmp_path), capture_output=True, text=True)
        assert done.returncode == 0, done.stdout + done.stderr
        assert "Uncertainty (linear" in done.stdout
        with h5py.File(tmp_path / (base + ".h5"), "r") as f:
            results.append([f["summary"].attrs[r] for r in STD_ROWS])
    print("from the prm", results[0], "from the h5", results[1])
    assert results[0][0] > 0
    assert np.allclose(results[0], results[1], rtol=1e-9)


BAD = [
    (uncertainty("linear", "shear modulos: 3%"),
     "Uncertainty/Standard deviations: 'shear modulos' is not a constant"),
    (uncertainty("linear", "Jlim: -3"), "a standard deviation must be zero or positive"),
    (uncertainty("linear", "Jlim 3"), "is not of the form NAME: VALUE"),
    (uncertainty("linear", "shear modulus: 3%, Jlim: 3%, permittivity: 3%",
                 "shear modulus, Jlim: 0.9; Jlim, permittivity: 0.9; shear modulus, "
                 "permittivity: -0.9"),
     "Uncertainty/Correlations: the correlation matrix is not positive semidefinite"),
    (uncertainty("linear", "shear modulus: 3%, Jlim: 3%", "shear modulus, Jlim: 1.5"),
     "lies between -1 and 1"),
    (uncertainty("linear", "shear modulus: 3%", "shear modulus, Jlim: 0.5"),
     "'Jlim' has no standard deviation"),
    ("subsection Uncertainty\n  set Mode = linear\nend\n",
     "needs either Uncertainty/Covariance file and Uncertainty/Standard deviations"),
    ("subsection Uncertainty\n  set Mode = linear\n  set Covariance file = missing_fit.h5\n"
     "end\n", "Uncertainty/Covariance file 'missing_fit.h5'"),
    ("subsection Uncertainty\n  set Mode = linear\n  set Covariance file = run.h5\nend\n",
     "is no fit file with a covariance"),
]


@pytest.mark.parametrize("extra,message", BAD)
def test_bad_input_rejected_with_no_output(tmp_path, extra, message):
    if "run.h5" in extra:
        cdea(tmp_path, "run", "")  # a results file, without a covariance
    done = cdea(tmp_path, "bad", extra, expect=1)
    assert message in done.stderr, done.stderr
    assert not os.path.exists(tmp_path / "bad.h5")


@pytest.mark.parametrize("verb", ["shoot", "sweep", "response"])
def test_commands_without_uncertainty_refuse_it(tmp_path, verb):
    done = cdea(tmp_path, "other", uncertainty("linear", "Jlim: 3%"), verb=verb, expect=1)
    assert "Uncertainty/Mode = linear: cdea " + verb + " does not carry uncertainty" \
        in done.stderr, done.stderr
    assert not [f for f in os.listdir(tmp_path) if f.endswith(".h5")]


def test_python_run_returns_the_same_rows(tmp_path):
    cdea_module = pytest.importorskip("cdea")
    deviations = ", ".join("%s: 3%%" % NAMES[k] for k in NOMINAL)
    extra = SCENE + uncertainty("linear", deviations)
    _, attrs = answers(tmp_path, "command", uncertainty("linear", deviations))
    r = cdea_module.run(prm_text(tmp_path, "module", extra))
    for row in STD_ROWS + ["onset_voltage_std_kV"]:
        assert np.allclose(r.attributes[row], attrs[row], rtol=1e-12), row
    mc = cdea_module.run(prm_text(tmp_path, "module_mc", SCENE + uncertainty(
        "monte carlo", deviations, samples=10)))
    assert mc.attributes["uncertainty_samples"] == 10
    assert np.ravel(mc.attributes["displacement_percentiles_mm"]).shape == (3,)
