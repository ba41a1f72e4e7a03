#!/usr/bin/python3
"""The example data of the viscoelastic fits, made by cdea at known constants
plus Gaussian noise (doc/materials.md, "Fits"), and the check that the fits
recover those constants.

  make_fit_examples.py dma [SEED]         writes prm/fit-dma.csv (seed 1)
  make_fit_examples.py creep [SEED]       writes prm/fit-creep.csv (seed 1)
  make_fit_examples.py check-dma N        fits N realisations (seeds 1..N)
  make_fit_examples.py check-creep N      of each and counts the constants
                                          within 2 standard errors

Run from the repository's top directory; CDEA (default build/cdea) is the
executable. The true constants are TRUE below; the prm files hold the start
values of the fits.
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

CDEA = os.environ.get("CDEA", "build/cdea")
# The true film: network A's shear modulus (kPa) and the three branches.
TRUE = {"mu_A": 25.1, "mu": [25.0, 15.0, 5.0], "tau": [0.2, 2.0, 20.0]}
DMA_NOISE_KPA = 0.3     # standard deviation on both moduli
CREEP_NOISE_MM = 0.005  # standard deviation on the displacement


def true_sets():
    return ["--set", f"Material/Shear modulus (kPa)={TRUE['mu_A']}",
            "--set", "Material/Branch shear moduli (kPa)=" + ", ".join(map(str, TRUE["mu"])),
            "--set", "Material/Branch relaxation times (s)=" + ", ".join(map(str, TRUE["tau"]))]


def true_values(kind):
    """The fit's free parameters in the order of the prm files (SI): the DMA
    fit frees every modulus and time, the creep fit mu_A and the moduli of
    branches 2 and 3 (prm/fit-creep.prm says why)."""
    values = [TRUE["mu_A"] * 1e3]
    for k, (mu, tau) in enumerate(zip(TRUE["mu"], TRUE["tau"])):
        if kind == "dma":
            values += [mu * 1e3, tau]
        elif k > 0:
            values += [mu * 1e3]
    return values


def run(args, directory):
    subprocess.run([CDEA] + args + ["--set", f"Output/Directory={directory}"], check=True,
                   stdout=subprocess.DEVNULL)


def dma_rows(seed, directory):
    run(["chart", "prm/fit-dma.prm"] + true_sets(), directory)
    with h5py.File(os.path.join(directory, "fit-dma_chart.h5")) as f:
        # The chart's frequencies from 1 mHz to 10 Hz (41 of its 61).
        keep = f["dma/frequency_Hz"][:] <= 10. * (1. + 1e-9)
        freq = f["dma/frequency_Hz"][keep]
        storage = f["dma/storage_modulus_kPa"][keep]
        loss = f["dma/loss_modulus_kPa"][keep]
    rng = np.random.default_rng(seed)
    storage = storage + rng.normal(0., DMA_NOISE_KPA, len(freq))
    loss = loss + rng.normal(0., DMA_NOISE_KPA, len(freq))
    lines = ["frequency_Hz, storage_kPa, loss_kPa"]
    lines += [f"{a:.6g}, {b:.6f}, {c:.6f}" for a, b, c in zip(freq, storage, loss)]
    return lines


def creep_rows(seed, directory):
    run(["run", "prm/fit-creep.prm"] + true_sets(), directory)
    with h5py.File(os.path.join(directory, "fit-creep.h5")) as f:
        t = f["summary/time_s"][:]
        d = f["summary/displacement_mm"][:]
        v = f["summary/voltage_kV"][:]
    keep = ~np.isnan(t)
    t, d, v = t[keep], d[keep], v[keep].reshape(len(t[keep]), -1)
    # Samples every 1 s (the steps land there) from t = 0.
    samples = [i for i in range(len(t)) if abs(t[i] - round(t[i])) < 1e-9]
    rng = np.random.default_rng(seed)
    noisy = d[samples] + rng.normal(0., CREEP_NOISE_MM, len(samples))
    lines = ["time_s, " + ", ".join(f"V{r + 1}_kV" for r in range(v.shape[1])) + ", displacement_mm"]
    for i, x in zip(samples, noisy):
        lines.append(f"{t[i]:.6g}, " + ", ".join(f"{u:.6g}" for u in v[i]) + f", {x:.6f}")
    return lines


def write(kind, seed, path, directory):
    rows = dma_rows(seed, directory) if kind == "dma" else creep_rows(seed, directory)
    header = [f"# Made by postprocess/make_fit_examples.py {kind} {seed}: cdea at the true",
              f"# constants mu_A = {TRUE['mu_A']} kPa, branch moduli {TRUE['mu']} kPa,",
              f"# relaxation times {TRUE['tau']} s, plus Gaussian noise of " +
              (f"{DMA_NOISE_KPA} kPa (seed {seed})." if kind == "dma" else
               f"{CREEP_NOISE_MM} mm (seed {seed}).")]
    with open(path, "w") as f:
        f.write("\n".join(header + rows) + "\n")


def check(kind, n):
    truth = np.array(true_values(kind))
    inside = constants = 0
    with tempfile.TemporaryDirectory() as directory:
        for seed in range(1, n + 1):
            data = os.path.join(directory, "data.csv")
            write(kind, seed, data, directory)
            subprocess.run([CDEA, "fit", f"prm/fit-{kind}.prm", data, "--set",
                            f"Output/Directory={directory}"], check=True,
                           stdout=subprocess.DEVNULL)
            with h5py.File(os.path.join(directory, f"fit-{kind}_fit.h5")) as f:
                values = np.array(f.attrs["fitted_values"])
                errors = np.array(f.attrs["standard_errors"])
            z = np.abs(values - truth) / errors
            ok = bool(np.all(z < 2.))
            inside += ok
            constants += int(np.sum(z < 2.))
            print(f"seed {seed:3d}: |fit - true| / std. error = "
                  + " ".join(f"{x:.2f}" for x in z) + ("" if ok else "  OUTSIDE"))
    print(f"{inside} of {n} realisations with every constant within 2 standard errors; "
          f"{constants} of {n * len(truth)} constants")
    return 0 if inside == n else 1


def main():
    kind = sys.argv[1] if len(sys.argv) > 1 else ""
    if kind in ("dma", "creep"):
        seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
        with tempfile.TemporaryDirectory() as directory:
            write(kind, seed, f"prm/fit-{kind}.csv", directory)
        return 0
    if kind in ("check-dma", "check-creep"):
        return check(kind[6:], int(sys.argv[2]) if len(sys.argv) > 2 else 20)
    print(__doc__)
    return 1


if __name__ == "__main__":
    sys.exit(main())
