"""ParaView output of `cdea run` read back with VTK's own XML reader and checked
against the HDF5 results of the same run: every converged step is in the PVD
collection at increasing times, the film's point data are the /steps fields,
the geometry is the meridian revolved about the axis, the true stresses are
l_i s_i, the wrinkled flag marks loss of tension, and the disk is a piece of
its own. Run by ctest (python3-pytest, python3-vtk9, python3-h5py)."""

import os
import subprocess
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

vtk = pytest.importorskip("vtk")
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
SEGMENTS = 12


def run(tmp, prm_name, base, extra=""):
    """cdea run on prm/<prm_name> with ParaView output into tmp/out."""
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    with open(os.path.join(SRC, "prm", prm_name)) as f:
        text = f.read()
    prm = os.path.join(tmp, base + ".prm")
    with open(prm, "w") as f:
        f.write(text + "\nsubsection Output\n  set Directory = out\n  set Base name = " + base
                + "\n  set ParaView = true\n  set ParaView segments = " + str(SEGMENTS)
                + "\nend\n" + extra)
    done = subprocess.run([EXE, "run", prm], cwd=tmp, capture_output=True, text=True)
    assert done.returncode in (0, 2), done.stderr
    return os.path.join(tmp, "out", base)


def collection(stem):
    root = ET.parse(stem + ".pvd").getroot()
    sets = root.find("Collection").findall("DataSet")
    folder = os.path.dirname(stem)
    return ([float(d.get("timestep")) for d in sets],
            [os.path.join(folder, d.get("file")) for d in sets])


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    pd = grid.GetPointData()
    data = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
    fd = grid.GetFieldData()
    field = {fd.GetArrayName(i): vtk_to_numpy(fd.GetArray(i)).ravel()
             for i in range(fd.GetNumberOfArrays())}
    cells = np.array([grid.GetCellType(i) for i in range(grid.GetNumberOfCells())])
    return vtk_to_numpy(grid.GetPoints().GetData()), data, field, cells, reader


@pytest.fixture(scope="module")
def partitioned(tmp_path_factory):
    tmp = str(tmp_path_factory.mktemp("partitioned"))
    return run(tmp, "partitioned-rv1.7.prm", "part")


def test_every_step_at_increasing_times(partitioned):
    times, files = collection(partitioned)
    with h5py.File(partitioned + ".h5", "r") as f:
        s = f["summary"]
        stage, t = s["stage"][:], s["load_factor"][:]
    assert len(files) == len(stage) > 20
    assert all(os.path.isfile(p) for p in files)
    # time = stage - 2 + t: pre-stretch in [-2, -1], load in [-1, 0], path t itself.
    np.testing.assert_allclose(times, stage - 2 + t, rtol=0, atol=1e-14)
    assert np.all(np.diff(times) > 0)
    assert not os.path.exists(partitioned + ".partial.pvd")
    assert not os.path.exists(partitioned + "_vtu.partial")


def test_point_data_equal_the_hdf5_fields(partitioned):
    _, files = collection(partitioned)
    names = ["R", "r", "z", "lambda1", "lambda2", "s1", "s2", "E", "Phi"]
    with h5py.File(partitioned + ".h5", "r") as f:
        a = f["summary"]["voltage_kV"].shape[1]
        assert a == 2
        for k, path in enumerate(files):
            g = f["steps"][f"{k:06d}"]
            points, data, field, cells, reader = read_vtu(path)
            assert reader.GetNumberOfPieces() == 2
            film = data["ring"] >= 0
            n = len(g["R"])
            assert film.sum() == n * SEGMENTS
            # Point j of sample i sits at index i * segments + j.
            first = np.arange(n) * SEGMENTS
            for name in names:
                np.testing.assert_allclose(data[name][first], g[name][:], rtol=1e-14, atol=0,
                                           err_msg=f"step {k}: {name}")
                # The same value all around the axis.
                around = data[name][:film.sum()].reshape(n, SEGMENTS)
                assert np.all(around == around[:, :1]), name
            np.testing.assert_array_equal(data["ring"][first], g["ring"][:])
            # True stresses sigma_i = l_i s_i (paper, below eq. 11).
            np.testing.assert_allclose(data["sigma1"][first], g["lambda1"][:] * g["s1"][:],
                                       rtol=1e-13)
            np.testing.assert_allclose(data["sigma2"][first], g["lambda2"][:] * g["s2"][:],
                                       rtol=1e-13, atol=1e-12)
            # The surface of revolution: radius r, height z, angles 2 pi j / segments.
            xyz = points[:film.sum()].reshape(n, SEGMENTS, 3)
            np.testing.assert_allclose(np.hypot(xyz[..., 0], xyz[..., 1]),
                                       np.repeat(g["r"][:][:, None], SEGMENTS, 1), rtol=1e-14)
            np.testing.assert_allclose(xyz[..., 2], np.repeat(g["z"][:][:, None], SEGMENTS, 1),
                                       rtol=0, atol=1e-14)
            phi = np.arctan2(xyz[1, :, 1], xyz[1, :, 0]) % (2 * np.pi)
            np.testing.assert_allclose(phi, 2 * np.pi * np.arange(SEGMENTS) / SEGMENTS,
                                       atol=1e-12)
            # Quads between neighbouring samples, none across the doubled ring edge.
            R = g["R"][:]
            assert np.count_nonzero(cells == 9) == SEGMENTS * np.count_nonzero(np.diff(R) > 0)
            assert np.count_nonzero(np.diff(R) == 0) == 1  # the edge at r_v/a = 1.7
            # The disk: its own piece, a fan of triangles at z(A) out to r(A) = a.
            disk = ~film
            assert disk.sum() == SEGMENTS + 1
            assert np.count_nonzero(cells == 5) == SEGMENTS
            np.testing.assert_allclose(points[disk, 2], g["z"][0], rtol=1e-14)
            radius = np.hypot(points[disk, 0], points[disk, 1])
            np.testing.assert_allclose(np.sort(radius)[1:], g["r"][0], rtol=1e-14)
            assert np.all(data["ring"][disk] == -1) and np.all(np.isnan(data["s1"][disk]))
            # Field data: the step's load.
            assert field["stage"][0] == g.attrs["stage"]
            np.testing.assert_allclose(field["voltage_kV"], g.attrs["voltage_kV"], rtol=1e-15)
            np.testing.assert_allclose(field["displacement_mm"], g.attrs["displacement_mm"],
                                       rtol=1e-15)


