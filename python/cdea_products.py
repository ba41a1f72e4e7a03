"""The products of cdea's results files, read with h5py alone (no module build).

Which study wrote a file, told from the groups and datasets each writer
always writes (the files carry no attribute that names their product), and
the file's groups as numpy arrays. Used by `cdea.load` (python/cdea_load.py)
and by postprocess/plot.py.
"""

import os

# The product of a file: the first whose every path is in the file (a time
# run is a run whose /summary has time_s); a fit file is told by its root
# attributes.
SIGNATURES = (
    ("time run", ("summary/stage", "summary/displacement_mm", "summary/time_s")),
    ("run", ("summary/stage", "summary/displacement_mm", "summary/voltage_kV")),
    ("map", ("rv_over_a", "outer_voltage_kV", "stroke_increase_percent")),
    ("optimum", ("history/objective", "optimum/s2_kPa", "starts/objective")),
    ("chart", ("uniaxial/stretch", "equibiaxial/stretch")),
    ("response", ("transfer/frequency_Hz", "modes/frequency_Hz")),
    ("frequency sweep", ("sweep/frequency_Hz", "sweep/stroke_amplitude_mm")),
    ("model selection", ("models/model", "models/aic", "models/bic", "constants/value")),
)
# A fit file: its root attributes (the data of material tests are in /samples).
FIT_ATTRIBUTES = ("free_parameters", "fitted_values", "standard_errors")


class ProductError(ValueError):
    """A file that is not a results file of cdea (or not one this reader knows)."""


def open_file(path):
    """The HDF5 file @p path open for reading; FileNotFoundError if there is
    none, ProductError if it is not HDF5."""
    import h5py
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(2, "no such results file", path)
    try:
        return h5py.File(path, "r")
    except OSError as error:
        raise ProductError(f"{path}: not an HDF5 file ({error})") from None


def kind_of(f):
    """The product of the open file @p f, or None."""
    if all(a in f.attrs for a in FIT_ATTRIBUTES) and ("data" in f or "samples" in f):
        return "fit"
    for kind, paths in SIGNATURES:
        if all(p in f for p in paths):
            return kind
    return None


def kind(path):
    """The product of the file @p path; ProductError naming the file if none."""
    with open_file(path) as f:
        found = kind_of(f)
    if found is None:
        raise ProductError(f"{os.fspath(path)}: not a results file of cdea (none of the groups "
                           "of a run, map, optimum, fit, model selection, chart, response or "
                           "frequency sweep)")
    return found


def text(value):
    return value.decode("utf-8", "replace") if isinstance(value, bytes) else value


def attributes(node):
    """The attributes of a group or dataset: str for texts, numpy otherwise."""
    return {k: text(v) for k, v in node.attrs.items()}


def datasets(group):
    """The datasets directly in @p group: numpy arrays (str for texts)."""
    import h5py
    out = {}
    for name, node in group.items():
        if isinstance(node, h5py.Dataset):
            value = node[()]
            if getattr(value, "dtype", None) is not None and value.dtype.kind == "O":
                value = value.astype(str)
            out[name] = value
    return out


def columns(group):
    """Name -> (unit, description) of the datasets of @p group."""
    import h5py
    return {name: (text(node.attrs.get("unit", "")), text(node.attrs.get("description", "")))
            for name, node in group.items() if isinstance(node, h5py.Dataset)}