def test_wrinkled_flag_marks_loss_of_tension(partitioned):
    _, files = collection(partitioned)
    flagged_steps = 0
    with h5py.File(partitioned + ".h5", "r") as f:
        wrinkled = f["summary"]["wrinkled"][:]
        stage = f["summary"]["stage"][:]
        for k, path in enumerate(files):
            _, data, _, _, _ = read_vtu(path)
            film = data["ring"] >= 0
            # As /summary/wrinkled: s2 < 0, past the stress-free start of the pre-stretch.
            np.testing.assert_array_equal(data["wrinkled"][film] == 1,
                                          (data["s2"][film] < 0) & (stage[k] > 0))
            if data["wrinkled"][film].any():
                flagged_steps += 1
                assert wrinkled[k] == 1
    # The outer ring's inner edge loses tension at 6.485 kV; the path ends at 6.5 kV.
    assert flagged_steps >= 1


def test_relaxed_zone_is_flagged(tmp_path):
    stem = run(str(tmp_path), "relaxed-low-prestretch.prm", "relaxed")
    _, files = collection(stem)
    with h5py.File(stem + ".h5", "r") as f:
        inner = f["summary"]["wrinkled_zone_inner_mm"][:]
        stage = f["summary"]["stage"][:]
    zone_steps = [k for k in range(len(files)) if stage[k] == 2 and np.isfinite(inner[k])]
    assert zone_steps, "the relaxed run has a wrinkled zone in its voltage stage"
    for k in zone_steps:
        _, data, _, _, _ = read_vtu(files[k])
        film = data["ring"] >= 0
        flag, s2 = data["wrinkled"][film] == 1, data["s2"][film]
        # Tension-field law: s2 = 0 in the wrinkled zone, s2 > 0 outside it.
        assert flag.any() and (~flag).any()
        assert np.all(s2[flag] == 0) and np.all(s2[~flag] > 0)
        # The zone starts at the disk edge (the first sample).
        assert flag[0]


def test_arc_length_times_keep_increasing_and_states_flagged(tmp_path):
    stem = run(str(tmp_path), "fold-full.prm", "fold")
    times, files = collection(stem)
    with h5py.File(stem + ".h5", "r") as f:
        s = f["summary"]
        t, stage, bits = s["load_factor"][:], s["stage"][:], s["nonphysical"][:]
        n = len(stage)
        r_max = np.array([f["steps"][f"{k:06d}"]["r"][:].max() for k in range(n)])
        stable = s["stable"][:]
        limit_v = np.atleast_2d(s.attrs["limit_point_voltage_kV"])
    assert len(files) == n
    assert np.all(np.diff(times) > 0), "PVD times strictly increase through the folds"
    voltage = stage == 2
    assert np.any(np.diff(t[voltage]) < 0), "t turns back at the first fold"
    # The time is the distance travelled along t: its steps are |change of t|.
    first_back = np.flatnonzero(voltage[1:] & (np.diff(t) < 0))[0] + 1
    np.testing.assert_allclose(np.diff(times)[first_back:], np.abs(np.diff(t))[first_back:],
                               rtol=1e-9, atol=1e-9)
    # Non-physical states: the meridian reaches beyond the 42 mm frame.
    np.testing.assert_array_equal((bits.astype(int) & 1) == 1, r_max > 42 * (1 + 1e-9))
    assert bits[-1] == 1 and r_max[-1] > 90
    assert limit_v.shape[0] == 2
    # Every state on the stable branch up to the first fold is possible.
    assert np.all(bits[: first_back][stable[: first_back] == 1] == 0)


def test_a_new_run_replaces_the_old_output(tmp_path):
    tmp = str(tmp_path)
    stem = run(tmp, "default.prm", "again")
    stale = os.path.join(stem + "_vtu", "stale.vtu")
    with open(stale, "w") as f:
        f.write("left from an older run")
    assert run(tmp, "default.prm", "again") == stem
    assert not os.path.exists(stale), "the older folder was replaced"
    _, files = collection(stem)
    assert len(files) == 26 and all(os.path.isfile(p) for p in files)
    assert sorted(os.listdir(os.path.join(tmp, "out"))) == ["again.h5", "again.pvd", "again_vtu"]
